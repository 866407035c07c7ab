#ifndef slidewave_terrain_raster_source_h
#define slidewave_terrain_raster_source_h

#include <deal.II/base/point.h>
#include <limits>
#include <slidewave/terrain/earth_bounds.h>
#include <slidewave/terrain/elevation_grid.h>
#include <slidewave/terrain/raster_checks.h>
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
      /** The values accepted, in metres after the band's scale, offset and unit: by
       *  default the elevations the Earth has; a value outside is refused, naming its
       *  pixel (a 1e300 or an undeclared no-data value of -3.4e38 is not a terrain). */
      double lowest_value = lowest_elevation, highest_value = highest_elevation;
      /** What is allowed, in messages. */
      std::string values_allowed = elevation_bounds_text();
    };

    /** A block of a raster's pixel centres [lower, upper] in the coordinates the model
     *  uses (after reprojection), its pixel sizes [m] and its CRS as WKT ("" for a raster
     *  without one), for messages and for scenes that take their grid from the raster. */
    struct RasterExtent
    {
      dealii::Point<2> lower, upper;
      double           pixel_x = 0., pixel_y = 0.;
      std::string      crs_wkt;
    };

    /**
     * A raster GDAL reads (GeoTIFF, ESRI ASCII grid, any raster driver), opened once and,
     * when it must be reprojected (a raster in degrees, or one not in
     * RasterOptions::match_crs), warped once by GDAL's warper into an in-memory dataset
     * that is kept while the object lives. Everything a scene asks of its raster is read
     * from that one dataset: the extent and CRS the model uses (extent()), the footprint
     * of its data (footprint()) and the values under the domain (window()). The warp of a
     * large DEM costs seconds; before this class each of these questions opened and
     * warped the file anew (issue 25).
     *
     * Band 1 is read at the pixel centres, north-up (a rotated or sheared raster is
     * refused), in the raster's own metric coordinates or, for a raster in degrees, in
     * the UTM zone of its centre or RasterOptions::target_crs after a reprojection
     * (RasterOptions::resampling) onto pixels no larger than the source's smaller side in
     * metres.
     *
     * A projected CRS in another unit than the metre (US survey feet) is read in the same
     * projection in metres (the geotransform scaled by the unit, crs.h in_metres()); band 1's
     * values are taken through its scale, offset and vertical unit (band_to_metres()).
     *
     * Every failure is an InputError naming the parameter the raster was given by, the
     * file and what is wrong: a missing file or one that is not a raster, an ESRI ASCII
     * grid whose count of values is not ncols x nrows, a rotated or degenerate
     * geotransform, a band scale or offset that is not finite, a vertical unit we do not
     * know, no CRS where one is needed, a raster in degrees whose coordinates are not
     * degrees, a warp GDAL refuses (on construction); a window outside the raster, no-data
     * under it, a value outside RasterOptions' bounds, no data at all (when asked).
     */
    class RasterSource
    {
    public:
      /** Opens @p filename (and warps it if it must be reprojected); @p parameter names it
       *  in every error, now and later. */
      RasterSource(const std::string   &parameter,
                   const std::string   &filename,
                   const RasterOptions &options);

      /** Closes the file and frees the warped copy. */
      ~RasterSource();

      RasterSource(const RasterSource &) = delete;
      RasterSource &
      operator=(const RasterSource &)
        = delete;

      /** The extent of all the pixel centres, the pixel sizes and the CRS the model uses
       *  (for a reprojected raster, the bounding box of the warp, the wedges of no-data at
       *  its corners included). */
      RasterExtent
      extent() const;

      /**
       * The largest rectangle of pixel centres under which the raster holds data (its
       * lower and upper corners; pixel sizes and CRS as extent()): the whole extent of a
       * raster without no-data; for one reprojected from degrees, the part inside the
       * wedges of no-data the warp leaves at its corners. Each row's data are taken from
       * its first to its last valid pixel in GDAL's mask (holes inside a row are not looked
       * for: window() refuses them under a domain).
       */
      RasterExtent
      footprint() const;

      /**
       * Band 1 (with its scale and offset) over the smallest block of pixels whose
       * centres cover [@p lower, @p upper] (the model's domain, in the coordinates of
       * extent()), as an ElevationGrid with its nodes at those centres (rows flipped so
       * that y grows northwards). No-data inside the block is refused, never read as a
       * value, unless RasterOptions::nodata_as_nan.
       */
      ElevationGrid
      window(const dealii::Point<2> &lower, const dealii::Point<2> &upper) const;

      /** How many rasters RasterSource has opened in this process, and how many of them it
       *  has warped, since the program started: for the tests that check that a scene
       *  reads each raster once. */
      static unsigned int
      n_opened();

      /** The pixels of the file, as its header declares them (width x height). */
      double
      pixel_count() const;

      static unsigned int
      n_warped();

    private:
      /** Opens the file (GDAL's own diagnosis silenced; ESRI ASCII grids read as doubles)
       *  into source; refuses a file that is not a raster or has no band. */
      void
      open();

      /** The geotransform of the file into @p gt; refuses a raster without one, a
       *  rotated or sheared raster and a degenerate one (check_geotransform()). */
      void
      read_geotransform(double gt[6]) const;

      /** Warps the file with GDAL's warper into the in-memory dataset warped: in the CRS
       *  @p target_wkt, onto square pixels of side @p resolution, no-data outside the
       *  source; refuses a raster the warper refuses. */
      void
      warp(const std::string &target_wkt, double resolution);

      /** The extent of the centres of the pixels [@p c0, @p c1] x [@p r0, @p r1]
       *  (columns, rows), the pixel sizes and the CRS. */
      RasterExtent
      pixel_block(int c0, int c1, int r0, int r1) const;

      /** What is read: the warped copy if there is one, else the file (a GDALDatasetH). */
      void *
      dataset() const
      {
        return warped != nullptr ? warped : source;
      }

      std::string   parameter, filename;
      RasterOptions options;
      /** The file and its warped copy (GDALDatasetH, which GDAL's C API defines as void *:
       *  GDAL's headers, and their macros, stay out of the files that include this one). */
      void *source = nullptr, *warped = nullptr;
      /** The geotransform of dataset(), in metres (a raster in a projected CRS in feet is
       *  read in the same projection in metres: its geotransform scaled, not warped). */
      double transform[6] = {0., 1., 0., 0., 0., -1.};
      /** The CRS (WKT) of the coordinates of transform, "" for none. */
      std::string model_wkt;
      /** From band 1's values to metres: its scale, offset and vertical unit. */
      BandToMetres to_metres;
    };
  } // namespace terrain
} // namespace slidewave

#endif
