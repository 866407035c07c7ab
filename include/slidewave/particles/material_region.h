#ifndef slidewave_particles_material_region_h
#define slidewave_particles_material_region_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <memory>
#include <string>
#include <vector>

namespace slidewave
{
  namespace particles
  {
    /**
     * A part of the domain filled with material points of one material at the start:
     * a rectangle or a polygon (with holes, when it comes from a GIS file), the name of
     * its material and its initial velocity. Where regions overlap, the one declared
     * first wins.
     */
    struct MaterialRegion
    {
      /** Largest number of regions a scene may declare ("Region 1" ... ). */
      static constexpr unsigned int max_regions = 4;

      /** Declares the entries of one "Region N" subsection; @p with_material: it names
       *  its material (a model with one material has none); @p with_vector_file: the
       *  shape may also be 'vector file', polygons a GIS file holds ('Vector file',
       *  'Layer'), read by the model that declared it (terrain::read_polygons). */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         bool                      with_material    = true,
                         bool                      with_vector_file = false);

      /**
       * Reads one region (the handler inside its subsection); returns false when the
       * region is unused (Shape = none). @p path names the subsection in errors. With
       * 'Shape = vector file' the polygon stays empty and vector_file names the file.
       */
      bool
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       bool                      with_material = true);

      /** Whether @p p lies inside the region (its boundary and its holes' boundaries
       *  included). */
      bool
      contains(const dealii::Point<2> &p) const;

      /** Bounding box: lower left and upper right corners. */
      std::pair<dealii::Point<2>, dealii::Point<2>>
      bounding_box() const;

      /** 'rectangle', 'polygon' or 'vector file', as given. */
      std::string shape;
      std::string material_name;
      /** Index of the material in MaterialPointParameters::materials (set when parsed). */
      unsigned int material_index = 0;
      /** Initial velocity of a point at @p p. */
      dealii::Tensor<1, 2>
      initial_velocity(const dealii::Point<2> &p) const;

      /** v_x(x, y) and v_y(x, y), muparser expressions. */
      std::shared_ptr<dealii::FunctionParser<2>> velocity_function;
      std::vector<dealii::Point<2>> polygon; ///< counter-clockwise or clockwise, closed implicitly
      /** Rings cut out of the polygon (same convention). */
      std::vector<std::vector<dealii::Point<2>>> holes;
      /** 'Shape = vector file': the file (as written in the scene) and the layer's name
       *  (empty: the first layer); empty otherwise. */
      std::string vector_file, vector_layer;
    };
  } // namespace particles
} // namespace slidewave

#endif
