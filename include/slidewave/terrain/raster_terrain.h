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
      /** The CRS (WKT) the raster must be in, whatever it is: a raster in another CRS is
       *  reprojected to it (a second raster over a terrain, e.g. a release thickness);
       *  empty: only rasters in degrees are reprojected, as above. */
      std::string match_crs;
      /** GDAL's resampling when reprojecting: "bilinear" (elevations) or "near" (values
       *  that hold for a whole pixel, e.g. a thickness). */
      std::string resampling = "bilinear";
      /** No-data pixels are read as NaN instead of refused (the caller decides where
       *  they matter). */
      bool nodata_as_nan = false;
      /** What the window read is, in messages. */
      std::string window_name = "the domain";
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
     * needed, a domain outside the raster, no-data under the domain (unless
     * RasterOptions::nodata_as_nan).
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

    /**
     * The largest rectangle of pixel centres under which the raster holds data, in the
     * coordinates read_raster_terrain() uses (its lower and upper corners; pixel sizes and
     * CRS as raster_extent()): the whole extent of a raster without no-data; for one
     * reprojected from degrees, the part inside the wedges of no-data the warp leaves at
     * its corners. Each row's data are taken from its first to its last valid pixel (holes
     * inside a row are not looked for: read_raster_terrain() refuses them under a domain).
     */
    RasterExtent
    raster_footprint(const std::string   &parameter,
                     const std::string   &filename,
                     const RasterOptions &options);
  } // namespace terrain
} // namespace slidewave

#endif
