#ifndef slidewave_depth_averaged_release_h
#define slidewave_depth_averaged_release_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <memory>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/particles/material_region.h>
#include <slidewave/terrain/elevation_grid.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * The released material (subsection "Depth averaged/Release") in the model's
     * coordinates: its areas, the scene's rectangle or polygon or the polygons of a vector
     * file OGR reads (reprojected to the terrain's CRS); and its initial depth, from an
     * expression of the depth or of the surface, a numeric attribute of each polygon, or
     * a raster (the value of the pixel that holds a point, so that the released volume
     * is the raster's whatever the points' spacing), measured vertically or normal to the
     * slope. Everything is read and checked when constructed (an InputError naming the
     * parameter otherwise).
     */
    class Release
    {
    public:
      /** @p model_crs_wkt: the terrain's CRS ("" when it has none). */
      Release(const DepthAveragedParameters &prm,
              const terrain::ElevationGrid  &elevation,
              const std::string             &model_crs_wkt);

      /** The areas; a point belongs to the first that contains it. */
      const std::vector<particles::MaterialRegion> &
      regions() const
      {
        return areas;
      }

      /** The depth h of the release at @p p in area @p region: <= 0 where there is no
       *  material, NaN where the depth raster has no data. */
      double
      depth(const dealii::Point<2> &p, unsigned int region) const;

      /** The initial velocity at @p p. */
      dealii::Tensor<1, 2>
      velocity(const dealii::Point<2> &p) const
      {
        return areas.front().initial_velocity(p);
      }

      /** The parameter the depth comes from ("Depth", "Surface", "Depth raster" or "Depth
       *  attribute") and its value, for messages. */
      std::pair<std::string, std::string>
      depth_source() const;

    private:
      const DepthAveragedParameters         &prm;
      const terrain::ElevationGrid          &elevation;
      std::vector<particles::MaterialRegion> areas;
      /** 'Depth attribute': the value of each area. */
      std::vector<double> area_depth;
      /** 'Depth raster', over the areas' bounding box. */
      std::unique_ptr<terrain::ElevationGrid> depth_raster;
      /** 'Depth' or 'Surface'. */
      std::unique_ptr<dealii::FunctionParser<2>> depth_function;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
