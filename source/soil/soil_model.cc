#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/rank_reports.h>
#include <slidewave/engine/particle_engine.templates.h>
#include <slidewave/soil/soil_model.h>
#include <sstream>

namespace slidewave
{
  namespace soil
  {
    SoilModel::SoilModel(const MaterialPointParameters &parameters,
                         const double                   grain_density,
                         const double                   suspension_porosity)
      : prm(parameters)
      , solid_density(grain_density)
      , contact_density((1. - suspension_porosity) * grain_density)
      , gravity(parameters.gravity)
      , point_forces(parameters.point_forces)
      , damping(parameters.damping)
    {
      for (const auto &material : prm.materials)
        {
          if (material.critical_state_dilatancy && !(grain_density > 0.))
            throw InputError(material.path + "/Dilatancy law",
                             "critical state",
                             "constant here: a critical-state dilatancy needs each point's "
                             "porosity, which only the grains of 'Physics = granular water' "
                             "have (their 'Grain density')");
          materials.emplace_back(material);
        }
      const auto &names = property_names();
      for (unsigned int i = 0; i < property::n_properties; ++i)
        if (i == property::velocity_x)
          property_layout.add_vector("velocity", {names[i], names[i + 1]});
        else if (i != property::velocity_y)
          property_layout.add_scalar(names[i]);
      if (point_forces)
        property_layout.add_load("point_force", {"point_force_x", "point_force_y"});
      // b^e only when some material needs it: other scenes keep their layout, output and
      // checkpoints.
      if (FiniteStrainPoints::needed(prm.materials))
        {
          finite_strain.emplace(prm.materials, property_layout.size());
          for (const auto &name : FiniteStrainPoints::property_names())
            property_layout.add_scalar(name);
        }
      // APIC's affine matrix only when chosen.
      if (prm.velocity_transfer == engine::VelocityTransfer::apic)
        {
          for (const auto &name : engine::affine_property_names())
            property_layout.add_scalar(name);
          affine_first = engine::affine_index(property_layout, prm.velocity_transfer);
        }
    }



    void
    SoilModel::update_cell(const ParticleRange        &particles_in_cell,
                           const dealii::Tensor<2, 2> *cell_gradients,
                           const double                dt) const
    {
      // With B-bar, the volumetric part of each point's strain increment is replaced by
      // its volume-weighted average over the cell (mean dilatation). The grains' contact
      // (n_s) is judged on the cell's points together, their mass over their volume, as
      // B-bar takes their mean dilatation: a single point's porosity is noisy, and judged
      // point by point a settled bed locks in rows of stressed points at n_s holding rows
      // of released ones open between them (n up to 0.67). Both sums are taken in one
      // pass over the cell's points.
      const bool   judge_contact = contact_density > 0.;
      double       mass_sum = 0., old_volume_sum = 0., volumetric_sum = 0.;
      unsigned int k = 0;
      if (prm.b_bar || judge_contact)
        for (const auto &particle : particles_in_cell)
          {
            const dealii::Tensor<2, 2> &L = cell_gradients[k++];
            const auto                  p = particle.get_properties();
            old_volume_sum += p[property::volume];
            volumetric_sum += p[property::volume] * (L[0][0] + L[1][1]);
            mass_sum += p[property::mass];
          }
      const double mean_volumetric = prm.b_bar ? volumetric_sum / old_volume_sum : 0.;
      // The cell holds other points than at the last step's end (they move between
      // cells), so it is judged at the step's start too: a cell looser than n_s starts
      // released (its points' update starts from zero stress).
      const double contact_volume = judge_contact ? mass_sum / contact_density : 0.;
      if (judge_contact && old_volume_sum > contact_volume)
        for (auto &particle : particles_in_cell)
          release_stress(particle.get_properties());

      const bool                follow_stretch = prm.shape_function == grid::ShapeFunction::cpgimp;
      const double              max_half       = 0.5 * prm.cell_size;
      const FiniteStrainPoints *hencky         = finite_strain ? &*finite_strain : nullptr;
      double                    volume_sum     = 0.;
      k                                        = 0;
      for (auto &particle : particles_in_cell)
        {
          const dealii::Tensor<2, 2> &L = cell_gradients[k++];
          auto                        p = particle.get_properties();
          if (hencky != nullptr
              && hencky->is_finite_strain(static_cast<unsigned int>(p[property::material_id])))
            hencky->update(p,
                           L,
                           dt,
                           prm.b_bar ? (mean_volumetric - (L[0][0] + L[1][1])) * dt : 0.,
                           state_dilatancy_coefficient(p));
          else
            update_small_strain(p, L, dt, mean_volumetric);
          if (follow_stretch)
            grid::stretch_domain(
              p[property::domain_half_x], p[property::domain_half_y], L, dt, max_half);
          volume_sum += p[property::volume];
        }
      if (!judge_contact)
        return;
      if (volume_sum > contact_volume)
        for (auto &particle : particles_in_cell)
          release_stress(particle.get_properties());
      else if (old_volume_sum > contact_volume)
        {
          // Released at the step's start, in contact by its end: only the part of the
          // step's compaction past the contact volume loads the grains, the fraction
          // (V_c - V) / (V_old - V) of it (V_old > V_c >= V: no division by zero).
          const double fraction = (contact_volume - volume_sum) / (old_volume_sum - volume_sum);
          for (auto &particle : particles_in_cell)
            regain_contact(particle.get_properties(), fraction);
        }
    }



    void
    SoilModel::regain_contact(dealii::ArrayView<double> p, const double fraction) const
    {
      // The stress is scaled towards zero (inside any Drucker-Prager cone that holds the
      // origin), and a finite-strain point's b^e follows the scaled stress.
      for (const unsigned int i :
           {property::stress_xx, property::stress_yy, property::stress_xy, property::stress_zz})
        p[i] *= fraction;
      if (finite_strain)
        finite_strain->set_from_stress(p);
    }



    void
    SoilModel::release_stress(dealii::ArrayView<double> p) const
    {
      for (const unsigned int i :
           {property::stress_xx, property::stress_yy, property::stress_xy, property::stress_zz})
        p[i] = 0.;
      if (finite_strain)
        finite_strain->set_from_stress(p);
    }



    void
    SoilModel::update_small_strain(dealii::ArrayView<double>   p,
                                   const dealii::Tensor<2, 2> &L,
                                   const double                dt,
                                   const double                mean_volumetric) const
    {
      dealii::SymmetricTensor<2, 3> strain_increment;
      strain_increment[0][0] = L[0][0] * dt;
      strain_increment[1][1] = L[1][1] * dt;
      strain_increment[0][1] = 0.5 * (L[0][1] + L[1][0]) * dt;
      if (prm.b_bar)
        {
          const double correction = 0.5 * (mean_volumetric - (L[0][0] + L[1][1])) * dt;
          strain_increment[0][0] += correction;
          strain_increment[1][1] += correction;
        }
      const double spin_xy = 0.5 * (L[0][1] - L[1][0]) * dt;

      dealii::SymmetricTensor<2, 3> stress;
      stress[0][0]                       = p[property::stress_xx];
      stress[1][1]                       = p[property::stress_yy];
      stress[0][1]                       = p[property::stress_xy];
      stress[2][2]                       = p[property::stress_zz];
      double                     plastic = p[property::equivalent_plastic_strain];
      const materials::Material &material
        = materials[static_cast<unsigned int>(p[property::material_id])];
      const double alpha_psi = state_dilatancy_coefficient(p);
      if (material.rate_dependent_friction())
        material.update_stress_at_rate(stress, strain_increment, spin_xy, plastic, alpha_psi, dt);
      else if (!std::isnan(alpha_psi))
        material.update_stress(stress, strain_increment, spin_xy, plastic, alpha_psi);
      else
        material.update_stress(stress, strain_increment, spin_xy, plastic);
      p[property::stress_xx]                 = stress[0][0];
      p[property::stress_yy]                 = stress[1][1];
      p[property::stress_xy]                 = stress[0][1];
      p[property::stress_zz]                 = stress[2][2];
      p[property::equivalent_plastic_strain] = plastic;
      // (with B-bar's own volumes: the point's own dilatation, not the cell's mean)
      p[property::volume] *= prm.own_volumes ? 1. + (L[0][0] + L[1][1]) * dt :
                                               1. + strain_increment[0][0] + strain_increment[1][1];
    }



    double
    SoilModel::state_dilatancy_coefficient(const dealii::ArrayView<double> &p) const
    {
      const materials::Material &material
        = materials[static_cast<unsigned int>(p[property::material_id])];
      if (!material.state_dependent_dilatancy())
        return std::numeric_limits<double>::quiet_NaN();
      // The porosity at the start of the step, n = 1 - m_p / (rho^s V_p).
      const double n = 1. - p[property::mass] / (solid_density * p[property::volume]);
      return material.dilatancy_coefficient(n);
    }



    double
    SoilModel::empty_node_mass() const
    {
      double density = 0.;
      for (const auto &material : prm.materials)
        density = std::max(density, material.density);
      return 1e-12 * prm.cell_size * prm.cell_size * (density > 0. ? density : 1.);
    }



    void
    SoilModel::fill_new_point(std::vector<double>    &properties,
                              const dealii::Point<2> &position,
                              const unsigned int      region_index,
                              const double            hx,
                              const double            hy) const
    {
      const unsigned int               n      = prm.particles_per_direction;
      const particles::MaterialRegion &region = prm.regions[region_index];
      const unsigned int               m      = region.material_index;
      const double                     volume = hx * hy / (n * n);
      properties[property::mass]              = prm.materials[m].density * volume;
      properties[property::volume]            = volume;
      properties[property::initial_volume]    = volume;
      const dealii::Tensor<1, 2> v            = region.initial_velocity(position);
      properties[property::velocity_x]        = v[0];
      properties[property::velocity_y]        = v[1];
      properties[property::initial_x]         = position[0];
      properties[property::initial_y]         = position[1];
      properties[property::material_id]       = m;
      properties[property::domain_half_x]     = 0.5 * hx / n;
      properties[property::domain_half_y]     = 0.5 * hy / n;
      if (finite_strain)
        finite_strain->initialize(properties);
      if (affine_first != dealii::numbers::invalid_unsigned_int)
        {
          // APIC: C_p = grad v of the initial velocity across the point's own domain
          // (exact for a linear field, zero for a uniform one; a jump inside the domain
          // gives the jump over the point's width, not an unbounded slope).
          for (unsigned int j = 0; j < 2; ++j)
            {
              const double         spacing = (j == 0 ? hx : hy) / n;
              dealii::Tensor<1, 2> half_step;
              half_step[j]                 = 0.5 * spacing;
              const dealii::Tensor<1, 2> g = (region.initial_velocity(position + half_step)
                                              - region.initial_velocity(position - half_step))
                                             / spacing;
              for (unsigned int i = 0; i < 2; ++i)
                properties[affine_first + 2 * i + j] = g[i];
            }
        }
    }



    void
    SoilModel::set_uniform_stress(particles::PointCloud &cloud) const
    {
      for (auto &particle : cloud.particles())
        {
          auto p                 = particle.get_properties();
          p[property::stress_xx] = prm.uniform_stress[0];
          p[property::stress_yy] = prm.uniform_stress[1];
          p[property::stress_xy] = prm.uniform_stress[2];
          p[property::stress_zz] = prm.uniform_stress[3];
          if (finite_strain)
            finite_strain->set_from_stress(p);
        }
    }



    void
    SoilModel::set_geostatic_stress(
      particles::PointCloud                                 &cloud,
      const std::function<double(const dealii::Point<2> &)> &buoyancy) const
    {
      // The weight above each point, per unit width, from the points in its vertical strip
      // (strips of the initial point spacing, which the points of a region fill on a
      // lattice): a histogram of mass over strips and rows, summed over all ranks, then
      // summed from the top down.
      const double       spacing = prm.cell_size / prm.particles_per_direction;
      const unsigned int n_x
        = static_cast<unsigned int>(std::round((prm.upper_right[0] - prm.lower_left[0]) / spacing));
      const unsigned int n_y
        = static_cast<unsigned int>(std::round((prm.upper_right[1] - prm.lower_left[1]) / spacing));
      const auto bin = [&](const dealii::Point<2> &x, const unsigned int d, const unsigned int n) {
        const int i = static_cast<int>(std::floor((x[d] - prm.lower_left[d]) / spacing));
        return static_cast<unsigned int>(std::clamp(i, 0, static_cast<int>(n) - 1));
      };
      std::vector<double> mass(static_cast<std::size_t>(n_x) * n_y, 0.);
      // A downward point force (the water on the surface) weighs like mass F / g.
      const double g = std::abs(prm.gravity[1]);
      // A point's weight as a mass: its own less the buoyancy, plus its point force.
      const auto weight = [&](const auto &particle) {
        const auto   p    = particle.get_properties();
        const double lift = buoyancy ? buoyancy(particle.get_location()) : 0.;
        return p[property::mass] * (1. - lift)
               - (prm.point_forces && g > 0. ? p[property::point_force_y] / g : 0.);
      };
      cloud.for_each_particle([&](const auto &particle) {
        mass[static_cast<std::size_t>(bin(particle.get_location(), 0, n_x)) * n_y
             + bin(particle.get_location(), 1, n_y)]
          += weight(particle);
      });
      dealii::Utilities::MPI::sum(mass, MPI_COMM_WORLD, mass);
      // Weight above the bottom of each bin.
      for (unsigned int i = 0; i < n_x; ++i)
        for (int j = static_cast<int>(n_y) - 2; j >= 0; --j)
          mass[static_cast<std::size_t>(i) * n_y + j]
            += mass[static_cast<std::size_t>(i) * n_y + j + 1];

      for (auto &particle : cloud.particles())
        {
          auto               p   = particle.get_properties();
          const unsigned int i   = bin(particle.get_location(), 0, n_x);
          const unsigned int j   = bin(particle.get_location(), 1, n_y);
          const double       own = weight(particle);
          const double above = (j + 1 < n_y ? mass[static_cast<std::size_t>(i) * n_y + j + 1] : 0.);
          const double sigma_v = -g * (above + 0.5 * own) / spacing;
          const auto &material = prm.materials[static_cast<unsigned int>(p[property::material_id])];
          double      k0       = prm.lateral_stress_ratio;
          if (k0 < 0.)
            k0 = material.model != materials::MaterialModel::linear_elastic ?
                   1. - std::sin(material.friction_angle * M_PI / 180.) :
                   material.poisson_ratio / (1. - material.poisson_ratio);
          p[property::stress_yy] = sigma_v;
          p[property::stress_xx] = k0 * sigma_v;
          p[property::stress_zz] = k0 * sigma_v;
          p[property::stress_xy] = 0.;
          if (finite_strain)
            finite_strain->set_from_stress(p);
        }
    }



    void
    SoilModel::finish_gravity_loading(particles::PointCloud &cloud) const
    {
      for (auto &particle : cloud.particles())
        {
          auto p                  = particle.get_properties();
          p[property::velocity_x] = 0.;
          p[property::velocity_y] = 0.;
          if (affine_first != dealii::numbers::invalid_unsigned_int)
            for (unsigned int i = 0; i < 4; ++i)
              p[affine_first + i] = 0.;
          p[property::initial_x] = particle.get_location()[0];
          p[property::initial_y] = particle.get_location()[1];
        }
    }



    void
    SoilModel::set_point_forces(
      particles::PointCloud &cloud,
      const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
        &force) const
    {
      Assert(point_forces, dealii::ExcMessage("point forces were not switched on"));
      for (auto &particle : cloud.particles())
        {
          const dealii::Tensor<1, 2> f = force(particle);
          auto                       p = particle.get_properties();
          p[property::point_force_x]   = f[0];
          p[property::point_force_y]   = f[1];
        }
    }



    dealii::Tensor<1, 2>
    SoilModel::total_point_force(const particles::PointCloud &cloud) const
    {
      dealii::Tensor<1, 2> total;
      if (point_forces)
        cloud.for_each_particle([&](const auto &particle) {
          const auto p = particle.get_properties();
          total[0] += p[property::point_force_x];
          total[1] += p[property::point_force_y];
        });
      return dealii::Utilities::MPI::sum(total, MPI_COMM_WORLD);
    }



    std::string
    SoilModel::find_invalid_particle(const particles::PointCloud &cloud) const
    {
      std::string problem;
      const auto &layout = property_layout;
      // The first such point in the grid's order.
      cloud.for_each_particle([&](const auto &particle) {
        if (!problem.empty())
          return;
        const auto p  = particle.get_properties();
        bool       ok = p[property::volume] > 0.;
        for (unsigned int i = 0; i < layout.size(); ++i)
          ok = ok && (!layout.is_state(i) || std::isfinite(p[i]));
        for (unsigned int d = 0; d < 2; ++d)
          ok = ok && std::isfinite(particle.get_location()[d]);
        if (!ok)
          {
            std::ostringstream out;
            out << "material point " << particle.get_id() << " at (" << particle.get_location()
                << ") has "
                << (std::isfinite(p[property::volume]) && p[property::volume] <= 0. ?
                      "a non-positive volume" :
                      "non-finite values")
                << " (velocity " << p[property::velocity_x] << ", " << p[property::velocity_y]
                << "; stress " << p[property::stress_xx] << ", " << p[property::stress_yy] << ", "
                << p[property::stress_xy] << ")";
            problem = out.str();
          }
      });
      if (problem.empty())
        problem = cloud.wall_crossing;
      // Every rank learns the problem of the lowest rank that has one.
      return rank_reports::first_nonempty(problem);
    }



    SoilModel::EnergyBudget
    SoilModel::energy_budget(const particles::PointCloud &cloud) const
    {
      double sums[3] = {0., 0., 0.};
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p  = particle.get_properties();
        const double m  = p[property::mass];
        const double vx = p[property::velocity_x], vy = p[property::velocity_y];
        sums[0] += 0.5 * m * (vx * vx + vy * vy);
        const auto &elastic
          = materials[static_cast<unsigned int>(p[property::material_id])].elasticity();
        const double sxx = p[property::stress_xx], syy = p[property::stress_yy],
                     szz = p[property::stress_zz], sxy = p[property::stress_xy];
        const double mean = (sxx + syy + szz) / 3.;
        const double dev2 = (sxx - mean) * (sxx - mean) + (syy - mean) * (syy - mean)
                            + (szz - mean) * (szz - mean) + 2. * sxy * sxy;
        // Hencky: the energy W(tau) per reference volume V_0 = V / J, tau = J sigma, so
        // J times the same expression in sigma and V.
        const double J = finite_strain
                             && finite_strain->is_finite_strain(
                               static_cast<unsigned int>(p[property::material_id])) ?
                           p[property::volume] / p[property::initial_volume] :
                           1.;
        sums[1]
          += J * p[property::volume]
             * (0.5 * mean * mean / elastic.bulk_modulus() + 0.25 * dev2 / elastic.shear_modulus());
        sums[2] += m
                   * (prm.gravity[0] * (particle.get_location()[0] - p[property::initial_x])
                      + prm.gravity[1] * (particle.get_location()[1] - p[property::initial_y]));
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 3));
      return {sums[0], sums[1], sums[2]};
    }



    std::string
    SoilModel::describe_fastest_particle(const particles::PointCloud &cloud) const
    {
      double             fastest = -1.;
      std::ostringstream out;
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p     = particle.get_properties();
        const double speed = std::sqrt(p[property::velocity_x] * p[property::velocity_x]
                                       + p[property::velocity_y] * p[property::velocity_y]);
        if (speed > fastest)
          {
            fastest = speed;
            out.str("");
            out << "material point " << particle.get_id() << " at (" << particle.get_location()
                << ") with speed " << speed << " m/s";
          }
      });
      // The rank with the fastest point tells everybody.
      return rank_reports::of_largest(fastest, out.str());
    }



    SoilModel::Integrals
    SoilModel::integrals(const particles::PointCloud &cloud) const
    {
      Integrals result;
      double    sums[4] = {0., 0., 0., 0.};
      double    maxima[3]
        = {0., -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p  = particle.get_properties();
        const double m  = p[property::mass];
        const double vx = p[property::velocity_x], vy = p[property::velocity_y];
        sums[0] += m;
        sums[1] += m * vx;
        sums[2] += m * vy;
        sums[3] += 0.5 * m * (vx * vx + vy * vy);
        maxima[0] = std::max(maxima[0], std::sqrt(vx * vx + vy * vy));
        maxima[1] = std::max(maxima[1], particle.get_location()[0]);
        maxima[2] = std::max(maxima[2], particle.get_location()[1]);
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 4),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 4));
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(maxima, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(maxima, 3));
      result.mass           = sums[0];
      result.momentum_x     = sums[1];
      result.momentum_y     = sums[2];
      result.kinetic_energy = sums[3];
      result.max_speed      = maxima[0];
      result.runout         = maxima[1];
      result.max_height     = maxima[2];
      result.lost_mass      = dealii::Utilities::MPI::sum(cloud.lost_mass, MPI_COMM_WORLD);
      result.n_particles    = cloud.particles().n_global_particles();
      return result;
    }
  } // namespace soil



  // The particle–grid cycle for the soil, with its terms inlined.
  template class engine::TransferKernels<soil::SoilModel>;
  template class engine::ParticleEngine<soil::SoilModel>;
} // namespace slidewave
