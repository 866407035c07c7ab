#ifndef slidewave_particles_property_layout_h
#define slidewave_particles_property_layout_h

#include <deal.II/numerics/data_component_interpretation.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace particles
  {
    /**
     * What a particle model's points carry: the properties in the order of their indices
     * in the property array, each with its name, whether it is a component of a vector
     * (and of which: "velocity" for velocity_x, velocity_y) and whether it is a load set
     * from outside (the point forces of the coupling) rather than state. Each model
     * describes its layout once (its index enum gives the same positions); the particle
     * output, the checkpoints (the number of properties) and the guards read it instead of
     * knowing any model's properties.
     */
    class PropertyLayout
    {
    public:
      /** Appends a scalar property. */
      void
      add_scalar(const std::string &name);

      /** Appends the components @p component_names of the vector @p vector_name. */
      void
      add_vector(const std::string &vector_name, const std::vector<std::string> &component_names);

      /** Appends a load set from outside (not checked by the guards), as a vector. */
      void
      add_load(const std::string &vector_name, const std::vector<std::string> &component_names);

      /** The number of properties of a point. */
      unsigned int
      size() const
      {
        return properties.size();
      }

      /** Whether a property named @p name exists. */
      bool
      has(const std::string &name) const;

      /** The index of the property @p name (it must exist). */
      unsigned int
      index(const std::string &name) const;

      const std::string &
      name(const unsigned int i) const
      {
        return properties[i].name;
      }

      /** Whether property @p i is state the guards check (not a load). */
      bool
      is_state(const unsigned int i) const
      {
        return !properties[i].load;
      }

      /** The names of the output: each property's, a vector's components the vector's. */
      std::vector<std::string>
      output_names() const;

      /** Scalar or part of a vector, per property (in the order of output_names()). */
      std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
      output_interpretation() const;

    private:
      struct Property
      {
        std::string name;
        /** The vector it is a component of, or empty. */
        std::string vector;
        bool        load = false;
      };
      std::vector<Property> properties;
    };
  } // namespace particles
} // namespace slidewave

#endif
