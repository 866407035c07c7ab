#ifndef slidewave_soil_soil_model_h
#define slidewave_soil_soil_model_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <optional>
#include <slidewave/engine/particle_model_defaults.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/materials/material.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/particles/property_layout.h>
#include <slidewave/soil/finite_strain_points.h>
#include <slidewave/soil/material_point_parameters.h>
#include <slidewave/soil/particle_properties.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace soil
  {
    /**
     * The soil of paper 000 as a particle model of the material point method in 2D plane
     * strain: what its points carry (property::Index, and the point forces of the
     * coupling when switched on), what they scatter to the grid (the internal force of
     * their stress, Eq. 16, gravity and the point force, Eq. 15), their constitutive
     * update (strain increment with the optional B-bar mean dilatation, the Jaumann rate,
     * Eqs. 5–6, and the material's elastic or Drucker–Prager update, materials/; or, for
     * the finite-strain materials, the Hencky update of FiniteStrainPoints), the
     * P-wave speed of the time step (Eqs. 22–23), their initial state and initial stress
     * (geostatic with K0, uniform; the end of gravity loading), and the soil's
     * diagnostics (energies, integrals and runout, the guards' description of a bad
     * point). The transfer kernels (TransferKernels<SoilModel>) are instantiated in its
     * source.
     */
    class SoilModel : public engine::ParticleModelDefaults
    {
    public:
      /** The properties the transfer kernels read (TransferKernels). */
      static constexpr unsigned int mass          = property::mass;
      static constexpr unsigned int volume        = property::volume;
      static constexpr unsigned int velocity_x    = property::velocity_x;
      static constexpr unsigned int velocity_y    = property::velocity_y;
      static constexpr unsigned int domain_half_x = property::domain_half_x;
      static constexpr unsigned int domain_half_y = property::domain_half_y;

      /** Cundall's local damping of the unbalanced nodal force (TransferKernels): a
       *  force opposing the motion, proportional to the unbalanced force. */
      double
      nodal_force_at_node(const double v, double f) const
      {
        if (damping > 0.)
          f -= damping * std::abs(f) * (v > 0. ? 1. : v < 0. ? -1. : 0.);
        return f;
      }

      /** The local damping coefficient in force now ('Local damping', heavier during
       *  gravity loading). */
      void
      set_damping(const double alpha)
      {
        damping = alpha;
      }

      using ParticleRange = dealii::Particles::ParticleHandler<2>::particle_iterator_range;

      /** @p grain_density: rho^s of the grains where the points are a porous skeleton
       *  (granular::PorousSkeletonModel), which a critical-state dilatancy needs to know
       *  a point's porosity n = 1 - m_p / (rho^s V_p); 0 for a soil without one, which
       *  refuses such a material (InputError). @p suspension_porosity: n_s, above which
       *  the grains of a cell's points lose contact (release_stress; 1, or no grain
       *  density: never). */
      explicit SoilModel(const MaterialPointParameters &parameters,
                         double                         grain_density       = 0.,
                         double                         suspension_porosity = 1.);

      /** The points' properties: property::Index, then the point forces if on, then b^e
       *  (FiniteStrainPoints) if some material is a finite-strain one. */
      const particles::PropertyLayout &
      layout() const
      {
        return property_layout;
      }

      /** What a point scatters, read once per point (Eqs. 14–17). */
      struct ScatterTerms
      {
        double m, vx, vy, V, sxx, syy, sxy, fx, fy;
        /** Gravity, a copy per point: held in registers over the point's nodes (the
         *  model's member could alias the nodal sums the loop writes). */
        double gx, gy;
      };

      template <typename Properties>
      ScatterTerms
      scatter_terms(const Properties &p, const dealii::Point<2> & /*location*/) const
      {
        return {p[property::mass],
                p[property::velocity_x],
                p[property::velocity_y],
                p[property::volume],
                p[property::stress_xx],
                p[property::stress_yy],
                p[property::stress_xy],
                point_forces ? p[property::point_force_x] : 0.,
                point_forces ? p[property::point_force_y] : 0.,
                gravity[0],
                gravity[1]};
      }

      /** The point's force on its k-th node, with @p mk = S_k m: the internal force
       *  -V sigma grad S (Eq. 16) plus gravity and the point force (Eq. 15). */
      void
      nodal_force(const ScatterTerms      &t,
                  const grid::NodeWeights &w,
                  const unsigned int       k,
                  const double             mk,
                  double                  &fx,
                  double                  &fy) const
      {
        fx = -t.V * (t.sxx * w.grad_x[k] + t.sxy * w.grad_y[k]) + mk * t.gx + w.value[k] * t.fx;
        fy = -t.V * (t.sxy * w.grad_x[k] + t.syy * w.grad_y[k]) + mk * t.gy + w.value[k] * t.fy;
      }

      /**
       * The stresses of the points of one cell from their velocity gradients @p L (in the
       * order of @p particles_in_cell): strain and spin increments, B-bar, the material's
       * update with the Jaumann rate (Eqs. 5–6), the new volume, cpGIMP's domain; the
       * points of finite-strain materials by FiniteStrainPoints::update() instead (the
       * same B-bar mean, as F-bar). Then, where the cell's points together are looser
       * than the suspension porosity n_s (their mass over their volume below the contact
       * density (1 - n_s) rho^s), they are released (release_stress); compacted below n_s
       * again, they take stress from zero at the contact (regain_contact).
       */
      void
      update_cell(const ParticleRange        &particles_in_cell,
                  const dealii::Tensor<2, 2> *L,
                  double                      dt) const;

      /** A point whose grains have lost contact (its cell's n > n_s): no stress, and a
       *  finite-strain point's elastic strain b^e reset to the identity with it, so that
       *  it takes stress from zero when its grains touch again. */
      void
      release_stress(dealii::ArrayView<double> p) const;

      /** A point of a cell released at the start of the step (zero stress) whose grains
       *  touch again by its end: its stress scaled by @p fraction, the part of the step's
       *  compaction past the contact (a whole step's compaction taken as elastic would load
       *  it by up to M v dt / h). */
      void
      regain_contact(dealii::ArrayView<double> p, double fraction) const;

      /**
       * The P-wave speed sqrt((K + 4G/3) / rho) of the point's material (Eq. 22), at its
       * density but not below the contact density (1 - n_s) rho^s (0 without a porous
       * skeleton). A dilated point may sit in a cell in contact, or its cell may regain
       * contact within a step: it keeps the step of the stiffness it may have, and a point
       * dilated far from the mass does not shorten the step as its density falls.
       */
      template <typename Properties>
      double
      wave_speed(const Properties &p) const
      {
        const double density = p[property::mass] / p[property::volume];
        return std::sqrt(
          materials[static_cast<unsigned int>(p[property::material_id])].p_wave_modulus()
          / (contact_density > 0. ? std::max(density, contact_density) : density));
      }

      /** Nodes with less mass than this are empty. */
      double
      empty_node_mass() const;

      /** The initial properties of a point of region @p region_index in a cell hx x hy. */
      void
      fill_new_point(std::vector<double>    &properties,
                     const dealii::Point<2> &position,
                     unsigned int            region_index,
                     double                  hx,
                     double                  hy) const;

      /** 'uniform': the given stress in every point. */
      void
      set_uniform_stress(particles::PointCloud &cloud) const;

      /**
       * 'geostatic': sigma_v from the weight of the material above, sigma_h = K0 sigma_v.
       * With @p buoyancy, the effective stress of grains in a fluid: each point weighs
       * m g (1 - buoyancy(x)), buoyancy(x) = rho^f(x) / rho^s the share of its grains'
       * weight the fluid at x carries (the pore fluid's own weight is its pressure's).
       */
      void
      set_geostatic_stress(particles::PointCloud                                 &cloud,
                           const std::function<double(const dealii::Point<2> &)> &buoyancy
                           = {}) const;

      /** The end of gravity loading: the points at rest where they are now. */
      void
      finish_gravity_loading(particles::PointCloud &cloud) const;

      /** Sets the point forces from @p force(particle) (needs point forces). */
      void
      set_point_forces(
        particles::PointCloud &cloud,
        const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
          &force) const;

      /** The sum of the point forces over all points (collective). */
      dealii::Tensor<1, 2>
      total_point_force(const particles::PointCloud &cloud) const;

      /** Integral quantities, reduced over all ranks (collective). */
      struct Integrals
      {
        double       mass = 0., momentum_x = 0., momentum_y = 0., kinetic_energy = 0.;
        double       max_speed = 0., runout = 0., max_height = 0.;
        double       lost_mass   = 0.;
        unsigned int n_particles = 0;
      };

      Integrals
      integrals(const particles::PointCloud &cloud) const;

      /**
       * Energies per unit thickness [J/m], reduced over all ranks (collective): kinetic,
       * elastic (p^2/(2K) + s:s/(4G) per unit volume) and the work done by gravity since
       * the start, sum m g.(x - x_0).
       */
      struct EnergyBudget
      {
        double kinetic = 0., elastic = 0., gravity_work = 0.;
      };

      EnergyBudget
      energy_budget(const particles::PointCloud &cloud) const;

      /** "material point ID at (x y) with speed S m/s" for the fastest point (collective). */
      std::string
      describe_fastest_particle(const particles::PointCloud &cloud) const;

      /**
       * Checks the points for non-finite state and non-positive volumes; returns a
       * description of the first bad one on any rank, or "" (collective).
       */
      std::string
      find_invalid_particle(const particles::PointCloud &cloud) const;

    private:
      /** One small-strain point: strain increment (B-bar with the cell's mean
       *  @p mean_volumetric of tr L), Jaumann rate, the material's update, the volume. */
      void
      update_small_strain(dealii::ArrayView<double>   p,
                          const dealii::Tensor<2, 2> &L,
                          double                      dt,
                          double                      mean_volumetric) const;

      /** The dilatancy coefficient of point @p p's porosity at the start of the step
       *  ('Dilatancy law = critical state'; Material::dilatancy_coefficient), NaN when
       *  its material's dilatancy is the fixed angle's. */
      double
      state_dilatancy_coefficient(const dealii::ArrayView<double> &p) const;

      const MaterialPointParameters   &prm;
      std::vector<materials::Material> materials;
      /** rho^s of the grains (0: unknown; the constructor's @p grain_density). */
      double solid_density;
      /** (1 - n_s) rho^s: where a cell's points together are lighter, their grains are
       *  out of contact (0: never). */
      double                    contact_density;
      particles::PropertyLayout property_layout;
      /** The finite-strain points' update and b^e; only when a material needs it. */
      std::optional<FiniteStrainPoints> finite_strain;
      /** APIC: the index of the affine matrix's first property (invalid: FLIP); the
       *  engine's kernels find the same index in the layout (engine::affine_index). */
      unsigned int               affine_first = dealii::numbers::invalid_unsigned_int;
      const dealii::Tensor<1, 2> gravity;
      const bool                 point_forces;
      /** Cundall's local damping in force now. */
      double damping;
    };
  } // namespace soil
} // namespace slidewave

#endif
