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

    /**
     * The CRS @p wkt with the metre as its linear unit: for a projected CRS in another unit
     * (US survey feet, e.g. EPSG:2227), the same projection in metres (OGR's
     * SetLinearUnitsAndUpdateParameters: its false easting and northing converted; its
     * EPSG twin, e.g. EPSG:26943, when GDAL finds one), and in @p metres the metres of its
     * unit (OGR's GetLinearUnits), by which its coordinates are multiplied; any other
     * @p wkt (empty, in degrees, already in metres) as it is, with @p metres = 1. The
     * vertical part of a compound CRS is dropped: elevations are values, not coordinates.
     */
    std::string
    in_metres(const std::string &wkt, double &metres);

    /** The name (crs_name()) of the metric twin (in_metres()) of the CRS @p text names
     *  (anything GDAL takes, "EPSG:2227"), for messages: "NAD83 / California zone 3
     *  (EPSG:26943)". */
    std::string
    metric_twin(const std::string &text);
  } // namespace terrain
} // namespace slidewave

#endif
