#include <cpl_error.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/map_files.h>
#include <slidewave/terrain/gdal_diagnostics.h>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace map_files
    {
      namespace
      {
        /** Throws an OutputFailure naming @p path when GDAL reported a failure since
         *  CPLErrorReset() (a dataset not created, a write or the flush at GDALClose
         *  failed), quoting what GDAL said. */
        void
        require_gdal_success(const std::string &path, const terrain::GdalDiagnostics &diagnostics)
        {
          if (CPLGetLastErrorType() >= CE_Failure)
            throw OutputFailure(
              path,
              "GDAL: " + (diagnostics.text().empty() ? std::string("failed") : diagnostics.text()));
        }
      } // namespace



      void
      write_geotiff(const std::string                                 &path,
                    const std::function<void(unsigned int, double *)> &row,
                    const unsigned int                                 width,
                    const unsigned int                                 height,
                    const double                                      *transform,
                    const std::string                                 &crs_wkt)
      {
        const int                      w = width, h = height;
        const terrain::GdalDiagnostics diagnostics;
        CPLErrorReset();
        GDALDatasetH data
          = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Float64, nullptr);
        if (data == nullptr)
          throw OutputFailure(path, "GDAL could not create it" + diagnostics.note());
        GDALSetGeoTransform(data, const_cast<double *>(transform));
        if (!crs_wkt.empty())
          GDALSetProjection(data, crs_wkt.c_str());
        GDALRasterBandH band = GDALGetRasterBand(data, 1);
        GDALSetRasterNoDataValue(band, no_data);
        // Row by row, from the north: the whole raster is never held (a regional DEM's
        // maps are millions of pixels).
        std::vector<double> values(w);
        CPLErr              written = CE_None;
        for (int r = 0; r < h && written == CE_None; ++r)
          {
            row(h - 1 - r, values.data());
            written
              = GDALRasterIO(band, GF_Write, 0, r, w, 1, values.data(), w, 1, GDT_Float64, 0, 0);
          }
        // The pixels reach the file at GDALClose (GDAL 3.6's returns nothing: its errors are
        // GDAL's last error).
        GDALClose(data);
        if (written != CE_None)
          throw OutputFailure(path, "GDAL could not write its pixels" + diagnostics.note());
        require_gdal_success(path, diagnostics);
      }



      void
      write_outline(const std::string       &path,
                    const std::vector<char> &inside,
                    const unsigned int       width,
                    const unsigned int       height,
                    const double            *transform,
                    const std::string       &crs_wkt)
      {
        const int    w = width, h = height;
        GDALDatasetH mask = GDALCreate(GDALGetDriverByName("MEM"), "", w, h, 1, GDT_Byte, nullptr);
        GDALSetGeoTransform(mask, const_cast<double *>(transform));
        std::vector<unsigned char> rows(static_cast<std::size_t>(w) * h);
        for (int j = 0; j < h; ++j)
          for (int i = 0; i < w; ++i)
            rows[static_cast<std::size_t>(h - 1 - j) * w + i]
              = inside[static_cast<std::size_t>(j) * w + i] ? 1 : 0;
        GDALRasterBandH band = GDALGetRasterBand(mask, 1);
        if (GDALRasterIO(band, GF_Write, 0, 0, w, h, rows.data(), w, h, GDT_Byte, 0, 0) != CE_None)
          return;
        const terrain::GdalDiagnostics diagnostics;
        CPLErrorReset();
        GDALDatasetH vector
          = GDALCreate(GDALGetDriverByName("GeoJSON"), path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
        if (vector == nullptr)
          {
            GDALClose(mask);
            throw OutputFailure(path, "GDAL could not create it" + diagnostics.note());
          }
        OGRSpatialReferenceH crs
          = crs_wkt.empty() ? nullptr : OSRNewSpatialReference(crs_wkt.c_str());
        OGRLayerH     layer = GDALDatasetCreateLayer(vector, "outline", crs, wkbPolygon, nullptr);
        OGRFieldDefnH field = OGR_Fld_Create("value", OFTInteger);
        OGR_L_CreateField(layer, field, TRUE);
        OGR_Fld_Destroy(field);
        GDALPolygonize(band, band, layer, 0, nullptr, nullptr, nullptr);
        if (crs != nullptr)
          OSRDestroySpatialReference(crs);
        GDALClose(vector);
        GDALClose(mask);
        require_gdal_success(path, diagnostics);
      }
    } // namespace map_files
  }   // namespace depth_averaged
} // namespace slidewave
