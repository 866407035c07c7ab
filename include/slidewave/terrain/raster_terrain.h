#ifndef slidewave_terrain_raster_terrain_h
#define slidewave_terrain_raster_terrain_h

#include <deal.II/base/point.h>
#include <slidewave/terrain/elevation_grid.h>
#include <string>

namespace slidewave
{
  namespace terrain
  {
    /** How a raster's coordinates are taken. */
    struct RasterOptions
    {
      /** A raster without a coordinate reference system is refused unless this is set: its
       *  coordinates are then taken as metres. */
      bool assume_metric = false;
      /** The CRS a raster in geographic coordinates (degrees) is reprojected to, as GDAL
       *  reads it ("EPSG:32632", a WKT or PROJ string); empty: the UTM zone of the
       *  raster's centre. */
      std::string target_crs;
    };

    /**
     * The terrain of a raster GDAL reads (GeoTIFF, ESRI ASCII grid, any raster driver):
     * band 1's values at the pixel centres become the nodes of an ElevationGrid (rows
     * flipped so that y grows northwards), in the raster's own metric coordinates, or,
     * for a raster in degrees, after GDAL's warper has reprojected it (bilinear) to a
     * metric CRS. Only the window of pixels that covers [@p lower, @p upper] (the
     * model's domain, in those coordinates) is kept; no-data inside it is refused, never
     * read as an elevation.
     *
     * Every failure is an InputError naming @p parameter, the file and what is wrong: a
     * missing file or one that is not a raster, a rotated raster, no CRS where one is
     * needed, a domain outside the raster, no-data under the domain.
     */
    ElevationGrid
    read_raster_terrain(const std::string      &parameter,
                        const std::string      &filename,
                        const dealii::Point<2> &lower,
                        const dealii::Point<2> &upper,
                        const RasterOptions    &options);

    /** The extent of the raster's pixel centres [lower, upper] in the coordinates
     *  read_raster_terrain() uses (after reprojection), and its CRS as WKT, for messages
     *  and for scenes that take the raster's extent. */
    struct RasterExtent
    {
      dealii::Point<2> lower, upper;
      double           pixel_x = 0., pixel_y = 0.;
      std::string      crs_wkt;
    };

    RasterExtent
    raster_extent(const std::string   &parameter,
                  const std::string   &filename,
                  const RasterOptions &options);
  } // namespace terrain
} // namespace slidewave

#endif
