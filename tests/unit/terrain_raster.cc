// Terrain from rasters through GDAL (terrain::read_raster_terrain, issue 19). The test writes
// its own rasters with GDAL into the working directory:
//  - a GeoTIFF in UTM zone 32N (EPSG:32632) of the plane Z = 2 + 0.3 (x - x0) - 0.7 (y - y0)
//    on 1 m pixels: read back over a window inside it, value and gradient are the plane's
//    (bilinear interpolation reproduces a plane; 1e-9 m: round-off at coordinates of 5e6 m);
//  - an ESRI ASCII grid (no CRS) of the bump Z1 of paper 001, written with 17 digits:
//    refused unless its coordinates are declared metric, then equal to Z1 at the pixel
//    centres (1e-9 m; GDAL reads such grids as 32-bit floats unless told otherwise, which
//    loses 2e-7 m);
//  - a GeoTIFF in degrees (EPSG:4326) around 9 E, 45.5 N of a field linear in longitude and
//    latitude: reprojected to UTM 32N, the zone of its centre, by GDAL's warper onto pixels
//    no larger than the source's; at points taken back to degrees the elevation is the
//    field's to 1e-4 m, a millionth of its 100 m of relief (measured 8e-6 m: the warper's
//    arithmetic; resampling a linear field bilinearly onto a finer grid keeps it, onto the
//    warper's default, coarser pixels it bent it by 0.1 m);
//  - the footprint (Grid/Extent = terrain raster) of such a raster 2.6 deg east of the
//    zone's central meridian has data everywhere (read without a no-data refusal) and
//    leaves out the corner wedges (0.85-0.95 of the bounding box, 0.88 expected); at the
//    central meridian, and for a raster without no-data, it is the whole extent;
//  - no-data: a pixel under the domain is refused, one outside the window is not read;
//  - a missing file, a text file, a domain outside the raster: refused;
//  - a depth-averaged run (a slab sliding on Z = -0.5 x, 20 steps) with the terrain from
//    the ESRI grid gives the same mass, momentum and energy as with the expression, to
//    1e-12 relative (both terrains are the exact plane).
#include "depth_averaged_input.h"
#include "raster_writer.h"
#include "unit_check.h"

#ifndef GEO_PIXEL
#define GEO_PIXEL 0.002
#endif

#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <functional>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/terrain/raster_terrain.h>
#include <string>
#include <vector>

using namespace slidewave;
using unit_check::check;
using unit_check::refused;

namespace
{
  double
  z1(const double x, const double y)
  {
    return 5. * std::exp(-0.4 * ((x - 5.) * (x - 5.) + (y - 5.) * (y - 5.)));
  }

  /** Integrals of a 20-step slab run on the plane Z = -0.5 x, terrain from @p terrain. */
  depth_averaged::DepthAveragedModel::Integrals
  slab_run(const std::string &terrain)
  {
    // The options of the test's blessed output (the defaults before issue 28).
    const auto parameters = depth_averaged_parameters("subsection Depth averaged\n"
                                                      "  set Shape functions = q1\n"
                                                      "  set Depth update = strain\n"
                                                      "  subsection Grid\n"
                                                      "    set Upper right = 40, 4\n"
                                                      "    set Cell size = 0.5\n"
                                                      "  end\n"
                                                      "  subsection Basal friction\n"
                                                      "    set Model = Voellmy\n"
                                                      "    set Friction angle = 10\n"
                                                      "  end\n"
                                                      "  subsection Terrain\n"
                                                      + terrain
                                                      + "  end\n"
                                                        "  subsection Release\n"
                                                        "    set Shape = rectangle\n"
                                                        "    set Rectangle = 5, 0, 15, 4\n"
                                                        "    set Depth = 1\n"
                                                        "    set Particles per direction = 2\n"
                                                        "  end\n"
                                                        "end\n");
    auto       grid       = depth_averaged::DepthAveragedSolver::make_grid(parameters);
    depth_averaged::DepthAveragedSolver solver(parameters, *grid);
    solver.setup(0.);
    for (unsigned int step = 0; step < 20; ++step)
      solver.advance(solver.stable_time_step());
    return solver.model().integrals(solver.point_cloud());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  GDALAllRegister();
  const terrain::RasterOptions strict;
  terrain::RasterOptions       metric;
  metric.assume_metric = true;

  std::printf("a plane in UTM 32N (GeoTIFF)\n");
  {
    const double x0 = 500000., y0 = 5000000.;
    const double gt[6] = {x0, 1., 0., y0 + 50., 0., -1.};
    const auto   plane
      = [&](const double x, const double y) { return 2. + 0.3 * (x - x0) - 0.7 * (y - y0); };
    write_raster("GTiff", "plane_utm.tif", 100, 50, gt, 32632, plane);
    const auto grid        = terrain::read_raster_terrain("Raster file",
                                                   "plane_utm.tif",
                                                   dealii::Point<2>(x0 + 10., y0 + 5.),
                                                   dealii::Point<2>(x0 + 90., y0 + 45.),
                                                   strict);
    double     value_error = 0., gradient_error = 0.;
    for (const double fx : {0.13, 0.5, 0.77})
      for (const double fy : {0.21, 0.5, 0.93})
        {
          const dealii::Point<2> p(x0 + 10. + 80. * fx, y0 + 5. + 40. * fy);
          value_error    = std::max(value_error, std::abs(grid.value(p) - plane(p[0], p[1])));
          gradient_error = std::max(gradient_error,
                                    (grid.gradient(p) - dealii::Tensor<1, 2>({0.3, -0.7})).norm());
        }
    std::printf("  largest errors: value %.1e m, gradient %.1e\n", value_error, gradient_error);
    check(value_error < 1e-9 && gradient_error < 1e-9, "the plane, value and gradient");
    check(grid.contains(dealii::Point<2>(x0 + 10., y0 + 5.))
            && grid.contains(dealii::Point<2>(x0 + 90., y0 + 45.)),
          "the window covers the domain");
    check(refused([&] {
            terrain::read_raster_terrain("Raster file",
                                         "plane_utm.tif",
                                         dealii::Point<2>(x0 - 10., y0 + 5.),
                                         dealii::Point<2>(x0 + 90., y0 + 45.),
                                         strict);
          }),
          "a domain reaching outside the raster refused");
  }

  std::printf("Z1 as an ESRI ASCII grid without a CRS\n");
  {
    const double gt[6] = {0., 0.25, 0., 10., 0., -0.25};
    write_raster("AAIGrid", "z1.asc", 40, 40, gt, 0, z1);
    check(refused([&] {
            terrain::read_raster_terrain(
              "Raster file", "z1.asc", dealii::Point<2>(1., 1.), dealii::Point<2>(9., 9.), strict);
          }),
          "no CRS: refused unless declared metric");
    const auto grid = terrain::read_raster_terrain(
      "Raster file", "z1.asc", dealii::Point<2>(1., 1.), dealii::Point<2>(9., 9.), metric);
    double error = 0.;
    for (int i = 4; i < 36; ++i)
      for (int j = 4; j < 36; ++j)
        {
          const dealii::Point<2> centre((i + 0.5) * 0.25, (j + 0.5) * 0.25);
          error = std::max(error, std::abs(grid.value(centre) - z1(centre[0], centre[1])));
        }
    std::printf("  largest error at the pixel centres: %.1e m\n", error);
    check(error < 1e-9, "Z1 at the pixel centres");
  }

  std::printf("a raster in degrees, reprojected\n");
  {
    const double gt[6] = {8.9, 0.002, 0., 45.6, 0., -0.002};
    const auto   field = [](const double lon, const double lat) {
      return 100. + 1000. * (lon - 9.) + 2000. * (lat - 45.5);
    };
    write_raster("GTiff",
                 "degrees.tif",
                 static_cast<int>(0.2 / GEO_PIXEL),
                 static_cast<int>(0.2 / GEO_PIXEL),
                 gt,
                 4326,
                 field);
    const auto extent = terrain::raster_extent("Raster file", "degrees.tif", strict);
    {
      OGRSpatialReferenceH crs   = OSRNewSpatialReference(extent.crs_wkt.c_str());
      int                  north = 0;
      const int            zone  = OSRGetUTMZone(crs, &north);
      OSRDestroySpatialReference(crs);
      std::printf("  reprojected to UTM zone %d%s\n", zone, north ? "N" : "S");
      check(zone == 32 && north, "reprojected to UTM zone 32N, the zone of its centre");
    }
    // Points inside, in UTM coordinates, taken back to degrees for the exact field.
    const dealii::Point<2>     centre = 0.5 * (extent.lower + extent.upper);
    const dealii::Tensor<1, 2> half({2000., 2000.});
    const auto                 grid = terrain::read_raster_terrain(
      "Raster file", "degrees.tif", centre - half, centre + half, strict);
    double error = 0.;
    for (const double fx : {-0.9, -0.3, 0.2, 0.8})
      for (const double fy : {-0.7, 0.1, 0.6})
        {
          double       x = centre[0] + fx * 2000., y = centre[1] + fy * 2000.;
          const double value = grid.value(dealii::Point<2>(x, y));
          to_degrees(32632, x, y);
          error = std::max(error, std::abs(value - field(x, y)));
        }
    std::printf("  largest error against the field at 12 points: %.1e m\n", error);
    check(error < 1e-4, "elevations kept (1e-4 m)");

    // The footprint ('Grid/Extent = terrain raster'): the same square of 0.2 deg moved to
    // 11.5-11.7 E, 2.6 deg east of the zone's central meridian, where UTM's grid turns by
    // about theta = 1.9 deg against the meridians: the warp's corner wedges (about 500 m,
    // three pixels) are left out, data lie everywhere under the footprint (it is read
    // without a no-data refusal), and it keeps what a square turned by theta leaves
    // inside its bounding box, ((cos - sin) / (cos + sin))^2 = 0.88: between 0.85 and
    // 0.95 (the turned "square" is not quite square, and the edges are pixels). At 9 E
    // itself the square is not turned: its footprint is the whole box.
    const double east[6] = {11.5, 0.002, 0., 45.6, 0., -0.002};
    write_raster("GTiff", "degrees_east.tif", 100, 100, east, 4326, field);
    const auto box       = terrain::raster_extent("Raster file", "degrees_east.tif", strict);
    const auto footprint = terrain::raster_footprint("Raster file", "degrees_east.tif", strict);
    const auto area      = [](const terrain::RasterExtent &e) {
      return (e.upper[0] - e.lower[0]) * (e.upper[1] - e.lower[1]);
    };
    std::printf("  footprint: %.2f of the bounding box\n", area(footprint) / area(box));
    bool read_whole = true;
    try
      {
        terrain::read_raster_terrain(
          "Raster file", "degrees_east.tif", footprint.lower, footprint.upper, strict);
      }
    catch (const InputError &e)
      {
        std::printf("    (%s)\n", e.allowed.c_str());
        read_whole = false;
      }
    check(refused([&] {
            terrain::read_raster_terrain(
              "Raster file", "degrees_east.tif", box.lower, box.upper, strict);
          }),
          "the bounding box holds no-data (the wedges)");
    check(read_whole && footprint.lower[0] >= box.lower[0] && footprint.upper[0] <= box.upper[0]
            && footprint.lower[1] >= box.lower[1] && footprint.upper[1] <= box.upper[1]
            && area(footprint) > 0.85 * area(box) && area(footprint) < 0.95 * area(box),
          "the footprint: data everywhere under it, the wedges left out");
    const auto centred = terrain::raster_footprint("Raster file", "degrees.tif", strict);
    check(centred.lower == extent.lower && centred.upper == extent.upper,
          "at the central meridian the footprint is the whole box");
  }

  std::printf("no-data, bad files\n");
  {
    const double gt[6] = {0., 1., 0., 20., 0., -1.};
    const auto   flat  = [](double, double) { return 7.; };
    write_raster("GTiff", "hole.tif", 20, 20, gt, 32632, flat, 15.5, 15.5);
    check(refused([&] {
            terrain::read_raster_terrain("Raster file",
                                         "hole.tif",
                                         dealii::Point<2>(2., 2.),
                                         dealii::Point<2>(18., 18.),
                                         strict);
          }),
          "no-data under the domain refused");
    const auto grid = terrain::read_raster_terrain(
      "Raster file", "hole.tif", dealii::Point<2>(2., 2.), dealii::Point<2>(12., 12.), strict);
    const auto whole = terrain::raster_footprint("Raster file", "plane_utm.tif", strict);
    const auto box   = terrain::raster_extent("Raster file", "plane_utm.tif", strict);
    check(whole.lower == box.lower && whole.upper == box.upper,
          "a raster without no-data: the footprint is its extent");
    check(grid.value(dealii::Point<2>(7., 7.)) == 7., "no-data outside the window not read");
    check(refused([&] {
            terrain::read_raster_terrain(
              "Raster file", "missing.tif", dealii::Point<2>(), dealii::Point<2>(1., 1.), strict);
          }),
          "a missing file refused");
    std::ofstream("text.tif") << "not a raster\n";
    check(refused([&] {
            terrain::read_raster_terrain(
              "Raster file", "text.tif", dealii::Point<2>(), dealii::Point<2>(1., 1.), strict);
          }),
          "a file that is not a raster refused");
  }

  std::printf("a depth-averaged run on a raster and on the expression\n");
  {
    const double gt[6] = {-1., 1., 0., 6., 0., -1.};
    write_raster("AAIGrid", "incline.asc", 43, 7, gt, 0, [](double x, double) { return -0.5 * x; });
    const auto   a = slab_run("    set Elevation = -0.5*x\n");
    const auto   b = slab_run("    set Source = raster\n"
                              "    set Raster file = incline.asc\n"
                              "    set Raster without CRS = metric\n");
    const double d = std::max({std::abs(a.momentum_x - b.momentum_x) / std::abs(a.momentum_x),
                               std::abs(a.kinetic_energy - b.kinetic_energy) / a.kinetic_energy,
                               std::abs(a.mass - b.mass) / a.mass});
    std::printf("  momentum_x %.6e and %.6e, largest relative difference %.1e\n",
                a.momentum_x,
                b.momentum_x,
                d);
    check(a.momentum_x > 0. && d < 1e-12, "the same run");
  }
  return unit_check::finish();
}
