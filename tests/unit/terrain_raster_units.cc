// Units and places of rasters and vector files that used to be read wrong (issue 29). The
// test writes its own files with GDAL into the working directory:
//  - a GeoTIFF in US survey feet (EPSG:2227, NAD83 / California zone 3 (ftUS)) of a plane
//    in metres: read in the same projection in metres (the geotransform scaled by the
//    unit, 0.3048006096 m, not warped): the extent is the file's times the unit, the CRS
//    GDAL's metric twin EPSG:26943, and a pixel centre lands where OGR's transformation
//    from EPSG:2227 to EPSG:26943 puts it (1e-3 m: the two EPSG definitions differ by
//    0.1 mm, EPSG:2227's false easting of 6561666.667 ftUS being 2000000.0001 m); the
//    values are the plane's at the pixel centres (1e-9 m);
//  - a GeoJSON polygon in EPSG:2227 read into that model CRS (reprojected by OGR from
//    EPSG:2227): each vertex is its feet times the unit (1e-3 m, as above);
//  - band units: a GeoTIFF whose band 1 is in feet ('ft') and one in a compound CRS whose
//    vertical part is in US survey feet (EPSG:2227+6360): 100 stored is 30.48 m and
//    30.48006096 m (1e-9 m); without a unit, 100 is 100 m;
//  - a raster in degrees across the antimeridian (179.9 E to 179.9 W, near Fiji) is
//    reprojected to UTM zone 1S, the zone of its centre (it used to be refused: "target ''
//    is not a projected CRS"), and keeps its values (a field linear in longitude and
//    latitude, 1e-3 m at its centre);
//  - a raster in degrees over coordinates in metres, a geotransform with a pixel height of
//    0, a band scale of NaN, an elevation of 1e300 m: refused.
#include "raster_writer.h"
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/crs.h>
#include <slidewave/terrain/raster_source.h>
#include <slidewave/terrain/vector_polygons.h>
#include <string>

using namespace slidewave;
using unit_check::check;
using unit_check::refused;

namespace
{
  /** The metres of a US survey foot, as GDAL has it. */
  const double us_foot = 0.3048006096012192;

  /** Writes a one-band GeoTIFF of the constant @p value in the CRS @p crs (anything
   *  GDAL takes), its band in @p unit ("" for none), with the geotransform @p gt, and
   *  optionally a band @p scale. */
  void
  write_constant(const std::string &path,
                 const std::string &crs,
                 const double      *gt,
                 const double       value,
                 const std::string &unit,
                 const double       scale = 1.)
  {
    GDALDatasetH data
      = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 10, 10, 1, GDT_Float64, nullptr);
    GDALSetGeoTransform(data, const_cast<double *>(gt));
    if (!crs.empty())
      {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        OSRSetFromUserInput(srs, crs.c_str());
        GDALSetSpatialRef(data, srs);
        OSRDestroySpatialReference(srs);
      }
    GDALRasterBandH     band = GDALGetRasterBand(data, 1);
    std::vector<double> values(100, value);
    if (GDALRasterIO(band, GF_Write, 0, 0, 10, 10, values.data(), 10, 10, GDT_Float64, 0, 0)
        != CE_None)
      std::printf("writing %s failed\n", path.c_str());
    if (!unit.empty())
      GDALSetRasterUnitType(band, unit.c_str());
    if (scale != 1.)
      GDALSetRasterScale(band, scale);
    GDALClose(data);
  }

  /** @p x, @p y from the CRS EPSG:@p from to EPSG:@p to, in place. */
  void
  transform(const int from, const int to, double &x, double &y)
  {
    OGRSpatialReferenceH a = OSRNewSpatialReference(nullptr);
    OGRSpatialReferenceH b = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(a, from);
    OSRImportFromEPSG(b, to);
    OSRSetAxisMappingStrategy(a, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(b, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH t = OCTNewCoordinateTransformation(a, b);
    OCTTransform(t, 1, &x, &y, nullptr);
    OCTDestroyCoordinateTransformation(t);
    OSRDestroySpatialReference(a);
    OSRDestroySpatialReference(b);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  GDALAllRegister();
  const terrain::RasterOptions strict;

  std::printf("a raster in US survey feet (EPSG:2227)\n");
  {
    const double x0 = 6000000., y0 = 2100000.; // feet
    const double gt[6] = {x0, 10., 0., y0 + 300., 0., -10.};
    const auto   plane
      = [&](const double x, const double y) { return 50. + 0.01 * (x - x0) - 0.02 * (y - y0); };
    write_raster("GTiff", "plane_feet.tif", 40, 30, gt, 2227, plane);
    const terrain::RasterSource raster("Raster file", "plane_feet.tif", strict);
    const auto                  extent = raster.extent();
    std::printf("  model CRS: %s\n", terrain::crs_name(extent.crs_wkt).c_str());
    std::printf("  pixels %.6f m x %.6f m\n", extent.pixel_x, extent.pixel_y);
    const double expected[2] = {(x0 + 5.) * us_foot, (y0 + 5.) * us_foot};
    check(std::abs(extent.lower[0] - expected[0]) < 1e-6
            && std::abs(extent.lower[1] - expected[1]) < 1e-6
            && std::abs(extent.pixel_x - 10. * us_foot) < 1e-12,
          "the extent and pixels are the file's times the unit");
    double x = x0 + 5., y = y0 + 5.;
    transform(2227, 26943, x, y);
    std::printf("  OGR: (%.3f, %.3f) ft -> (%.6f, %.6f) m\n", x0 + 5., y0 + 5., x, y);
    check(std::abs(x - extent.lower[0]) < 1e-3 && std::abs(y - extent.lower[1]) < 1e-3,
          "the lower-left pixel centre is where OGR puts it in EPSG:26943");
    const auto grid  = raster.window(extent.lower, extent.upper);
    double     error = 0.;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 30; ++j)
        {
          const double xf = x0 + 5. + 10. * i, yf = y0 + 5. + 10. * j;
          error = std::max(error,
                           std::abs(grid.value(dealii::Point<2>(xf * us_foot, yf * us_foot))
                                    - plane(xf, yf)));
        }
    std::printf("  largest error at the pixel centres: %.1e m\n", error);
    check(error < 1e-9, "the values kept (metres: the band declares no unit)");

    std::ofstream("release_feet.geojson")
      << "{ \"type\": \"FeatureCollection\", \"crs\": { \"type\": \"name\", \"properties\": "
         "{ \"name\": \"urn:ogc:def:crs:EPSG::2227\" } }, \"features\": [ { \"type\": "
         "\"Feature\", \"properties\": {}, \"geometry\": { \"type\": \"Polygon\", "
         "\"coordinates\": [ [ [6000100, 2100100], [6000200, 2100100], [6000200, 2100200], "
         "[6000100, 2100100] ] ] } } ] }\n";
    const auto polygons
      = terrain::read_polygons("Vector file", "release_feet.geojson", "", extent.crs_wkt);
    double vertex_error = 0.;
    for (const auto &p : polygons.at(0).outer)
      vertex_error = std::max(
        vertex_error,
        std::min(std::abs(p[0] - 6000100. * us_foot), std::abs(p[0] - 6000200. * us_foot))
          + std::min(std::abs(p[1] - 2100100. * us_foot), std::abs(p[1] - 2100200. * us_foot)));
    std::printf("  a GeoJSON in EPSG:2227: largest vertex error %.1e m\n", vertex_error);
    check(vertex_error < 1e-3, "a vector file in feet lands on the same metres");
  }

  std::printf("band units\n");
  {
    const double gt[6] = {500000., 1., 0., 5000010., 0., -1.};
    write_constant("unit_ft.tif", "EPSG:32632", gt, 100., "ft");
    write_constant("unit_none.tif", "EPSG:32632", gt, 100., "");
    const double gt_feet[6] = {6000000., 10., 0., 2100100., 0., -10.};
    write_constant("unit_compound.tif", "EPSG:2227+6360", gt_feet, 100., "");
    const auto value_of = [&](const std::string &path) {
      const terrain::RasterSource raster("Raster file", path, strict);
      const auto                  e = raster.extent();
      return raster.window(e.lower, e.upper).value(e.lower);
    };
    const double ft = value_of("unit_ft.tif"), none = value_of("unit_none.tif"),
                 compound = value_of("unit_compound.tif");
    std::printf("  100 in ft: %.9f m; in a CRS with heights in ftUS: %.9f m; no unit: %.9f m\n",
                ft,
                compound,
                none);
    check(std::abs(ft - 30.48) < 1e-9, "a band in feet converted");
    check(std::abs(compound - 100. * us_foot) < 1e-9, "a compound CRS's vertical unit used");
    check(none == 100., "no unit: metres");
  }

  std::printf("a raster in degrees across the antimeridian\n");
  {
    const double gt[6] = {179.9, 0.002, 0., -16.9, 0., -0.002};
    const auto   field = [](const double lon, const double lat) {
      return 100. + 50. * (lon - 179.9) - 80. * (lat + 16.9);
    };
    write_raster("GTiff", "antimeridian.tif", 100, 100, gt, 4326, field);
    const terrain::RasterSource raster("Raster file", "antimeridian.tif", strict);
    const auto                  extent = raster.extent();
    std::printf("  reprojected to %s\n", terrain::crs_name(extent.crs_wkt).c_str());
    check(terrain::crs_name(extent.crs_wkt).find("EPSG:32701") != std::string::npos,
          "reprojected to UTM zone 1S, the zone of its centre");
    double lon = 180., lat = -17.;
    // The centre in UTM 1S.
    transform(4326, 32701, lon, lat);
    const dealii::Point<2> centre(lon, lat);
    double                 back_x = lon, back_y = lat;
    to_degrees(32701, back_x, back_y);
    std::printf(
      "  180 E, 17 S is (%.3f, %.3f) in UTM 1S, and back (%.9f, %.9f)\n", lon, lat, back_x, back_y);
    const auto   grid  = raster.window(dealii::Point<2>(lon - 500., lat - 500.),
                                    dealii::Point<2>(lon + 500., lat + 500.));
    const double error = std::abs(grid.value(centre) - field(180., -17.));
    std::printf("  at 180 E, 17 S: error %.1e m\n", error);
    check(error < 1e-3, "the values kept across the antimeridian");
  }

  std::printf("refused\n");
  {
    std::ofstream("metres_as_degrees.asc")
      << "ncols 3\nnrows 3\nxllcorner 500000\nyllcorner 4000000\ncellsize 10\n"
         "1 1 1\n1 1 1\n1 1 1\n";
    std::ofstream("metres_as_degrees.prj")
      << "GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137.0,"
         "298.257223563]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]]\n";
    check(refused([] {
            terrain::RasterSource("Raster file", "metres_as_degrees.asc", terrain::RasterOptions());
          }),
          "metres under a CRS in degrees refused");
    const double flat[6] = {500000., 1., 0., 5000010., 0., 0.};
    write_constant("flat.tif", "EPSG:32632", flat, 1., "");
    check(refused(
            [] { terrain::RasterSource("Raster file", "flat.tif", terrain::RasterOptions()); }),
          "a pixel height of 0 refused");
    const double gt[6] = {500000., 1., 0., 5000010., 0., -1.};
    write_constant("scale_nan.tif", "EPSG:32632", gt, 1., "", std::nan(""));
    check(refused([] {
            terrain::RasterSource("Raster file", "scale_nan.tif", terrain::RasterOptions());
          }),
          "a scale of NaN refused");
    write_constant("absurd.tif", "EPSG:32632", gt, 1e300, "");
    check(refused([] {
            const terrain::RasterSource raster("Raster file",
                                               "absurd.tif",
                                               terrain::RasterOptions());
            const auto                  e = raster.extent();
            raster.window(e.lower, e.upper);
          }),
          "an elevation of 1e300 m refused");
  }

  return unit_check::finish();
}
