// Hazard maps of the depth-averaged flow (depth_averaged::HazardMaps, issue 19), on a terrain
// the test writes itself: a GeoTIFF in UTM zone 32N (EPSG:32632) of the plane
// Z = -0.5 (x - x0), 1 m pixels. A slab 1 m deep released on it slides 40 steps with
// Voellmy friction (phi = 10 deg); the maps, recorded every step, are read back with GDAL:
//  - their CRS is the terrain raster's (OSRIsSame) and their pixel centres are the grid's
//    nodes (geotransform from the grid's corners and cell size, exactly);
//  - where the release was (nodes under the slab at t = 0, away from its edges), the peak
//    thickness is at least the initial depth (1 m, less 1e-12) and the arrival time is 0;
//  - the deposit lies inside the affected area, the peak velocity is positive where the
//    slab went and the arrival time is no-data (-9999) only outside it;
//  - summary.csv has the affected area, the runout and a travel angle in (0, 90);
//  - release_area.geojson read back is the release rectangle (to 1e-6 m: GeoJSON keeps
//    15 significant digits, 1e-9 m at coordinates of 5e6 m).
#include "depth_averaged_input.h"
#include "raster_writer.h"
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/depth_averaged/hazard_maps.h>
#include <slidewave/terrain/vector_polygons.h>
#include <sstream>
#include <string>
#include <vector>

using namespace slidewave;
using unit_check::check;

namespace
{
  std::vector<double>
  read_map(const std::string &path, double *transform, std::string &wkt, int &w, int &h)
  {
    GDALDatasetH data = GDALOpen(path.c_str(), GA_ReadOnly);
    GDALGetGeoTransform(data, transform);
    wkt = GDALGetProjectionRef(data);
    w   = GDALGetRasterXSize(data);
    h   = GDALGetRasterYSize(data);
    std::vector<double> values(static_cast<std::size_t>(w) * h);
    if (GDALRasterIO(
          GDALGetRasterBand(data, 1), GF_Read, 0, 0, w, h, values.data(), w, h, GDT_Float64, 0, 0)
        != CE_None)
      std::printf("reading %s failed\n", path.c_str());
    GDALClose(data);
    return values;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  GDALAllRegister();
  const double x0 = 500000., y0 = 5000000.;
  {
    const double gt[6] = {x0 - 2., 1., 0., y0 + 12., 0., -1.};
    write_raster("GTiff", "incline_utm.tif", 64, 14, gt, 32632, [&](double x, double) {
      return -0.5 * (x - x0);
    });
  }
  std::ostringstream input;
  input.precision(12);
  // The options of the test's blessed output (the defaults before issue 28).
  input << "subsection Depth averaged\n"
        << "  set Shape functions = q1\n"
        << "  set Depth update = strain\n"
        << "  subsection Grid\n"
        << "    set Lower left = " << x0 << ", " << y0 << "\n"
        << "    set Upper right = " << x0 + 60. << ", " << y0 + 10. << "\n"
        << "    set Cell size = 0.5\n"
        << "  end\n"
        << "  subsection Basal friction\n"
        << "    set Model = Voellmy\n"
        << "    set Friction angle = 10\n"
        << "  end\n"
        << "  subsection Terrain\n"
        << "    set Source = raster\n"
        << "    set Raster file = incline_utm.tif\n"
        << "  end\n"
        << "  subsection Release\n"
        << "    set Shape = rectangle\n"
        << "    set Rectangle = " << x0 + 5. << ", " << y0 << ", " << x0 + 15. << ", " << y0 + 10.
        << "\n"
        << "    set Depth = 1\n"
        << "    set Particles per direction = 2\n"
        << "  end\n"
        << "end\n";
  const auto parameters = depth_averaged_parameters(input.str());

  auto grid = depth_averaged::DepthAveragedSolver::make_grid(parameters);
  depth_averaged::DepthAveragedSolver solver(parameters, *grid);
  solver.setup(0.);
  depth_averaged::HazardMaps maps(parameters, 0.05);
  double                     time = 0.;
  maps.record(solver, time);
  for (unsigned int step = 0; step < 40; ++step)
    {
      const double dt = solver.stable_time_step();
      solver.advance(dt);
      time += dt;
      maps.record(solver, time);
    }
  std::printf("40 steps to t = %.3f s\n", time);
  maps.write(".",
             solver,
             terrain::raster_extent("Raster file", "incline_utm.tif", {}).crs_wkt,
             dealii::Point<2>(x0 + 10., y0 + 5.),
             0.);

  double      transform[6];
  std::string wkt;
  int         w = 0, h = 0;
  const auto  thickness = read_map("peak_flow_thickness.tif", transform, wkt, w, h);
  const auto  arrival   = read_map("arrival_time.tif", transform, wkt, w, h);
  const auto  velocity  = read_map("peak_flow_velocity.tif", transform, wkt, w, h);
  const auto  deposit   = read_map("deposit_thickness.tif", transform, wkt, w, h);
  {
    GDALDatasetH         input_raster = GDALOpen("incline_utm.tif", GA_ReadOnly);
    OGRSpatialReferenceH a            = OSRNewSpatialReference(GDALGetProjectionRef(input_raster));
    OGRSpatialReferenceH b            = OSRNewSpatialReference(wkt.c_str());
    check(OSRIsSame(a, b) != 0, "the maps' CRS is the terrain raster's");
    OSRDestroySpatialReference(a);
    OSRDestroySpatialReference(b);
    GDALClose(input_raster);
  }
  std::printf("  maps of %d x %d pixels, origin (%.2f, %.2f), pixel %.2f m\n",
              w,
              h,
              transform[0] - x0,
              transform[3] - y0,
              transform[1]);
  check(w == 121 && h == 21 && transform[0] == x0 - 0.25 && transform[3] == y0 + 10.25
          && transform[1] == 0.5 && transform[5] == -0.5,
        "one pixel per grid node, centred on it");

  // Pixel (c, r) is the node at (x0 + 0.5 c, y0 + 10 - 0.5 r).
  bool   release_ok = true, inside_ok = true, velocity_ok = true;
  double least = 1e300;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      {
        const std::size_t k = static_cast<std::size_t>(r) * w + c;
        const double      x = 0.5 * c, y = 10. - 0.5 * r;
        if (x > 6. && x < 14. && y > 1. && y < 9.)
          {
            least      = std::min(least, thickness[k]);
            release_ok = release_ok && thickness[k] >= 1. - 1e-12 && arrival[k] == 0.;
          }
        inside_ok   = inside_ok && (deposit[k] == 0. || thickness[k] > 0.05);
        inside_ok   = inside_ok && ((arrival[k] == -9999.) == !(thickness[k] > 0.05));
        velocity_ok = velocity_ok && (!(thickness[k] > 0.05) || x < 6. || velocity[k] > 0.);
      }
  std::printf("  least peak thickness over the release: %.12f m\n", least);
  check(release_ok, "over the release: peak thickness >= 1 m, arrival time 0");
  check(inside_ok, "deposit inside the affected area; no-data arrival exactly outside it");
  check(velocity_ok, "a peak velocity wherever the slab went downslope of its start");

  std::ifstream summary("summary.csv");
  std::string   line;
  double        area = 0., runout = 0., angle = 0.;
  while (std::getline(summary, line))
    {
      const auto comma = line.find(',');
      const auto name  = line.substr(0, comma);
      const auto value = comma == std::string::npos ? 0. : std::atof(line.c_str() + comma + 1);
      if (name == "affected_area")
        area = value;
      if (name == "runout")
        runout = value;
      if (name == "travel_angle")
        angle = value;
    }
  std::printf("  affected area %.2f m^2, runout %.3f m, travel angle %.3f deg\n",
              area,
              runout,
              angle);
  check(area > 100. && runout > 5. && angle > 0. && angle < 90., "summary: area, runout, angle");

  // release_area.geojson: the release rectangle, read back in the terrain's CRS.
  const auto release
    = terrain::read_polygons("release",
                             "release_area.geojson",
                             "",
                             terrain::raster_extent("Raster file", "incline_utm.tif", {}).crs_wkt);
  check(release.size() == 1 && release[0].outer.size() == 4
          && release[0].outer[0].distance(dealii::Point<2>(x0 + 5., y0)) < 1e-6
          && release[0].outer[2].distance(dealii::Point<2>(x0 + 15., y0 + 10.)) < 1e-6,
        "release_area.geojson: the release rectangle");
  return unit_check::finish();
}
