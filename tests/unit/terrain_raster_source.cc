// Each raster of a depth-averaged scene is opened and warped once (terrain::RasterSource,
// issue 25). The test writes a terrain in degrees (EPSG:4326, 0.2 deg square around 9 E,
// 45.5 N, reprojected to UTM 32N) and a release depth in degrees over its centre, and counts
// the openings and warps (RasterSource::n_opened, n_warped):
//  - a RasterSource asked for its extent, footprint and a window twice opens and warps the
//    file once, and gives what the one-call functions (raster_extent, raster_footprint,
//    read_raster_terrain) give, to the bit;
//  - a solver over the terrain raster: one opening, one warp (it was two: the CRS, then the
//    elevations);
//  - a scene with 'Grid/Extent = terrain raster' and its depth from the raster in degrees,
//    through its set-up: two openings and two warps, one each (it was five: three for the
//    terrain, the footprint, the CRS and the elevations; two for the depth raster);
//  - a missing file counts no opening.
#include "depth_averaged_input.h"
#include "raster_writer.h"
#include "unit_check.h"

#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <gdal.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/depth_averaged/depth_averaged_scene.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/terrain/raster_source.h>
#include <slidewave/terrain/raster_terrain.h>
#include <sstream>
#include <string>

using namespace slidewave;
using terrain::RasterSource;
using unit_check::check;
using unit_check::refused;

namespace
{
  /** The openings and warps of RasterSource since there were @p opened and @p warped. */
  std::string
  counted(const unsigned int opened, const unsigned int warped)
  {
    return std::to_string(RasterSource::n_opened() - opened) + " opened, "
           + std::to_string(RasterSource::n_warped() - warped) + " warped";
  }

  /** A scene's text: the @p grid entries, the terrain in degrees, a release of 1 km^2 at
   *  its centre (UTM 32N) with the @p release entries for its depth. */
  std::string
  scene_text(const std::string &grid, const std::string &release)
  {
    // The options of the test's blessed output (the defaults before issue 28).
    return "subsection Depth averaged\n"
           "  set Shape functions = q1\n"
           "  set Depth update = strain\n"
           "  subsection Grid\n"
           + grid
           + "  end\n"
             "  subsection Terrain\n"
             "    set Source = raster\n"
             "    set Raster file = terrain_degrees.tif\n"
             "  end\n"
             "  subsection Release\n"
             "    set Shape = rectangle\n"
             "    set Rectangle = 499500, 5038500, 500500, 5039500\n"
             "    set Particles per direction = 2\n"
           + release
           + "  end\n"
             "end\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  GDALAllRegister();
  {
    const double terrain[6] = {8.9, 0.002, 0., 45.6, 0., -0.002};
    write_raster("GTiff", "terrain_degrees.tif", 100, 100, terrain, 4326, [](double x, double y) {
      return 100. + 1000. * (x - 9.) + 2000. * (y - 45.5);
    });
    const double depth[6] = {8.98, 0.001, 0., 45.53, 0., -0.001};
    write_raster("GTiff", "depth_degrees.tif", 40, 40, depth, 4326, [](double, double) {
      return 2.;
    });
  }
  const terrain::RasterOptions strict;

  std::printf("one RasterSource, four questions\n");
  {
    const unsigned int opened = RasterSource::n_opened(), warped = RasterSource::n_warped();
    const RasterSource raster("Raster file", "terrain_degrees.tif", strict);
    const auto         extent    = raster.extent();
    const auto         footprint = raster.footprint();
    const auto         first     = raster.window(footprint.lower, footprint.upper);
    const auto         second    = raster.window(footprint.lower, footprint.upper);
    std::printf("  %s\n", counted(opened, warped).c_str());
    check(counted(opened, warped) == "1 opened, 1 warped", "opened and warped once");

    const auto once_extent = terrain::raster_extent("Raster file", "terrain_degrees.tif", strict);
    const auto once_footprint
      = terrain::raster_footprint("Raster file", "terrain_degrees.tif", strict);
    const auto once_window = terrain::read_raster_terrain(
      "Raster file", "terrain_degrees.tif", footprint.lower, footprint.upper, strict);
    check(counted(opened, warped) == "4 opened, 4 warped",
          "each one-call function opens and warps the file once");
    bool same = extent.lower == once_extent.lower && extent.upper == once_extent.upper
                && extent.crs_wkt == once_extent.crs_wkt && footprint.lower == once_footprint.lower
                && footprint.upper == once_footprint.upper;
    for (const double fx : {0.1, 0.37, 0.5, 0.92})
      for (const double fy : {0.05, 0.5, 0.81})
        {
          const dealii::Point<2> p(footprint.lower[0]
                                     + fx * (footprint.upper[0] - footprint.lower[0]),
                                   footprint.lower[1]
                                     + fy * (footprint.upper[1] - footprint.lower[1]));
          same = same && first.value(p) == once_window.value(p)
                 && second.value(p) == once_window.value(p);
        }
    check(same, "extent, footprint and elevations the one-call functions' (to the bit)");
  }

  std::printf("a solver over the terrain raster\n");
  {
    const auto parameters     = depth_averaged_parameters(scene_text("    set Lower left = 495000, "
                                                                     "5035000\n"
                                                                     "    set Upper right = 505000, "
                                                                     "5043000\n"
                                                                     "    set Cell size = 500\n",
                                                                 "    set Depth = 1\n"));
    const unsigned int opened = RasterSource::n_opened(), warped = RasterSource::n_warped();
    auto               grid = depth_averaged::DepthAveragedSolver::make_grid(parameters);
    depth_averaged::DepthAveragedSolver solver(parameters, *grid);
    std::printf("  %s\n", counted(opened, warped).c_str());
    check(counted(opened, warped) == "1 opened, 1 warped", "the terrain opened and warped once");
  }

  std::printf("a scene on the terrain raster's extent, its depth from a raster in degrees\n");
  {
    dealii::ParameterHandler prm;
    depth_averaged::DepthAveragedScene::declare_parameters(prm);
    prm.parse_input_from_string(scene_text("    set Extent = terrain raster\n"
                                           "    set Cell size = 500\n",
                                           "    set Depth raster = depth_degrees.tif\n"));
    SceneParameters scene_parameters;
    scene_parameters.scene_directory  = ".";
    scene_parameters.output_directory = "output";
    dealii::TimerOutput timer(MPI_COMM_WORLD,
                              std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    const unsigned int  opened = RasterSource::n_opened(), warped = RasterSource::n_warped();
    depth_averaged::DepthAveragedScene scene(scene_parameters, prm);
    scene.set_up(0., timer);
    std::printf("  %s\n", scene.description().c_str());
    std::printf("  %s\n", counted(opened, warped).c_str());
    check(counted(opened, warped) == "2 opened, 2 warped",
          "each raster opened and warped once (the footprint, the CRS and the elevations from "
          "one; the depth raster's extent and values from the other)");
  }

  std::printf("a missing file\n");
  {
    const unsigned int opened = RasterSource::n_opened(), warped = RasterSource::n_warped();
    check(refused([&] { RasterSource("Raster file", "missing.tif", strict); }),
          "a missing file refused");
    check(counted(opened, warped) == "0 opened, 0 warped", "and not counted");
  }
  return unit_check::finish();
}
