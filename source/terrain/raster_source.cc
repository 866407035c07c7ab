#include <algorithm>
#include <atomic>
#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <filesystem>
#include <gdal.h>
#include <gdal_utils.h>
#include <gdalwarper.h>
#include <limits>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/terrain/crs.h>
#include <slidewave/terrain/gdal_diagnostics.h>
#include <slidewave/terrain/raster_source.h>
#include <sstream>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** RasterSource::n_opened() and n_warped(). */
      std::atomic<unsigned int> n_opens{0}, n_warps{0};



      /** The WKT of @p crs ("" for none). */
      std::string
      wkt_of(const OGRSpatialReferenceH crs)
      {
        if (crs == nullptr)
          return "";
        char *wkt = nullptr;
        OSRExportToWkt(crs, &wkt);
        const std::string result = wkt != nullptr ? wkt : "";
        CPLFree(wkt);
        return result;
      }



      /**
       * The WKT of the CRS a raster in @p crs must be warped to, or "" when it is read as
       * it is (@p metric_wkt: @p crs in metres, crs.h in_metres()): options.match_crs when
       * given and different from both; else, for a raster in degrees, options.target_crs
       * or the UTM zone of its @p centre (longitude, latitude; a raster across the
       * antimeridian may give a longitude beyond 180 degrees).
       */
      std::string
      target_crs(const OGRSpatialReferenceH crs,
                 const std::string         &metric_wkt,
                 const dealii::Point<2>    &centre,
                 const RasterOptions       &options,
                 const std::string         &parameter,
                 const std::string         &filename)
      {
        if (crs == nullptr)
          return "";
        OGRSpatialReferenceH target = OSRNewSpatialReference(nullptr);
        OSRSetAxisMappingStrategy(target, OAMS_TRADITIONAL_GIS_ORDER);
        bool ok = true;
        if (!options.match_crs.empty())
          {
            ok = OSRSetFromUserInput(target, options.match_crs.c_str()) == OGRERR_NONE;
            if (ok && (OSRIsSame(target, crs) || same_crs(options.match_crs, metric_wkt)))
              {
                OSRDestroySpatialReference(target);
                return "";
              }
          }
        else if (!OSRIsGeographic(crs))
          {
            OSRDestroySpatialReference(target);
            return "";
          }
        else if (options.target_crs.empty())
          {
            // The UTM zone of the raster's centre, its longitude taken into [-180, 180).
            const double longitude = centre[0] - 360. * std::floor((centre[0] + 180.) / 360.);
            const int    zone
              = std::min(static_cast<int>(std::floor((longitude + 180.) / 6.)) + 1, 60);
            OGRSpatialReferenceH geographic = OSRClone(crs);
            OSRSetAxisMappingStrategy(geographic, OAMS_TRADITIONAL_GIS_ORDER);
            ok = OSRCopyGeogCSFrom(target, geographic) == OGRERR_NONE
                 && OSRSetUTM(target, zone, centre[1] >= 0. ? 1 : 0) == OGRERR_NONE;
            OSRDestroySpatialReference(geographic);
          }
        else
          {
            ok = OSRSetFromUserInput(target, options.target_crs.c_str()) == OGRERR_NONE
                 && !OSRIsGeographic(target);
            char        *unit   = nullptr;
            const double metres = ok ? OSRGetLinearUnits(target, &unit) : 1.;
            if (metres != 1.)
              {
                const std::string unit_name = unit != nullptr ? unit : "?";
                OSRDestroySpatialReference(target);
                throw InputError(parameter.substr(0, parameter.rfind('/')) + "/Target CRS",
                                 options.target_crs,
                                 "a projected CRS in metres (this one's unit is the " + unit_name
                                   + ", " + to_string(metres)
                                   + " m: the model's coordinates are metres; use its metric "
                                     "twin, "
                                   + metric_twin(options.target_crs) + ")");
              }
          }
        if (!ok)
          {
            OSRDestroySpatialReference(target);
            throw InputError(parameter,
                             filename,
                             "a raster that can be reprojected to a metric CRS (the target '"
                               + (options.match_crs.empty() ? options.target_crs :
                                                              options.match_crs)
                               + "' is not a projected CRS GDAL knows)");
          }
        // With its EPSG code the CRS travels into every file written in it (GeoJSON
        // keeps only an authority code).
        OSRAutoIdentifyEPSG(target);
        char *wkt = nullptr;
        OSRExportToWkt(target, &wkt);
        OSRDestroySpatialReference(target);
        const std::string result = wkt;
        CPLFree(wkt);
        return result;
      }



      /** Refuses a raster in degrees (@p crs geographic) whose pixel centres (@p gt, @p w x
       *  @p h pixels) are not longitudes and latitudes: coordinates in metres under a CRS
       *  in degrees (a wrong .prj) would otherwise be reprojected into nonsense. */
      void
      require_degrees(const OGRSpatialReferenceH crs,
                      const double               gt[6],
                      const int                  w,
                      const int                  h,
                      const std::string         &parameter,
                      const std::string         &filename)
      {
        const double x0 = gt[0] + 0.5 * gt[1], x1 = gt[0] + (w - 0.5) * gt[1];
        const double y0 = gt[3] + 0.5 * gt[5], y1 = gt[3] + (h - 0.5) * gt[5];
        const double west = std::min(x0, x1), east = std::max(x0, x1);
        const double south = std::min(y0, y1), north = std::max(y0, y1);
        if (west >= -360. && east <= 360. && east - west <= 360. && south >= -90. && north <= 90.)
          return;
        throw InputError(parameter,
                         filename,
                         "a raster in degrees (its CRS, " + crs_name(wkt_of(crs))
                           + ", is geographic) whose pixel centres are longitudes in [-360, 360] "
                             "and latitudes in [-90, 90] (this one's span ["
                           + to_string(west) + ", " + to_string(east) + "] x [" + to_string(south)
                           + ", " + to_string(north)
                           + "]: metres under a wrong CRS? Fix its .prj or assign the right CRS, "
                             "e.g. with gdal_translate -a_srs)");
      }



      /** The first and last pixel (rows or columns) whose centres bracket [a, b] along one
       *  axis of origin @p o and pixel size @p d (negative for rows north to south). */
      std::pair<long, long>
      bracket(const double a, const double b, const double o, const double d)
      {
        const double s0 = (a - o) / d - 0.5, s1 = (b - o) / d - 0.5;
        const double lo = std::min(s0, s1), hi = std::max(s0, s1);
        // A coordinate on a pixel centre (to round-off) needs no neighbour beyond it.
        const long first = static_cast<long>(std::floor(lo + 1e-9));
        const long last  = static_cast<long>(std::ceil(hi - 1e-9));
        return {first, std::max(last, first + 1)};
      }



      /** Refuses a raster without a coordinate reference system (@p crs null) unless its
       *  coordinates are to be taken as metres. */
      void
      require_crs(const GDALDatasetH         source,
                  const OGRSpatialReferenceH crs,
                  const RasterOptions       &options,
                  const std::string         &parameter,
                  const std::string         &filename)
      {
        if (crs != nullptr || options.assume_metric)
          return;
        // A .prj next to the file that GDAL could not read says nothing is a mistake.
        std::string prj;
        char      **files = GDALGetFileList(source);
        for (char **file = files; file != nullptr && *file != nullptr; ++file)
          if (EQUAL(CPLGetExtension(*file), "prj"))
            prj = std::filesystem::path(*file).filename().string();
        CSLDestroy(files);
        if (!prj.empty())
          throw InputError(
            parameter,
            filename,
            "a raster with a coordinate reference system GDAL can read (its " + prj
              + " holds none GDAL reads: write it again, e.g. with gdalsrsinfo -o wkt_esri "
                "EPSG:32616, or delete it and set 'Raster without CRS = metric')");
        throw InputError(parameter,
                         filename,
                         "a raster with a coordinate reference system (this one has none: "
                         "set 'Raster without CRS = metric' to take its coordinates as "
                         "metres)");
      }



      /**
       * The pixel size [m] of the warp of a raster of geotransform @p gt in @p crs centred at
       * @p centre: no larger than the source's smallest side in metres. Bilinear resampling
       * onto a coarser grid averages (GDAL widens the kernel) and bends even a field linear
       * in degrees by 0.1 % of its relief; onto a finer one it keeps it.
       */
      double
      warp_resolution(const double               gt[6],
                      const OGRSpatialReferenceH crs,
                      const dealii::Point<2>    &centre)
      {
        double resolution = std::min(gt[1], std::abs(gt[5])) * OSRGetLinearUnits(crs, nullptr);
        if (OSRIsGeographic(crs))
          {
            const double metres_per_degree = M_PI / 180. * 6371000.;
            resolution = std::min(gt[1] * metres_per_degree * std::cos(centre[1] * M_PI / 180.),
                                  std::abs(gt[5]) * metres_per_degree);
          }
        return resolution;
      }
    } // namespace



    RasterSource::RasterSource(const std::string   &parameter,
                               const std::string   &filename,
                               const RasterOptions &options)
      : parameter(parameter)
      , filename(filename)
      , options(options)
    {
      // A constructor that throws runs no destructor: what is open is closed here.
      try
        {
          open();
          // Before a pixel is read: a raster too large for the memory is refused.
          core::MemoryEstimate::check_raster(parameter,
                                             filename,
                                             GDALGetRasterXSize(source),
                                             GDALGetRasterYSize(source));
          check_ascii_grid(parameter, filename, source);
          double gt[6];
          read_geotransform(gt);
          const OGRSpatialReferenceH crs = GDALGetSpatialRef(source);
          require_crs(source, crs, options, parameter, filename);
          to_metres   = band_to_metres(parameter, filename, source, crs);
          const int w = GDALGetRasterXSize(source), h = GDALGetRasterYSize(source);
          if (crs != nullptr && OSRIsGeographic(crs))
            require_degrees(crs, gt, w, h, parameter, filename);
          // x = longitude in GDAL's traditional order of a geotransform.
          const dealii::Point<2> centre(gt[0] + 0.5 * gt[1] * w, gt[3] + 0.5 * gt[5] * h);
          // A projected CRS in feet: read in the same projection in metres.
          double            metres     = 1.;
          const std::string metric_wkt = in_metres(wkt_of(crs), metres);
          const std::string target_wkt
            = target_crs(crs, metric_wkt, centre, options, parameter, filename);
          if (!target_wkt.empty())
            {
              warp(target_wkt, warp_resolution(gt, crs, centre));
              GDALGetGeoTransform(warped, transform);
              model_wkt = wkt_of(GDALGetSpatialRef(warped));
            }
          else
            {
              for (unsigned int i = 0; i < 6; ++i)
                transform[i] = metres * gt[i];
              model_wkt = metric_wkt;
            }
        }
      catch (...)
        {
          if (warped != nullptr)
            GDALClose(warped);
          if (source != nullptr)
            GDALClose(source);
          throw;
        }
    }



    void
    RasterSource::open()
    {
      GDALAllRegister();
      // GDAL's own diagnosis goes to stderr otherwise; the InputError says what is wrong.
      const GdalDiagnostics diagnostics;
      // ESRI ASCII grids are read as 32-bit floats unless asked otherwise.
      CPLSetThreadLocalConfigOption("AAIGRID_DATATYPE", "Float64");
      source = GDALOpen(filename.c_str(), GA_ReadOnly);
      if (source == nullptr)
        {
          // What GDAL says of a file that is there (a header it cannot parse, ...); of a
          // missing one it would only repeat the path.
          std::error_code error;
          if (std::filesystem::exists(filename, error) && !diagnostics.text().empty())
            throw InputError(parameter,
                             filename,
                             "a raster file GDAL can read (GeoTIFF, ESRI ASCII grid, ...; GDAL "
                             "cannot read this one: "
                               + diagnostics.text() + ")");
          throw InputError(parameter,
                           filename,
                           "a raster file GDAL can read (GeoTIFF, ESRI ASCII grid, ...): it "
                           "does not exist or is not a raster");
        }
      ++n_opens;
      if (GDALGetRasterCount(source) < 1)
        throw InputError(parameter, filename, "a raster with at least one band");
    }



    void
    RasterSource::read_geotransform(double gt[6]) const
    {
      if (GDALGetGeoTransform(source, gt) != CE_None)
        throw InputError(parameter,
                         filename,
                         "a georeferenced raster (this one has no geotransform)");
      check_geotransform(parameter, filename, gt);
    }



    void
    RasterSource::warp(const std::string &target_wkt, const double resolution)
    {
      const std::string         res       = std::to_string(resolution);
      std::vector<const char *> arguments = {"-of",
                                             "MEM",
                                             "-t_srs",
                                             target_wkt.c_str(),
                                             "-r",
                                             options.resampling.c_str(),
                                             "-et",
                                             "0",
                                             "-tr",
                                             res.c_str(),
                                             res.c_str(),
                                             // Outside the source (the wedges a
                                             // reprojection opens at the corners):
                                             // no-data, refused under the domain.
                                             "-dstnodata",
                                             "-3.4e38",
                                             nullptr};
      GDALWarpAppOptions       *warp_options
        = GDALWarpAppOptionsNew(const_cast<char **>(arguments.data()), nullptr);
      const GdalDiagnostics diagnostics;
      int                   error = 0;
      warped                      = GDALWarp("", nullptr, 1, &source, warp_options, &error);
      GDALWarpAppOptionsFree(warp_options);
      if (warped == nullptr || error != 0)
        throw InputError(parameter,
                         filename,
                         "a raster GDAL can reproject to a metric CRS (the warper "
                         "refused this one"
                           + (diagnostics.text().empty() ? std::string() :
                                                           ": " + diagnostics.text())
                           + ")");
      ++n_warps;
    }



    RasterSource::~RasterSource()
    {
      if (warped != nullptr)
        GDALClose(warped);
      if (source != nullptr)
        GDALClose(source);
    }



    double
    RasterSource::pixel_count() const
    {
      return static_cast<double>(GDALGetRasterXSize(source)) * GDALGetRasterYSize(source);
    }



    unsigned int
    RasterSource::n_opened()
    {
      return n_opens;
    }



    unsigned int
    RasterSource::n_warped()
    {
      return n_warps;
    }



    RasterExtent
    RasterSource::pixel_block(const int c0, const int c1, const int r0, const int r1) const
    {
      const double *gt = transform;
      RasterExtent  block;
      const double  x0 = gt[0] + (c0 + 0.5) * gt[1], x1 = gt[0] + (c1 + 0.5) * gt[1];
      const double  y0 = gt[3] + (r0 + 0.5) * gt[5], y1 = gt[3] + (r1 + 0.5) * gt[5];
      block.lower   = dealii::Point<2>(std::min(x0, x1), std::min(y0, y1));
      block.upper   = dealii::Point<2>(std::max(x0, x1), std::max(y0, y1));
      block.pixel_x = std::abs(gt[1]);
      block.pixel_y = std::abs(gt[5]);
      block.crs_wkt = model_wkt;
      return block;
    }



    RasterExtent
    RasterSource::extent() const
    {
      return pixel_block(0,
                         GDALGetRasterXSize(dataset()) - 1,
                         0,
                         GDALGetRasterYSize(dataset()) - 1);
    }



    RasterExtent
    RasterSource::footprint() const
    {
      const double *gt   = transform;
      GDALDatasetH  data = dataset();
      const int     w = GDALGetRasterXSize(data), h = GDALGetRasterYSize(data);
      // GDAL's mask of valid pixels (no-data, NaN and the warp's wedges are 0).
      std::vector<unsigned char> valid(static_cast<std::size_t>(w) * h);
      GDALRasterBandH            mask = GDALGetMaskBand(GDALGetRasterBand(data, 1));
      if (GDALRasterIO(mask, GF_Read, 0, 0, w, h, valid.data(), w, h, GDT_Byte, 0, 0) != CE_None)
        throw InputError(parameter, filename, "a raster whose band 1 GDAL can read");
      std::vector<int> first(h, -1), last(h, -1);
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          if (valid[static_cast<std::size_t>(r) * w + c] != 0)
            {
              if (first[r] < 0)
                first[r] = c;
              last[r] = c;
            }
      // The rows r0..r1 and columns c0..c1 of largest area (between pixel centres).
      double best    = -1.;
      int    rows[2] = {0, 0}, columns[2] = {0, 0};
      for (int r0 = 0; r0 < h; ++r0)
        {
          int c0 = first[r0], c1 = last[r0];
          for (int r1 = r0; r1 < h && first[r1] >= 0 && c0 >= 0; ++r1)
            {
              c0 = std::max(c0, first[r1]);
              c1 = std::min(c1, last[r1]);
              if (c1 <= c0)
                break;
              const double area = (c1 - c0) * gt[1] * (r1 - r0) * std::abs(gt[5]);
              if (area > best)
                {
                  best       = area;
                  rows[0]    = r0;
                  rows[1]    = r1;
                  columns[0] = c0;
                  columns[1] = c1;
                }
            }
        }
      if (!(best > 0.))
        throw InputError(parameter,
                         filename,
                         "a raster with data over at least 2 x 2 pixels (this one has none)");
      return pixel_block(columns[0], columns[1], rows[0], rows[1]);
    }



    ElevationGrid
    RasterSource::window(const dealii::Point<2> &lower, const dealii::Point<2> &upper) const
    {
      const double *gt   = transform;
      GDALDatasetH  data = dataset();
      const long    nx = GDALGetRasterXSize(data), ny = GDALGetRasterYSize(data);
      const auto [i0, i1] = bracket(lower[0], upper[0], gt[0], gt[1]);
      const auto [j0, j1] = bracket(lower[1], upper[1], gt[3], gt[5]);
      if (i0 < 0 || j0 < 0 || i1 >= nx || j1 >= ny)
        {
          const RasterExtent e = extent();
          std::ostringstream message;
          message.precision(12);
          message << "a raster covering " << options.window_name << " [" << lower[0] << ", "
                  << upper[0] << "] x [" << lower[1] << ", " << upper[1]
                  << "] (its pixel centres span [" << e.lower[0] << ", " << e.upper[0] << "] x ["
                  << e.lower[1] << ", " << e.upper[1] << "] in the coordinates the model uses)";
          throw InputError(parameter, filename, message.str());
        }
      const int           w = static_cast<int>(i1 - i0 + 1), h = static_cast<int>(j1 - j0 + 1);
      std::vector<double> values(static_cast<std::size_t>(w) * h);
      GDALRasterBandH     band = GDALGetRasterBand(data, 1);
      {
        const GdalDiagnostics diagnostics;
        if (GDALRasterIO(band, GF_Read, i0, j0, w, h, values.data(), w, h, GDT_Float64, 0, 0)
            != CE_None)
          throw InputError(parameter,
                           filename,
                           "a raster whose band 1 GDAL can read" + diagnostics.note());
      }
      int          has_nodata = 0;
      const double nodata     = GDALGetRasterNoDataValue(band, &has_nodata);
      // Rows from south to north (ElevationGrid's y grows), no-data refused.
      const bool          north_up = gt[5] < 0.;
      std::vector<double> z(values.size());
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          {
            const double v     = values[static_cast<std::size_t>(r) * w + c];
            const bool   empty = !std::isfinite(v) || (has_nodata && v == nodata);
            if (empty && options.nodata_as_nan)
              {
                const int row                            = north_up ? h - 1 - r : r;
                z[static_cast<std::size_t>(row) * w + c] = std::numeric_limits<double>::quiet_NaN();
                continue;
              }
            if (empty)
              {
                std::ostringstream message;
                message.precision(12);
                message << "elevations everywhere under " << options.window_name
                        << " (the pixel centred at (" << gt[0] + (i0 + c + 0.5) * gt[1] << ", "
                        << gt[3] + (j0 + r + 0.5) * gt[5]
                        << ") is no-data: crop the domain or fill the raster)";
                throw InputError(parameter, filename, message.str());
              }
            const double value = to_metres(v);
            if (!(value >= options.lowest_value && value <= options.highest_value))
              {
                std::ostringstream message;
                message.precision(12);
                message << options.values_allowed << ": the pixel centred at ("
                        << gt[0] + (i0 + c + 0.5) * gt[1] << ", " << gt[3] + (j0 + r + 0.5) * gt[5]
                        << ") holds " << value << " m";
                throw InputError(parameter, filename, message.str());
              }
            const int row                            = north_up ? h - 1 - r : r;
            z[static_cast<std::size_t>(row) * w + c] = value;
          }
      const double x_first = gt[0] + (i0 + 0.5) * gt[1];
      const double y_south = north_up ? gt[3] + (j1 + 0.5) * gt[5] : gt[3] + (j0 + 0.5) * gt[5];
      return ElevationGrid(dealii::Point<2>(x_first, y_south),
                           std::abs(gt[1]),
                           std::abs(gt[5]),
                           w,
                           h,
                           std::move(z),
                           options.nodata_as_nan);
    }
  } // namespace terrain
} // namespace slidewave
