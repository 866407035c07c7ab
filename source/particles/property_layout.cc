#include <deal.II/base/exceptions.h>
#include <slidewave/particles/property_layout.h>

namespace slidewave
{
  namespace particles
  {
    void
    PropertyLayout::add_scalar(const std::string &name)
    {
      properties.push_back({name, "", false});
    }



    void
    PropertyLayout::add_vector(const std::string              &vector_name,
                               const std::vector<std::string> &component_names)
    {
      for (const auto &component : component_names)
        properties.push_back({component, vector_name, false});
    }



    void
    PropertyLayout::add_load(const std::string              &vector_name,
                             const std::vector<std::string> &component_names)
    {
      for (const auto &component : component_names)
        properties.push_back({component, vector_name, true});
    }



    bool
    PropertyLayout::has(const std::string &name) const
    {
      for (const auto &property : properties)
        if (property.name == name)
          return true;
      return false;
    }



    unsigned int
    PropertyLayout::index(const std::string &name) const
    {
      for (unsigned int i = 0; i < properties.size(); ++i)
        if (properties[i].name == name)
          return i;
      AssertThrow(false, dealii::ExcMessage("no particle property named '" + name + "'"));
      return 0;
    }



    std::vector<std::string>
    PropertyLayout::output_names() const
    {
      std::vector<std::string> names;
      for (const auto &property : properties)
        names.push_back(property.vector.empty() ? property.name : property.vector);
      return names;
    }



    std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
    PropertyLayout::output_interpretation() const
    {
      std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation> result;
      for (const auto &property : properties)
        result.push_back(property.vector.empty() ?
                           dealii::DataComponentInterpretation::component_is_scalar :
                           dealii::DataComponentInterpretation::component_is_part_of_vector);
      return result;
    }
  } // namespace particles
} // namespace slidewave
