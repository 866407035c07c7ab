#ifndef slidewave_terrain_raster_terrain_h
#define slidewave_terrain_raster_terrain_h

#include <deal.II/base/point.h>
#include <slidewave/terrain/elevation_grid.h>
#include <slidewave/terrain/raster_source.h>
#include <string>

namespace slidewave
{
  namespace terrain
  {
    /**
     * @name One question to a raster, in one call
     * Each of these opens the file as a RasterSource (warping it if it must be
     * reprojected), asks it and closes it. A caller with more than one question to the
     * same raster (a scene: its CRS, its footprint, its elevations) opens one RasterSource
     * and asks it each, so that a large DEM is read and warped once.
     * @{
     */

    /**
     * The terrain of a raster GDAL reads: RasterSource::window() over [@p lower,
     * @p upper] (the model's domain, in the coordinates the model uses). Every failure
     * is an InputError naming @p parameter, the file and what is wrong: a missing file or
     * one that is not a raster, a rotated raster, no CRS where one is needed, a domain
     * outside the raster, no-data under the domain (unless RasterOptions::nodata_as_nan).
     */
    ElevationGrid
    read_raster_terrain(const std::string      &parameter,
                        const std::string      &filename,
                        const dealii::Point<2> &lower,
                        const dealii::Point<2> &upper,
                        const RasterOptions    &options);

    /** The extent of the raster's pixel centres and its CRS: RasterSource::extent(). */
    RasterExtent
    raster_extent(const std::string   &parameter,
                  const std::string   &filename,
                  const RasterOptions &options);

    /** The largest rectangle of pixel centres under which the raster holds data:
     *  RasterSource::footprint(). */
    RasterExtent
    raster_footprint(const std::string   &parameter,
                     const std::string   &filename,
                     const RasterOptions &options);

    /** @} */
  } // namespace terrain
} // namespace slidewave

#endif
