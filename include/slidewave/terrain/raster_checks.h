#ifndef slidewave_terrain_raster_checks_h
#define slidewave_terrain_raster_checks_h

#include <string>

namespace slidewave
{
  namespace terrain
  {
    /**
     * @name What a raster file must be before its values are used
     * The checks RasterSource makes of what GDAL reads from a file (issue 29: each of these
     * used to crash, or run on wrong values without a word). Each refusal is an InputError
     * naming @p parameter, the file and what is wrong. The GDAL handles are passed as the
     * void pointers GDAL's C API defines them as.
     * @{
     */

    /** Refuses a geotransform @p gt with a coefficient that is not finite (a NaN origin), a
     *  rotated or sheared one, a pixel width not > 0 or a pixel height of 0. */
    void
    check_geotransform(const std::string &parameter,
                       const std::string &filename,
                       const double       gt[6]);

    /** How a band's stored values v become elevations in metres: (scale v + offset) times
     *  the metres of its vertical unit. */
    struct BandToMetres
    {
      double scale = 1., offset = 0.;
      /** The vertical unit, for messages ("metre" when none is declared). */
      std::string unit = "metre";

      double
      operator()(const double v) const
      {
        return scale * v + offset;
      }
    };

    /**
     * The map of band 1 of @p dataset (a GDALDatasetH, the file as opened, before any warp)
     * to metres: GDAL's scale and offset of the band (1 and 0 when it has none), which must be
     * finite and the scale not 0; times the metres of the band's unit (GDALGetRasterUnitType:
     * metre, foot or US survey foot; any other unit is refused) or, when it declares none, of
     * the vertical part of a compound CRS @p crs (an OGRSpatialReferenceH, may be null); else
     * metres are assumed: a horizontal CRS says nothing of z.
     */
    BandToMetres
    band_to_metres(const std::string &parameter,
                   const std::string &filename,
                   void              *dataset,
                   void              *crs);

    /** For an ESRI ASCII grid (GDAL's AAIGrid driver): refuses a file that does not hold
     *  ncols x nrows values after its header. GDAL reads the values as one stream, so a
     *  file with more (ncols too small) is read shifted row by row without a word, and one
     *  with fewer fails only when the missing rows are read. */
    void
    check_ascii_grid(const std::string &parameter, const std::string &filename, void *dataset);

    /** @} */
  } // namespace terrain
} // namespace slidewave

#endif
