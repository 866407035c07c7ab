#ifndef slidewave_soil_particle_properties_h
#define slidewave_soil_particle_properties_h

#include <array>
#include <string>

namespace slidewave
{
  namespace soil
  {
    /**
     * The state a material point carries, as indices into its property array. A property
     * is found by name, never by a magic number; `property_names` (same order) names them
     * in the output files.
     */
    namespace property
    {
      enum Index : unsigned int
      {
        mass,           ///< m_p [kg per m of thickness]
        volume,         ///< current V_p [m^2]
        initial_volume, ///< V_p at t = 0 [m^2]
        velocity_x,     ///< v_p [m/s]
        velocity_y,
        stress_xx, ///< Cauchy stress, tension positive [Pa]
        stress_yy,
        stress_xy,
        stress_zz,                 ///< out of plane (plane strain)
        equivalent_plastic_strain, ///< accumulated, dimensionless
        initial_x,                 ///< position at t = 0 [m]
        initial_y,
        material_id,   ///< index of the material (stored as a double)
        domain_half_x, ///< GIMP: half-lengths of the point's domain [m]
        domain_half_y,
        n_properties
      };

      /**
       * Optional: the point force on a material point [N per m of thickness], added to
       * the nodal forces of every particle-to-grid transfer (paper 000, Eq. 15: the
       * tractions of the water on the surface points). Stored only when a scene applies
       * surface loads (MaterialPointParameters::point_forces); other scenes neither allocate nor
       * scatter it.
       */
      constexpr unsigned int point_force_x                  = n_properties;
      constexpr unsigned int point_force_y                  = n_properties + 1;
      constexpr unsigned int n_properties_with_point_forces = n_properties + 2;
    } // namespace property

    inline const std::array<std::string, property::n_properties> &
    property_names()
    {
      static const std::array<std::string, property::n_properties> names{
        {"mass",
         "volume",
         "initial_volume",
         "velocity_x",
         "velocity_y",
         "stress_xx",
         "stress_yy",
         "stress_xy",
         "stress_zz",
         "equivalent_plastic_strain",
         "initial_x",
         "initial_y",
         "material_id",
         "domain_half_x",
         "domain_half_y"}};
      return names;
    }
  } // namespace soil
} // namespace slidewave

#endif
