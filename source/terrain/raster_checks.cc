#include <cmath>
#include <cpl_string.h>
#include <fstream>
#include <gdal.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/raster_checks.h>
#include <sstream>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** The metres of the unit named @p name (a band's unit type as GDAL's drivers write
       *  it: "metre", "m", "foot", "ft", "US survey foot", ...); 0 for a unit we do not
       *  know. The factors are GDAL's (SRS_UL_FOOT_CONV, SRS_UL_US_FOOT_CONV). */
      double
      metres_of_unit(const std::string &name)
      {
        for (const char *metre : {"m", "metre", "meter", "metres", "meters"})
          if (EQUAL(name.c_str(), metre))
            return 1.;
        for (const char *foot : {"ft", "foot", "feet", "international foot"})
          if (EQUAL(name.c_str(), foot))
            return CPLAtof(SRS_UL_FOOT_CONV);
        for (const char *foot : {"US survey foot", "US survey feet", "ftUS", "us-ft", "foot_us"})
          if (EQUAL(name.c_str(), foot))
            return CPLAtof(SRS_UL_US_FOOT_CONV);
        return 0.;
      }
    } // namespace



    void
    check_geotransform(const std::string &parameter,
                       const std::string &filename,
                       const double       gt[6])
    {
      std::ostringstream shown;
      shown.precision(12);
      shown << "origin (" << gt[0] << ", " << gt[3] << "), pixel " << gt[1] << " x " << gt[5]
            << ", rotation " << gt[2] << ", " << gt[4];
      for (unsigned int i = 0; i < 6; ++i)
        if (!std::isfinite(gt[i]))
          throw InputError(parameter,
                           filename,
                           "a raster whose geotransform (origin and pixel size) is finite (this "
                           "one's: "
                             + shown.str() + ")");
      if (gt[2] != 0. || gt[4] != 0.)
        throw InputError(parameter, filename, "a north-up raster (this one is rotated or sheared)");
      if (!(gt[1] > 0.) || gt[5] == 0.)
        throw InputError(parameter,
                         filename,
                         "a raster whose pixels have a width > 0 and a height other than 0 "
                         "(this one's geotransform: "
                           + shown.str() + ")");
    }



    BandToMetres
    band_to_metres(const std::string &parameter,
                   const std::string &filename,
                   void              *dataset,
                   void              *crs)
    {
      GDALRasterBandH band       = GDALGetRasterBand(dataset, 1);
      int             has_scale  = 0;
      int             has_offset = 0;
      BandToMetres    map;
      const double    scale  = GDALGetRasterScale(band, &has_scale);
      const double    offset = GDALGetRasterOffset(band, &has_offset);
      if (has_scale)
        map.scale = scale;
      if (has_offset)
        map.offset = offset;
      if (!std::isfinite(map.scale) || map.scale == 0. || !std::isfinite(map.offset))
        throw InputError(parameter,
                         filename,
                         "a raster whose band 1 has a finite scale other than 0 and a finite "
                         "offset (band 1 of this one: scale "
                           + to_string(map.scale) + ", offset " + to_string(map.offset) + ")");

      // The vertical unit: the band's own, else the vertical part of a compound CRS.
      const char *band_unit = GDALGetRasterUnitType(band);
      std::string unit      = band_unit != nullptr ? band_unit : "";
      double      metres    = 1.;
      if (!unit.empty())
        metres = metres_of_unit(unit);
      else if (crs != nullptr && OSRIsCompound(crs))
        {
          char *name = nullptr;
          metres     = OSRGetTargetLinearUnits(crs, "VERT_CS", &name);
          unit       = name != nullptr ? name : "";
        }
      if (!(metres > 0.) || !std::isfinite(metres))
        throw InputError(parameter,
                         filename,
                         "a raster whose band 1 is in metres, feet or US survey feet (this one's "
                         "unit is '"
                           + unit
                           + "'; convert it, e.g. with gdal_translate -scale, and set its unit)");
      map.unit = unit.empty() ? "metre" : unit;
      map.scale *= metres;
      map.offset *= metres;
      return map;
    }



    void
    check_ascii_grid(const std::string &parameter, const std::string &filename, void *dataset)
    {
      GDALDriverH driver = GDALGetDatasetDriver(dataset);
      if (driver == nullptr || !EQUAL(GDALGetDriverShortName(driver), "AAIGrid"))
        return;
      const long    ncols = GDALGetRasterXSize(dataset), nrows = GDALGetRasterYSize(dataset);
      std::ifstream file(filename);
      if (!file)
        return;
      // The header's lines start with a keyword (ncols, nrows, xllcorner, cellsize,
      // NODATA_value, ...); the values follow.
      std::string       line;
      bool              in_header = true;
      long              values = 0, lines = 0;
      std::vector<long> per_line;
      while (std::getline(file, line))
        {
          std::istringstream tokens(line);
          std::string        token;
          long               count = 0;
          while (tokens >> token)
            {
              if (in_header && count == 0 && std::isalpha(static_cast<unsigned char>(token[0])))
                break;
              in_header = false;
              ++count;
            }
          if (count > 0)
            {
              values += count;
              ++lines;
              if (per_line.size() < 2 && (per_line.empty() || per_line.back() != count))
                per_line.push_back(count);
            }
        }
      if (values == ncols * nrows)
        return;
      std::string layout = std::to_string(lines) + " lines";
      if (per_line.size() == 1)
        layout = std::to_string(lines) + " lines of " + std::to_string(per_line[0])
                 + (lines == nrows && per_line[0] != ncols ?
                      ": is ncols " + std::to_string(per_line[0]) + "?" :
                      "");
      throw InputError(parameter,
                       filename,
                       "an ESRI ASCII grid holding ncols x nrows = " + std::to_string(ncols) + " x "
                         + std::to_string(nrows) + " = " + std::to_string(ncols * nrows)
                         + " values after its header (this one holds " + std::to_string(values)
                         + ", in " + layout + ")");
    }
  } // namespace terrain
} // namespace slidewave
