#ifndef slidewave_terrain_crs_h
#define slidewave_terrain_crs_h

#include <string>

namespace slidewave
{
  namespace terrain
  {
    /**
     * The WKT of the projected (metric) coordinate reference system @p text names, as GDAL
     * reads it ("EPSG:32616", a WKT or a PROJ string); "" for an empty @p text. A CRS GDAL
     * does not know, or one in degrees, is refused with an InputError naming @p parameter.
     */
    std::string
    projected_crs_wkt(const std::string &parameter, const std::string &text);

    /** A short name of the CRS in @p wkt for messages: its name and, when GDAL finds one,
     *  its EPSG code ("WGS 84 / UTM zone 16N (EPSG:32616)"); "none" for an empty @p wkt. */
    std::string
    crs_name(const std::string &wkt);

    /** Whether @p a and @p b are the same CRS (both empty counts as the same). */
    bool
    same_crs(const std::string &a, const std::string &b);
  } // namespace terrain
} // namespace slidewave

#endif
