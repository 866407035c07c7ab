#ifndef slidewave_granular_porous_skeleton_model_h
#define slidewave_granular_porous_skeleton_model_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/point.h>
#include <slidewave/granular/drag_law.h>
#include <slidewave/granular/granular_water_parameters.h>
#include <slidewave/soil/soil_model.h>

namespace slidewave
{
  namespace granular
  {
    /**
     * The solid skeleton of a saturated (or dry) granular mass as a particle model of the
     * engine (paper 002, §2 and §3.5): the soil's points (SoilModel: effective stress,
     * constitutive update, volume from the deformation) with what the pore fluid needs of
     * them. A point's mass is its grains' mass m_p = (1 - n_p) rho^s V_p, so its solid
     * volume m_p / rho^s is fixed and its porosity follows its volume,
     * n_p = 1 - m_p / (rho^s V_p) (paper 002, the porosity update of §3.5 with J = V / V_0),
     * capped at 0.99. Its permeability k_p is the given constant or Kozeny–Carman's of
     * n_p (DragLaw, Eq. 4) and its Darcy drag coefficient C_p = n_p^2 mu^f / k_p.
     *
     * Two nodal fields of its own, summed like the mass:
     *   field 0, the solid volume  S_I = sum_p N_I(x_p) m_p / rho^s,
     *   field 1, the drag          D_I = sum_p N_I(x_p) V_p C_p       [kg/s per m],
     * from which SkeletonFluidExchange makes the fluid's fields: the fluid fraction
     * n_I = 1 - S_I / A_I (A_I the node's lumped area) and the drag C_I = D_I / A_I.
     * With the semi-implicit drag coupling, a third field that the points do not sum: the
     * water's drag at the nodes, W_I = integral of N_I C (the same C and quadrature as the
     * water's), which the exchange writes before the grid update, where each node's
     * velocity takes the drag of the new step implicitly, v_I = v_I^trial m_I / (m_I + dt
     * W_I) (update_nodal_velocity; the water's force then holds -(1 - n) grad p + C u, not
     * the - C v_s). With the Forchheimer drag (Eq. 3), a fourth field the points read: the
     * relative speed |u - v_s| of the water's last step at the nodes, which the exchange
     * writes and each point gathers into its property 'relative_speed' for the next
     * step's C_p.
     */
    class PorousSkeletonModel : public soil::SoilModel
    {
    public:
      static constexpr unsigned int n_nodal_fields = 4;
      static constexpr unsigned int solid_volume   = 0;
      static constexpr unsigned int drag           = 1;
      static constexpr unsigned int water_drag     = 2;
      static constexpr unsigned int relative_speed = 3;

      PorousSkeletonModel(const soil::MaterialPointParameters &soil_parameters,
                          const GranularWaterParameters       &parameters,
                          double                               fluid_density,
                          double                               fluid_viscosity);

      /** The water's drag only with the semi-implicit coupling, the relative speed only
       *  with the Forchheimer drag. */
      unsigned int
      n_used_nodal_fields() const
      {
        return parameters.forchheimer ? 4 : parameters.implicit_drag ? 3 : 2;
      }

      /** The water's drag of the new step, implicit at node @p i of mass @p m (the
       *  semi-implicit coupling): scales the velocity, so a held component stays zero. */
      void
      update_nodal_velocity(const grid::NodalWorkspace &nodes,
                            const unsigned int          i,
                            const double                m,
                            const double                dt,
                            double                     &vx,
                            double                     &vy) const
      {
        if (!parameters.implicit_drag)
          return;
        const double scale = m / (m + dt * nodes.fields[water_drag].local_element(i));
        vx *= scale;
        vy *= scale;
      }

      /** The soil's properties, and 'relative_speed' with the Forchheimer drag. */
      const particles::PropertyLayout &
      layout() const
      {
        return porous_layout;
      }

      bool
      needs_lumped_area() const
      {
        return true;
      }

      /** What a point scatters: the soil's terms, its solid volume and V_p C_p. */
      struct ScatterTerms : soil::SoilModel::ScatterTerms
      {
        double solid_volume, drag_volume;
      };

      template <typename Properties>
      ScatterTerms
      scatter_terms(const Properties &p, const dealii::Point<2> &location) const
      {
        const soil::SoilModel::ScatterTerms soil  = soil::SoilModel::scatter_terms(p, location);
        const double                        solid = soil.m / grain_density;
        const double                        n     = porosity(solid, soil.V);
        return {soil,
                solid,
                soil.V * drag_coefficient(n, parameters.forchheimer ? p[speed_index] : 0.)};
      }

      template <typename Terms>
      void
      scatter_fields(const Terms &t, const double N_k, double *sums) const
      {
        sums[solid_volume] += N_k * t.solid_volume;
        sums[drag] += N_k * t.drag_volume;
      }

      /** The relative speed of the water's last step at the point (Forchheimer). */
      template <typename Properties>
      void
      gather_fields(const grid::NodeWeights    &w,
                    const grid::NodalWorkspace &nodes,
                    Properties                 &p,
                    bool /*before_update*/) const
      {
        if (!parameters.forchheimer)
          return;
        const auto &speed = nodes.fields[relative_speed];
        double      value = 0.;
        for (unsigned int k = 0; k < w.n; ++k)
          value += w.value[k] * speed.local_element(w.node[k]);
        p[speed_index] = value;
      }

      /** n = 1 - solid volume / volume, in [0, 0.99]. */
      static double
      porosity(const double solid, const double volume)
      {
        return std::clamp(1. - solid / volume, 0., DragLaw::porosity_cap);
      }

      /** The drag coefficient [kg/(m^3 s)] at porosity @p n and relative speed
       *  @p speed: Darcy's n^2 mu^w / k(n), plus Forchheimer's term (DragLaw) when on. */
      double
      drag_coefficient(const double n, const double speed) const
      {
        if (n <= 0.)
          return 0.; // no pores, no flow through them
        const double k = parameters.permeability_law == PermeabilityLaw::constant ?
                           parameters.permeability :
                           law.permeability(n);
        return parameters.forchheimer ? law.drag_coefficient(n, k, speed) : n * n * viscosity / k;
      }

      /**
       * The smallest rho^s (1 - n) n^2 / C = rho^s (1 - n) k / mu^w of the points
       * (collective). The pore pressure of the new step answers the skeleton's velocity of
       * the old one: where the drag dominates the water's inertia, the water's continuity
       * makes p = (C / n^2) Laplace^-1 div v_s, and its force on the grains,
       * -(1 - n) grad p + C (u - v_s) = -grad p, acts on them as a volumetric damping of
       * coefficient C / n^2 = mu / k, explicit: stable for steps below twice this time.
       * (The drag alone, C (u - v_s), is stable below 2 rho^s (1 - n) / C, a larger
       * bound.)
       */
      double
      coupling_time_scale(const particles::PointCloud &cloud) const;

    private:
      const GranularWaterParameters &parameters;
      const double                   grain_density, viscosity;
      const DragLaw                  law;
      particles::PropertyLayout      porous_layout;
      /** The index of 'relative_speed' among the points' properties. */
      unsigned int speed_index;
    };
  } // namespace granular

  extern template class engine::TransferKernels<granular::PorousSkeletonModel>;
  extern template class engine::ParticleEngine<granular::PorousSkeletonModel>;
} // namespace slidewave

#endif
