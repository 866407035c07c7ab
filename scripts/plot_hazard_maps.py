#!/usr/bin/python3
"""Draw the hazard maps of a finished depth-averaged run ('Depth averaged/Hazard maps/Enable
= true') over the terrain: peak flow thickness, peak flow velocity, peak dynamic pressure
[kPa], arrival time and deposit thickness, each over a grey hillshade with elevation
contours every 50 m, the affected-area outline and the release, and the run's summary.

  /usr/bin/python3 scripts/plot_hazard_maps.py OUTPUT_DIR [--dem FILE] [--png FILE]
      [--title TEXT] [--margin METRES | --full]

OUTPUT_DIR holds maps/*.tif, maps/affected_area.geojson, maps/deposit_area.geojson and
maps/summary.csv (doc/terrain.md); the scene file the program copied there (its release
polygon, density and terrain) and statistics.csv (the release's centre of mass, the
released volume, when the flow slowed down) are used when present. The terrain is the DEM
warped by GDAL (bilinear) to the maps' CRS and grid, one pixel per grid node: --dem, else
the scene's 'Terrain/Raster file' (relative to prm/, where the scenes live), else
prm/data/jacksboro_dem.tif. A scene whose terrain is an expression or a table gets no
hillshade unless --dem is given. Values at or below the scene's thickness threshold are
left transparent. The view is the affected area with --margin metres around it (default
300), or the whole grid with --full. --png defaults to OUTPUT_DIR/hazard-maps.png; its path
is printed. Needs numpy, matplotlib and GDAL's Python bindings (Debian: python3-numpy,
python3-matplotlib, python3-gdal); uses the Agg backend. Takes a few seconds."""
import argparse
import csv
import glob
import math
import os
import sys

try:
    import numpy as np
    import matplotlib
    from osgeo import gdal, ogr, osr
except ImportError as exc:
    sys.exit(f"{exc}; run this script with a python3 that has numpy, matplotlib and GDAL "
             "(e.g. /usr/bin/python3 with python3-gdal)")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after selecting the backend)
from matplotlib.colors import LightSource, ListedColormap  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_DEM = os.path.join(ROOT, "prm", "data", "jacksboro_dem.tif")
GRAVITY = 9.81
CONTOUR_STEP = 50.0  # m
STOP_SPEED = 0.5     # m/s: "slowed down" when the fastest column stays below this

# name, panel title, colour-bar label, factor from the file's unit, colour map
PANELS = [
    ("peak_flow_thickness", "peak flow thickness", "h_max [m]", 1.0, "viridis"),
    ("peak_flow_velocity", "peak flow velocity", "|v|_max [m/s]", 1.0, "plasma"),
    ("peak_pressure_dynamic", "peak dynamic pressure", "rho v^2 max [kPa]", 1e-3,
     ListedColormap(plt.get_cmap("YlOrRd")(np.linspace(0.15, 1.0, 256)))),
    ("arrival_time", "arrival time", "t [s]", 1.0, "cividis"),
    ("deposit_thickness", "deposit thickness (end of run)", "h [m]", 1.0, "viridis"),
]


def read_scene(directory):
    """{'Sub/section/Name': value} of the scene file copied into OUTPUT_DIR ({} if none)."""
    paths = sorted(glob.glob(os.path.join(directory, "*.prm")))
    if not paths:
        return {}, None
    values, sections, pending = {}, [], ""
    with open(paths[0]) as f:
        for raw in f:
            line = pending + raw.split("#", 1)[0].rstrip()
            if line.endswith("\\"):
                pending = line[:-1] + " "
                continue
            pending = ""
            words = line.split()
            if not words:
                continue
            if words[0] == "subsection":
                sections.append(line.split(None, 1)[1].strip())
            elif words[0] == "end":
                sections.pop()
            elif words[0] == "set" and "=" in line:
                key, value = line.split(None, 1)[1].split("=", 1)
                values["/".join(sections + [key.strip()])] = value.strip()
    return values, paths[0]


def read_map(path):
    """(values as a masked array, rows north to south; geotransform; CRS WKT) of a GeoTIFF."""
    data = gdal.Open(path)
    band = data.GetRasterBand(1)
    values = band.ReadAsArray().astype(np.float64)
    nodata = band.GetNoDataValue()
    mask = ~np.isfinite(values)
    if nodata is not None:
        mask |= values == nodata
    return np.ma.masked_array(values, mask), data.GetGeoTransform(), data.GetProjection()


def read_summary(path):
    """{quantity: value} of maps/summary.csv."""
    with open(path) as f:
        return {row["quantity"]: float(row["value"]) for row in csv.DictReader(f)}


def read_statistics(path):
    """Columns of statistics.csv as arrays ({} if it is not there)."""
    if not os.path.exists(path):
        return {}
    data = np.genfromtxt(path, delimiter=",", names=True)
    return {name: np.atleast_1d(data[name]) for name in data.dtype.names}


def read_outline(path):
    """The rings (N x 2 arrays, metres) of the polygons of a GeoJSON outline. The file's
    coordinates are the maps' (OGR may call them WGS 84 when the file names no CRS)."""
    rings = []
    if not os.path.exists(path):
        return rings
    source = ogr.Open(path)
    for layer in source:
        for feature in layer:
            geometry = feature.GetGeometryRef()
            polygons = ([geometry.GetGeometryRef(i) for i in range(geometry.GetGeometryCount())]
                        if geometry.GetGeometryType() in (ogr.wkbMultiPolygon,
                                                          ogr.wkbMultiPolygon25D)
                        else [geometry])
            for polygon in polygons:
                for i in range(polygon.GetGeometryCount()):
                    points = polygon.GetGeometryRef(i).GetPoints()
                    if points:
                        rings.append(np.array(points)[:, :2])
    return rings


def release_rings(scene):
    """Polygons and rectangles of the scene's release regions (N x 2 arrays, metres)."""
    rings = []
    for key, shape in scene.items():
        parts = key.split("/")
        if len(parts) != 3 or parts[0] != "Depth averaged" or parts[2] != "Shape" \
                or not parts[1].startswith("Release"):
            continue
        section = "/".join(parts[:2])
        try:
            if shape == "polygon":
                points = [[float(v) for v in vertex.split(",")]
                          for vertex in scene[section + "/Polygon"].split(";") if vertex.strip()]
                rings.append(np.array(points + points[:1]))
            elif shape == "rectangle":
                x0, y0, x1, y1 = (float(v) for v in scene[section + "/Rectangle"].split(","))
                rings.append(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]))
        except (KeyError, ValueError):
            pass
    return rings


def choose_dem(args, scene):
    """The DEM to draw the terrain from, or None (with the reason printed)."""
    if args.dem:
        return args.dem
    source = scene.get("Depth averaged/Terrain/Source", "expression" if scene else "raster")
    if source != "raster":
        print(f"plot_hazard_maps: the scene's terrain is an {source}, not a raster: no "
              "hillshade (give --dem FILE to draw one)")
        return None
    candidates = []
    raster = scene.get("Depth averaged/Terrain/Raster file", "")
    if raster:
        candidates += [raster] if os.path.isabs(raster) else [os.path.join(ROOT, "prm", raster),
                                                              raster]
    candidates.append(DEFAULT_DEM)
    for path in candidates:
        if os.path.exists(path):
            return path
    print(f"plot_hazard_maps: none of {', '.join(candidates)} exists: no hillshade "
          "(make it with scripts/make_jacksboro_dem.py or give --dem FILE)")
    return None


def warp_terrain(dem, shape, transform, wkt):
    """The DEM warped (bilinear) onto the maps' pixels: rows north to south, NaN outside it."""
    height, width = shape
    x0, dx, _, y1, _, dy = transform
    bounds = (x0, y1 + dy * height, x0 + dx * width, y1)
    options = dict(format="MEM", outputBounds=bounds, width=width, height=height,
                   resampleAlg="bilinear", outputType=gdal.GDT_Float64,
                   dstNodata=float("nan"))
    if wkt:
        options["dstSRS"] = wkt
    warped = gdal.Warp("", dem, **options)
    z = warped.GetRasterBand(1).ReadAsArray().astype(np.float64)
    return np.where(np.isfinite(z), z, np.nan)


def crs_name(wkt):
    if not wkt:
        return ""
    crs = osr.SpatialReference(wkt=wkt)
    code = crs.GetAuthorityCode(None)
    name = crs.GetName() or ""
    return f"{name} (EPSG:{code})" if code and crs.GetAuthorityName(None) == "EPSG" else name


def view_limits(args, affected, extent, transform):
    """(x0, x1, y0, y1) in metres: the affected nodes with a margin, or the whole grid."""
    if args.full or not affected.any():
        return extent
    x0, dx, _, y1, _, dy = transform
    rows, cols = np.nonzero(affected)
    xs = x0 + (cols + 0.5) * dx
    ys = y1 + (rows + 0.5) * dy
    m = args.margin
    lo_x, hi_x = xs.min() - m, xs.max() + m
    lo_y, hi_y = ys.min() - m, ys.max() + m
    # A square window (the panels share it), kept inside the grid.
    half = 0.5 * max(hi_x - lo_x, hi_y - lo_y)
    cx, cy = 0.5 * (lo_x + hi_x), 0.5 * (lo_y + hi_y)
    cx = min(max(cx, extent[0] + half), extent[1] - half)
    cy = min(max(cy, extent[2] + half), extent[3] - half)
    return (max(cx - half, extent[0]), min(cx + half, extent[1]),
            max(cy - half, extent[2]), min(cy + half, extent[3]))


def summary_text(summary, statistics, scene, maps, pixel_area, threshold):
    """The lines of the summary box."""
    density = float(scene.get("Depth averaged/Material/Density", "1200") or 1200)
    # Each node's share of the grid's area: a pixel, half of one on the sides, a quarter at
    # the corners (the nodal thickness is the columns' volume over that area).
    deposit = maps["deposit_thickness"].filled(0.0)
    share = np.ones(deposit.shape)
    share[[0, -1], :] *= 0.5
    share[:, [0, -1]] *= 0.5
    volume = float(np.sum(np.where(deposit > 0, deposit, 0.0) * share)) * pixel_area
    get = summary.get
    rows = [("threshold", f"{threshold:g} m")]
    if "affected_area" in summary:
        rows.append(("affected area", f"{get('affected_area') / 1e4:.2f} ha"))
    if "deposit_area" in summary:
        rows.append(("deposit area", f"{get('deposit_area') / 1e4:.2f} ha"))
    rows.append(("deposit volume", f"{volume:.4g} m^3"))
    if "mass" in statistics:
        released = statistics["mass"][0] / density
        lost = statistics["lost_mass"][-1] / density if "lost_mass" in statistics else 0.0
        rows.append(("released volume", f"{released:.4g} m^3"))
        if lost > 0:
            rows.append(("left the grid", f"{lost:.4g} m^3"))
    if "runout" in summary:
        rows.append(("runout (crown to toe)", f"{get('runout'):.0f} m"))
    if "elevation_drop" in summary:
        rows.append(("elevation drop", f"{get('elevation_drop'):.0f} m"))
    if "travel_angle" in summary:
        ratio = math.tan(math.radians(get("travel_angle")))
        rows.append(("travel angle", f"{get('travel_angle'):.1f} deg (H/L {ratio:.2f})"))
    rows.append(("", ""))
    for key, text, factor, unit, digits in [
            ("max_peak_flow_thickness", "max flow thickness", 1.0, "m", 1),
            ("max_peak_flow_velocity", "max flow velocity", 1.0, "m/s", 1),
            ("max_peak_pressure_dynamic", "max dynamic pressure", 1e-3, "kPa", 0),
            ("max_peak_pressure_static", "max static pressure", 1e-3, "kPa", 0)]:
        if key in summary:
            rows.append((text, f"{get(key) * factor:.{digits}f} {unit}"))
    arrival = maps["arrival_time"].compressed()
    if arrival.size:
        rows.append(("last arrival", f"{arrival.max():.1f} s"))
    if "max_speed" in statistics and "time" in statistics:
        t, speed = statistics["time"], statistics["max_speed"]
        fast = np.nonzero(speed >= STOP_SPEED)[0]
        if fast.size and fast[-1] + 1 < t.size:
            rows.append((f"all < {STOP_SPEED:g} m/s by", f"{t[fast[-1] + 1]:.0f} s"))
        rows.append(("end of run", f"{t[-1]:.0f} s"))
    width = max(len(label) for label, _ in rows) + 2
    return [f"{label:<{width}}{value}" for label, value in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the run's output directory (with maps/)")
    parser.add_argument("--dem", help="DEM for the hillshade and contours (any raster GDAL "
                        "reads; default: the scene's raster, else prm/data/jacksboro_dem.tif)")
    parser.add_argument("--png", help="output figure (default: OUTPUT_DIR/hazard-maps.png)")
    parser.add_argument("--title", help="figure title (default: from the scene file's name)")
    parser.add_argument("--margin", type=float, default=300.0,
                        help="metres of terrain shown around the affected area (default 300)")
    parser.add_argument("--full", action="store_true", help="show the whole grid")
    args = parser.parse_args()

    gdal.UseExceptions()
    maps_dir = os.path.join(args.directory, "maps")
    if not os.path.exists(os.path.join(maps_dir, "peak_flow_thickness.tif")):
        sys.exit(f"plot_hazard_maps: no {maps_dir}/peak_flow_thickness.tif: run the scene with "
                 "'Depth averaged/Hazard maps/Enable = true'")
    scene, scene_path = read_scene(args.directory)
    summary = read_summary(os.path.join(maps_dir, "summary.csv"))
    statistics = read_statistics(os.path.join(args.directory, "statistics.csv"))
    threshold = summary.get("threshold",
                            float(scene.get("Depth averaged/Hazard maps/Thickness threshold",
                                            "0.05")))

    maps = {}
    for name, *_ in PANELS + [("peak_pressure_static",)]:
        maps[name], transform, wkt = read_map(os.path.join(maps_dir, name + ".tif"))
    shape = maps["peak_flow_thickness"].shape
    x0, dx, _, y1, _, dy = transform
    extent = (x0, x0 + dx * shape[1], y1 + dy * shape[0], y1)  # metres: left right bottom top
    pixel_area = abs(dx * dy)
    affected = maps["peak_flow_thickness"].filled(0.0) > threshold

    dem = choose_dem(args, scene)
    terrain = warp_terrain(dem, shape, transform, wkt) if dem else None
    if terrain is not None and np.isnan(terrain).all():
        print(f"plot_hazard_maps: {dem} does not cover the maps: no hillshade")
        terrain, dem = None, None
    elif terrain is not None and np.isnan(terrain[affected]).any():
        print(f"plot_hazard_maps: {dem} does not cover every affected node")

    outline = read_outline(os.path.join(maps_dir, "affected_area.geojson"))
    deposit_outline = read_outline(os.path.join(maps_dir, "deposit_area.geojson"))
    # The release as the program took it (maps/release_area.geojson: a vector file's
    # polygons already reprojected); older outputs: the scene's polygon or rectangle.
    release = read_outline(os.path.join(maps_dir, "release_area.geojson")) \
        or release_rings(scene)
    centre = None
    if "centroid_x" in statistics:
        centre = (statistics["centroid_x"][0], statistics["centroid_y"][0])
    farthest = (summary["farthest_x"], summary["farthest_y"]) if "farthest_x" in summary \
        else None

    view = view_limits(args, affected, extent, transform)
    # Georeferenced maps in km of easting and northing, others in metres of x and y.
    unit, unit_name = (1e3, "km") if wkt else (1.0, "m")
    map_extent = [v / unit for v in extent]
    crs = crs_name(wkt)
    if terrain is not None:
        shade = LightSource(azdeg=315, altdeg=45).hillshade(
            np.nan_to_num(terrain, nan=float(np.nanmean(terrain))), vert_exag=1.0,
            dx=abs(dx), dy=abs(dy))
        shade = np.where(np.isnan(terrain), np.nan, shade)
        # Contours from pixel centres, only over the window shown (faster, finer labels).
        xs = (x0 + (np.arange(shape[1]) + 0.5) * dx) / unit
        ys = (y1 + (np.arange(shape[0]) + 0.5) * dy) / unit
        rows = (ys * unit >= view[2] - 2 * abs(dy)) & (ys * unit <= view[3] + 2 * abs(dy))
        cols = (xs * unit >= view[0] - 2 * dx) & (xs * unit <= view[1] + 2 * dx)
        xs_view, ys_view, z_view = xs[cols], ys[rows], terrain[np.ix_(rows, cols)]
        levels = np.arange(math.floor(np.nanmin(z_view) / CONTOUR_STEP) * CONTOUR_STEP,
                           np.nanmax(z_view) + CONTOUR_STEP, CONTOUR_STEP)

    # Colour bars about as tall as the (equal-aspect) maps.
    shrink = min(0.85, max(0.25, 1.1 * (view[3] - view[2]) / (view[1] - view[0])))
    fig, axes = plt.subplots(2, 3, figsize=(16.5, 10.5), constrained_layout=True)
    title = args.title or ("Hazard maps of %s" % os.path.splitext(
        os.path.basename(scene_path))[0] if scene_path else "Hazard maps")
    fig.suptitle(title, fontsize=14)
    for ax, (name, panel_title, label, factor, cmap) in zip(axes.flat, PANELS):
        if terrain is not None:
            # A light grey relief: the colours stay readable on the slopes facing away from
            # the light (north-west).
            ax.imshow(shade, cmap="gray", vmin=-0.6, vmax=1.1, extent=map_extent,
                      interpolation="bilinear")
        values = maps[name]
        extend = "neither"
        colours = plt.get_cmap(cmap).copy() if isinstance(cmap, str) else cmap.copy()
        if name in ("arrival_time",):
            shown = np.ma.masked_where(~affected | values.mask, values)
            # Nodes reached at t = 0 (the release, spread over the cells it touches) in grey.
            later = shown.compressed()
            later = later[later > 0]
            vmin = 0.5 * later.min() if later.size else 1e-9
            colours.set_under("0.85")
            extend = "min"
            # A few nodes reached late by material creeping at cm/s would squeeze the scale:
            # it ends at the 98th percentile of the arrivals after t = 0.
            top = math.ceil(np.percentile(later, 98)) if later.size else 1.0
            if later.size and later.max() > top:
                extend = "both"
                label = f"{label}, scale to the 98th percentile (latest {later.max():.0f} s)"
        elif name == "deposit_thickness":
            shown = np.ma.masked_where(values.filled(0.0) <= threshold, values)
            vmin = 0.0
        else:
            shown = np.ma.masked_where(~affected, values)
            vmin = 0.0
        shown = shown * factor
        vmax = float(shown.max()) if shown.count() else 1.0
        if name == "arrival_time":
            vmax = min(vmax, top)
        if name == "deposit_thickness":  # the same scale as the peak thickness
            vmax = float(maps["peak_flow_thickness"].max())
        image = ax.imshow(shown, cmap=colours, vmin=vmin, vmax=max(vmax, 1.001 * vmin),
                          extent=map_extent, interpolation="nearest", alpha=0.92)
        bar = fig.colorbar(image, ax=ax, shrink=shrink, label=label, extend=extend)
        if name == "arrival_time":
            bar.ax.text(1.3, -0.03, "t = 0", transform=bar.ax.transAxes, ha="left",
                        va="center", fontsize=7.5)
        if terrain is not None:
            contours = ax.contour(xs_view, ys_view, z_view, levels=levels, colors="k",
                                  linewidths=0.5, alpha=0.5)
            labelled = [v for v in contours.levels if v % (2 * CONTOUR_STEP) == 0]
            ax.clabel(contours, labelled, fontsize=7, fmt="%d m", inline_spacing=2)
        for ring in outline:
            ax.plot(ring[:, 0] / unit, ring[:, 1] / unit, color="k", lw=1.1,
                    label="affected area (h > %g m)" % threshold if ring is outline[0] else None)
        if name == "deposit_thickness":
            for ring in deposit_outline:
                ax.plot(ring[:, 0] / unit, ring[:, 1] / unit, color="tab:blue", lw=0.9,
                        label="deposit area" if ring is deposit_outline[0] else None)
        for ring in release:
            ax.plot(ring[:, 0] / unit, ring[:, 1] / unit, color="w", lw=1.0, ls="--",
                    label="release" if ring is release[0] else None)
        if name == "peak_flow_thickness" and centre is not None and farthest is not None:
            ax.plot([centre[0] / unit, farthest[0] / unit], [centre[1] / unit, farthest[1] / unit],
                    color="tab:red", lw=1.3, marker="o", ms=3.5, label="runout")
        ax.set_xlim(view[0] / unit, view[1] / unit)
        ax.set_ylim(view[2] / unit, view[3] / unit)
        ax.set_aspect("equal")
        ax.set_title(panel_title)
        ax.set_xlabel(f"easting [km], {crs}" if crs else f"x [{unit_name}]", fontsize=8.5)
        ax.set_ylabel(f"northing [km], {crs}" if crs else f"y [{unit_name}]", fontsize=8.5)
        ax.tick_params(labelsize=8)
        ax.ticklabel_format(useOffset=False, style="plain")
        if name in ("peak_flow_thickness", "deposit_thickness"):
            ax.legend(loc="lower left", fontsize=7.5, framealpha=0.85)

    box = axes.flat[-1]
    box.axis("off")
    lines = summary_text(summary, statistics, scene, maps, pixel_area, threshold)
    box.text(0.02, 0.98, "summary (maps/summary.csv)\n\n" + "\n".join(lines),
             transform=box.transAxes, va="top", ha="left", family="monospace", fontsize=9,
             bbox=dict(boxstyle="round", facecolor="white", edgecolor="0.6"))
    notes = [f"grid: {shape[1]} x {shape[0]} nodes of {abs(dx):g} m"]
    if dem:
        notes += [f"terrain: {os.path.relpath(dem)},", "warped bilinearly to the nodes;",
                  f"contours every {CONTOUR_STEP:g} m"]
    else:
        notes.append("no terrain drawn")
    if view != extent:
        # Where the window lies in the whole grid.
        inset = box.inset_axes([0.64, 0.0, 0.36, 0.36])
        if terrain is not None:
            inset.imshow(shade, cmap="gray", vmin=-0.6, vmax=1.1, extent=map_extent)
        inset.imshow(np.ma.masked_where(~affected, affected.astype(float)), cmap="autumn",
                     extent=map_extent, interpolation="nearest")
        inset.add_patch(plt.Rectangle((view[0] / unit, view[2] / unit),
                                      (view[1] - view[0]) / unit, (view[3] - view[2]) / unit,
                                      fill=False, edgecolor="tab:red", lw=1.2))
        inset.set_xlim(map_extent[0], map_extent[1])
        inset.set_ylim(map_extent[2], map_extent[3])
        inset.set_xlabel(f"the whole grid [{unit_name}]", fontsize=7.5)
        inset.tick_params(labelsize=6.5)
        inset.ticklabel_format(useOffset=False, style="plain")
    box.text(0.02, 0.02, "\n".join(notes), transform=box.transAxes, va="bottom", ha="left",
             fontsize=8, color="0.3")

    png = args.png or os.path.join(args.directory, "hazard-maps.png")
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
    fig.savefig(png, dpi=130)
    print(png)


if __name__ == "__main__":
    main()
