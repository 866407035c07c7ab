#include <slidewave/terrain/raster_terrain.h>

namespace slidewave
{
  namespace terrain
  {
    ElevationGrid
    read_raster_terrain(const std::string      &parameter,
                        const std::string      &filename,
                        const dealii::Point<2> &lower,
                        const dealii::Point<2> &upper,
                        const RasterOptions    &options)
    {
      return RasterSource(parameter, filename, options).window(lower, upper);
    }



    RasterExtent
    raster_extent(const std::string   &parameter,
                  const std::string   &filename,
                  const RasterOptions &options)
    {
      return RasterSource(parameter, filename, options).extent();
    }



    RasterExtent
    raster_footprint(const std::string   &parameter,
                     const std::string   &filename,
                     const RasterOptions &options)
    {
      return RasterSource(parameter, filename, options).footprint();
    }
  } // namespace terrain
} // namespace slidewave
