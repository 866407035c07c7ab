#ifndef slidewave_depth_averaged_map_files_h
#define slidewave_depth_averaged_map_files_h

#include <functional>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * The GDAL files of the hazard maps: a map as a GeoTIFF and an area as GeoJSON
     * outlines. Rows are numbered from the south (j = 0) as the maps store them; the files
     * go from north to south.
     */
    namespace map_files
    {
      /** No-data value of the GeoTIFFs (an arrival time where the flow never came). */
      constexpr double no_data = -9999.;

      /** Writes a GeoTIFF of @p width x @p height pixels (Float64, no-data no_data) with
       *  the geotransform @p transform and the CRS @p crs_wkt ("" for none); @p row(j, out)
       *  gives the @p width values of row j. Throws OutputFailure naming @p path if GDAL
       *  fails. */
      void
      write_geotiff(const std::string                                 &path,
                    const std::function<void(unsigned int, double *)> &row,
                    unsigned int                                       width,
                    unsigned int                                       height,
                    const double                                      *transform,
                    const std::string                                 &crs_wkt);

      /** The outline of the pixels where @p inside (row j at [j * width, (j + 1) * width))
       *  is true, as GeoJSON polygons (GDAL's polygonize). */
      void
      write_outline(const std::string       &path,
                    const std::vector<char> &inside,
                    unsigned int             width,
                    unsigned int             height,
                    const double            *transform,
                    const std::string       &crs_wkt);
    } // namespace map_files
  }   // namespace depth_averaged
} // namespace slidewave

#endif
