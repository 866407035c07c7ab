// Release areas and depths from GIS files (terrain::read_polygons and depth_averaged::Release,
// issue 19). The test writes its own files into the working directory:
//  - a GeoJSON in degrees (no 'crs' member: WGS 84) of a square with a hole near 87 W on
//    the equator, read into UTM zone 16N (EPSG:32616), whose central meridian is 87 W: the
//    vertex (87 W, 0) must land on (500000, 0) and (87 W, 0.01 N) on easting 500000, to
//    1e-6 m (the projection's definition; round-off of coordinates of 5e5 m is 1e-10 m),
//    with the hole and the 'thickness' field kept and the closing vertex dropped;
//  - the same file with no model CRS (a terrain from an expression): refused;
//  - a GeoJSON in EPSG:32616 read into EPSG:32616: coordinates unchanged, exactly;
//  - refused with the parameter and the reason: a missing file, a raster given as a vector
//    file, an unknown layer, a missing field, a text field, a file of points, no polygon;
//  - a depth raster in degrees (EPSG:4326, 3 m everywhere) over a terrain raster in UTM 16N:
//    reprojected to the terrain's CRS (nearest pixel), every column of a 100 m x 100 m
//    release gets 3 m: mass rho x 3 m x 1e4 m^2 to 1e-12 relative (a sum of 1600 equal
//    columns), maximum depth 3 m exactly;
//  - the same with one no-data pixel under the release: refused, on every rank at once.
#include "depth_averaged_input.h"
#include "raster_writer.h"
#include "unit_check.h"

#include <cmath>
#include <cpl_conv.h>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <fstream>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/terrain/vector_polygons.h>
#include <string>

using namespace slidewave;
using unit_check::check;
using unit_check::refused;

namespace
{
  void
  write_text(const std::string &path, const std::string &text)
  {
    std::ofstream(path) << text;
  }

  std::string
  wkt_of(const int epsg)
  {
    OGRSpatialReferenceH crs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(crs, epsg);
    char *wkt = nullptr;
    OSRExportToWkt(crs, &wkt);
    const std::string result = wkt;
    CPLFree(wkt);
    OSRDestroySpatialReference(crs);
    return result;
  }

  /** A feature collection of @p features, in @p crs ("" for none). */
  std::string
  collection(const std::string &crs, const std::string &features)
  {
    return "{ \"type\": \"FeatureCollection\", \"name\": \"areas\", "
           + (crs.empty() ?
                std::string() :
                "\"crs\": { \"type\": \"name\", \"properties\": { \"name\": \"" + crs + "\" } }, ")
           + "\"features\": [" + features + "] }\n";
  }

  /** The integrals right after the set-up of a release over the raster terrain
   *  terrain_utm.tif with its depth from @p depth_raster. */
  depth_averaged::DepthAveragedModel::Integrals
  release_integrals(const std::string &depth_raster)
  {
    const auto parameters
      = depth_averaged_parameters("subsection Depth averaged\n"
                                  "  set Shape functions = q1\n"
                                  "  set Depth update = strain\n"
                                  "  subsection Grid\n"
                                  "    set Lower left = 500000, 4000000\n"
                                  "    set Upper right = 500200, 4000200\n"
                                  "    set Cell size = 5\n"
                                  "  end\n"
                                  "  subsection Terrain\n"
                                  "    set Source = raster\n"
                                  "    set Raster file = terrain_utm.tif\n"
                                  "  end\n"
                                  "  subsection Release\n"
                                  "    set Shape = rectangle\n"
                                  "    set Rectangle = 500050, 4000050, 500150, 4000150\n"
                                  "    set Particles per direction = 2\n"
                                  "    set Depth raster = "
                                  + depth_raster
                                  + "\n"
                                    "  end\n"
                                    "end\n");
    auto grid = depth_averaged::DepthAveragedSolver::make_grid(parameters);
    depth_averaged::DepthAveragedSolver solver(parameters, *grid);
    solver.setup(0.);
    return solver.model().integrals(solver.point_cloud());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unit_check::print = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  GDALAllRegister();
  const std::string utm16 = wkt_of(32616);
  const std::string square_with_hole
    = "{ \"type\": \"Feature\", \"properties\": { \"thickness\": 1.5, \"name\": \"slab\" }, "
      "\"geometry\": { \"type\": \"Polygon\", \"coordinates\": ["
      "[[-87, 0], [-86.99, 0], [-86.99, 0.01], [-87, 0.01], [-87, 0]], "
      "[[-86.998, 0.002], [-86.998, 0.004], [-86.996, 0.004], [-86.996, 0.002], "
      "[-86.998, 0.002]]] } }";
  // Only rank 0 writes; the others wait for the files.
  if (unit_check::print)
    {
      write_text("degrees.geojson", collection("", square_with_hole));
      write_text("utm.geojson",
                 collection("urn:ogc:def:crs:EPSG::32616",
                            "{ \"type\": \"Feature\", \"properties\": {}, \"geometry\": { "
                            "\"type\": \"Polygon\", \"coordinates\": [[[500010.25, 4000020.5], "
                            "[500030, 4000020.5], [500020, 4000040.75], [500010.25, "
                            "4000020.5]]] } }"));
      write_text("points.geojson",
                 collection("urn:ogc:def:crs:EPSG::32616",
                            "{ \"type\": \"Feature\", \"properties\": {}, \"geometry\": { "
                            "\"type\": \"Point\", \"coordinates\": [500010, 4000020] } }"));
      write_text("empty.geojson", collection("urn:ogc:def:crs:EPSG::32616", ""));
      const double gt[6] = {499990., 1., 0., 4000210., 0., -1.};
      write_raster("GTiff", "terrain_utm.tif", 220, 220, gt, 32616, [](double x, double y) {
        return 100. + 0.1 * (x - 500000.) - 0.05 * (y - 4000000.);
      });
      // 3 m over the release in degrees: 87 W is the zone's central meridian, 4e6 m of
      // northing is about 36.14 N; pixels of 1e-4 deg (about 9-11 m).
      const double geo[6] = {-87.0005, 1e-4, 0., 36.1500, 0., -1e-4};
      const auto   three  = [](double, double) { return 3.; };
      write_raster("GTiff", "depth_degrees.tif", 80, 80, geo, 4326, three);
      // The same with a hole at the release's centre (500100, 4000100).
      double lon = 500100., lat = 4000100.;
      to_degrees(32616, lon, lat);
      write_raster("GTiff", "depth_hole.tif", 80, 80, geo, 4326, three, lon, lat);
    }
  MPI_Barrier(MPI_COMM_WORLD);

  std::printf("polygons in degrees read into UTM 16N\n");
  {
    const auto polygons
      = terrain::read_polygons("Vector file", "degrees.geojson", "", utm16, "thickness");
    const bool shape = polygons.size() == 1 && polygons[0].outer.size() == 4
                       && polygons[0].holes.size() == 1 && polygons[0].holes[0].size() == 4;
    check(shape, "one polygon, four vertices (the closing one dropped), one hole");
    if (shape)
      {
        const auto &outer = polygons[0].outer;
        if (unit_check::print)
          std::printf("  (87 W, 0) -> (%.6f, %.6f), (87 W, 0.01 N) -> (%.6f, %.3f)\n",
                      outer[0][0],
                      outer[0][1],
                      outer[3][0],
                      outer[3][1]);
        check(std::abs(outer[0][0] - 500000.) < 1e-6 && std::abs(outer[0][1]) < 1e-6
                && std::abs(outer[3][0] - 500000.) < 1e-6 && outer[3][1] > 1100.
                && outer[3][1] < 1110.,
              "the central meridian at easting 500000, the equator at northing 0");
        check(polygons[0].attribute == 1.5, "the thickness field read");
      }
    check(refused([] { terrain::read_polygons("Vector file", "degrees.geojson", "", ""); }),
          "degrees with no model CRS refused");
  }

  std::printf("polygons in the model's CRS\n");
  {
    const auto polygons = terrain::read_polygons("Vector file", "utm.geojson", "", utm16);
    check(polygons.size() == 1 && polygons[0].outer.size() == 3
            && polygons[0].outer[0] == dealii::Point<2>(500010.25, 4000020.5)
            && polygons[0].outer[2] == dealii::Point<2>(500020, 4000040.75)
            && std::isnan(polygons[0].attribute),
          "coordinates unchanged, exactly; no attribute asked for");
  }

  std::printf("bad vector files\n");
  {
    const auto read = [&](const std::string &file,
                          const std::string &layer     = "",
                          const std::string &attribute = "") {
      return [=] { terrain::read_polygons("Vector file", file, layer, utm16, attribute); };
    };
    check(refused(read("no_such.geojson")), "a missing file refused");
    check(refused(read("terrain_utm.tif")), "a raster refused");
    check(refused(read("degrees.geojson", "roads")), "an unknown layer refused");
    check(refused(read("degrees.geojson", "", "depth")), "a missing field refused");
    check(refused(read("degrees.geojson", "", "name")), "a text field refused");
    check(refused(read("points.geojson")), "points refused");
    check(refused(read("empty.geojson")), "no polygon refused");
  }

  std::printf("a depth raster in degrees over a terrain in UTM 16N\n");
  {
    const auto   integrals = release_integrals("depth_degrees.tif");
    const double expected  = 1200. * 3. * 1e4;
    if (unit_check::print)
      std::printf("  mass %.10e kg (expected %.10e), max depth %.17g m, %u columns\n",
                  integrals.mass,
                  expected,
                  integrals.max_depth,
                  integrals.n_particles);
    check(std::abs(integrals.mass - expected) < 1e-12 * expected && integrals.max_depth == 3.,
          "every column 3 m deep");
    check(refused([] { release_integrals("depth_hole.tif"); }),
          "no-data under the release refused");
  }
  return unit_check::print ? unit_check::finish() : 0;
}
