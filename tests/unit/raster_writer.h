#ifndef slidewave_tests_raster_writer_h
#define slidewave_tests_raster_writer_h

#include <cmath>
#include <cstdio>
#include <functional>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <string>
#include <vector>

// Rasters the tests write for themselves through GDAL.
namespace
{
  /** Writes a one-band float64 raster of @p f at the pixel centres. */
  void
  write_raster(const std::string                           &driver_name,
               const std::string                           &path,
               const int                                    nx,
               const int                                    ny,
               const double                                *gt,
               const int                                    epsg,
               const std::function<double(double, double)> &f,
               const double                                 nodata_x = NAN,
               const double                                 nodata_y = NAN)
  {
    GDALDriverH  mem  = GDALGetDriverByName("MEM");
    GDALDatasetH data = GDALCreate(mem, "", nx, ny, 1, GDT_Float64, nullptr);
    GDALSetGeoTransform(data, const_cast<double *>(gt));
    if (epsg > 0)
      {
        OGRSpatialReferenceH crs = OSRNewSpatialReference(nullptr);
        OSRImportFromEPSG(crs, epsg);
        GDALSetSpatialRef(data, crs);
        OSRDestroySpatialReference(crs);
      }
    std::vector<double> values(static_cast<std::size_t>(nx) * ny);
    for (int r = 0; r < ny; ++r)
      for (int c = 0; c < nx; ++c)
        {
          const double x = gt[0] + (c + 0.5) * gt[1], y = gt[3] + (r + 0.5) * gt[5];
          const bool   hole = std::abs(x - nodata_x) < 0.5 * gt[1]
                            && std::abs(y - nodata_y) < 0.5 * std::abs(gt[5]);
          values[static_cast<std::size_t>(r) * nx + c] = hole ? -9999. : f(x, y);
        }
    GDALRasterBandH band = GDALGetRasterBand(data, 1);
    GDALSetRasterNoDataValue(band, -9999.);
    if (GDALRasterIO(band, GF_Write, 0, 0, nx, ny, values.data(), nx, ny, GDT_Float64, 0, 0)
        != CE_None)
      std::printf("writing %s failed\n", path.c_str());
    const char  *options[] = {"DECIMAL_PRECISION=17", nullptr};
    GDALDatasetH copy
      = GDALCreateCopy(GDALGetDriverByName(driver_name.c_str()),
                       path.c_str(),
                       data,
                       FALSE,
                       driver_name == "AAIGrid" ? const_cast<char **>(options) : nullptr,
                       nullptr,
                       nullptr);
    GDALClose(copy);
    GDALClose(data);
  }

  /** Takes @p x, @p y from metres in the CRS EPSG:@p epsg to longitude and latitude
   *  (WGS 84, EPSG:4326), in place. */
  void
  to_degrees(const int epsg, double &x, double &y)
  {
    OGRSpatialReferenceH from = OSRNewSpatialReference(nullptr);
    OGRSpatialReferenceH to   = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(from, epsg);
    OSRImportFromEPSG(to, 4326);
    OSRSetAxisMappingStrategy(from, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(to, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH transformation = OCTNewCoordinateTransformation(from, to);
    OCTTransform(transformation, 1, &x, &y, nullptr);
    OCTDestroyCoordinateTransformation(transformation);
    OSRDestroySpatialReference(from);
    OSRDestroySpatialReference(to);
  }
} // namespace

#endif
