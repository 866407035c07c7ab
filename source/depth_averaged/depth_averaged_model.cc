#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <limits>
#include <slidewave/core/rank_reports.h>
#include <slidewave/depth_averaged/bingham.h>
#include <slidewave/depth_averaged/depth_averaged_model.h>
#include <slidewave/engine/particle_engine.templates.h>
#include <sstream>

namespace slidewave
{
  namespace depth_averaged
  {
    DepthAveragedModel::DepthAveragedModel(const DepthAveragedParameters &parameters,
                                           const terrain::ElevationGrid  &terrain)
      : prm(parameters)
      , elevation(terrain)
      , g(parameters.gravity)
      , half_rho_g(0.5 * parameters.density * parameters.gravity)
      , rho_g(parameters.density * parameters.gravity)
      , still_level_form(parameters.hydrostatic_term == HydrostaticTerm::still_level)
      , still_level(parameters.still_level)
      , friction(parameters.friction)
      , tan_phi(std::tan(parameters.friction_angle))
      , rho_g_over_xi(parameters.turbulence > 0. ?
                        parameters.density * parameters.gravity / parameters.turbulence :
                        0.)
      , atmospheric_pressure(parameters.atmospheric_pressure)
      , project_depth(parameters.depth_update == DepthUpdate::projection)
      , bed_normal(parameters.slope_correction == SlopeCorrection::bed_normal)
      , split_width(parameters.split_stretch * parameters.cell_size
                    / parameters.particles_per_direction)
    {
      property_layout.add_scalar("mass");
      property_layout.add_scalar("volume");
      property_layout.add_scalar("depth");
      property_layout.add_vector("velocity", {"velocity_x", "velocity_y"});
      property_layout.add_scalar("stress_xx");
      property_layout.add_scalar("stress_yy");
      property_layout.add_scalar("stress_xy");
      property_layout.add_scalar("effective_stress_xx");
      property_layout.add_scalar("effective_stress_yy");
      property_layout.add_scalar("effective_stress_xy");
      property_layout.add_scalar("initial_x");
      property_layout.add_scalar("initial_y");
      property_layout.add_scalar("domain_half_x");
      property_layout.add_scalar("domain_half_y");
      property_layout.add_scalar("width_x");
      property_layout.add_scalar("width_y");
    }



    void
    DepthAveragedModel::update_cell(const ParticleRange        &particles_in_cell,
                                    const dealii::Tensor<2, 2> *cell_gradients,
                                    const double                dt) const
    {
      const bool   follow_stretch = prm.shape_function == grid::ShapeFunction::cpgimp;
      const double max_half       = 0.5 * prm.cell_size;
      const double mu = prm.viscosity, tau_y = prm.yield_stress;
      unsigned int k = 0;
      for (auto &particle : particles_in_cell)
        {
          const dealii::Tensor<2, 2> &L = cell_gradients[k++];
          auto                        p = particle.get_properties();
          // Eq. 38: the column keeps its volume, its area grows by 1 + tr(delta eps).
          const double h     = p[property::depth] / (1. + (L[0][0] + L[1][1]) * dt);
          p[property::depth] = h;
          // Eqs. 36-37: the stress of the rate D = sym(L) at the updated velocity and
          // depth (a viscous law: the stress follows the rate, no history).
          const auto sigma       = bingham::stress(L[0][0],
                                             L[1][1],
                                             0.5 * (L[0][1] + L[1][0]),
                                             p[property::velocity_x],
                                             p[property::velocity_y],
                                             h,
                                             mu,
                                             tau_y,
                                             prm.regularization);
          p[property::stress_xx] = sigma.xx;
          p[property::stress_yy] = sigma.yy;
          p[property::stress_xy] = sigma.xy;
          // The column's widths follow the stretch along x and y (for splitting).
          p[property::width_x] *= 1. + L[0][0] * dt;
          p[property::width_y] *= 1. + L[1][1] * dt;
          if (follow_stretch)
            grid::stretch_domain(
              p[property::domain_half_x], p[property::domain_half_y], L, dt, max_half);
        }
    }



    double
    DepthAveragedModel::empty_node_mass() const
    {
      // A film of 1e-12 of the cell size over a cell.
      return 1e-12 * prm.density * std::pow(prm.cell_size, 3);
    }



    double
    DepthAveragedModel::stability_limit(const double max_speed, const double h) const
    {
      // Eq. 22 with the wave speed: h / max_p (|v_p| + sqrt(g h_p)); and the viscous
      // limit of an explicit step, rho h^2 / (4 eta) with eta = 2 mu + tau_Y m the largest
      // viscosity of the (regularized) Bingham law: its stress is eta D, and the largest
      // eigenvalue of div(eta D) on the grid is below 8 eta / (rho h^2).
      const double eta       = 2. * prm.viscosity + prm.yield_stress * prm.regularization;
      const double advective = ParticleModelDefaults::stability_limit(max_speed, h);
      const double viscous
        = eta > 0. ? prm.density * h * h / (4. * eta) : std::numeric_limits<double>::infinity();
      return std::min(advective, viscous);
    }



    bool
    DepthAveragedModel::fill_new_point(std::vector<double>        &properties,
                                       const dealii::Point<2>     &position,
                                       const double                h,
                                       const dealii::Tensor<1, 2> &v,
                                       const double                hx,
                                       const double                hy) const
    {
      if (!(h > 0.))
        return false;
      const unsigned int n                = prm.particles_per_direction;
      const double       area             = hx * hy / (n * n);
      properties[property::volume]        = h * area;               // Eq. 18
      properties[property::mass]          = prm.density * h * area; // Eq. 17
      properties[property::depth]         = h;
      properties[property::velocity_x]    = v[0];
      properties[property::velocity_y]    = v[1];
      properties[property::initial_x]     = position[0];
      properties[property::initial_y]     = position[1];
      properties[property::domain_half_x] = 0.5 * hx / n;
      properties[property::domain_half_y] = 0.5 * hy / n;
      properties[property::width_x]       = hx / n;
      properties[property::width_y]       = hy / n;
      return true;
    }



    void
    DepthAveragedModel::refresh_effective_stress(particles::PointCloud &cloud) const
    {
      for (auto &particle : cloud.particles())
        {
          auto       p                     = particle.get_properties();
          const auto t                     = scatter_terms(p, particle.get_location());
          p[property::effective_stress_xx] = t.sxx;
          p[property::effective_stress_yy] = t.syy;
          p[property::effective_stress_xy] = t.sxy;
        }
    }



    DepthAveragedModel::Integrals
    DepthAveragedModel::integrals(const particles::PointCloud &cloud) const
    {
      constexpr double inf = std::numeric_limits<double>::infinity();
      // Sums: mass, momentum x, y, kinetic, potential energy, m x, m y.
      double sums[7] = {0., 0., 0., 0., 0., 0., 0.};
      // Maxima: speed, depth, travel, x, -x, y, -y, cells holding points.
      double       maxima[7] = {0., 0., 0., -inf, -inf, -inf, -inf};
      unsigned int covered   = 0;
      // In the grid's order (for_each_cell_with_particles()): the same sums in a run
      // resumed from a checkpoint.
      cloud.for_each_cell_with_particles([&](const auto &, const auto &particles_in_cell) {
        ++covered;
        for (const auto &particle : particles_in_cell)
          {
            const auto              p  = particle.get_properties();
            const dealii::Point<2> &x  = particle.get_location();
            const double            m  = p[property::mass];
            const double            vx = p[property::velocity_x], vy = p[property::velocity_y];
            const double            h = p[property::depth];
            sums[0] += m;
            sums[1] += m * vx;
            sums[2] += m * vy;
            sums[3] += 0.5 * m * (vx * vx + vy * vy);
            // The column's centre of mass is at Z + h / 2.
            sums[4] += m * g * (elevation.value(x) + 0.5 * h);
            sums[5] += m * x[0];
            sums[6] += m * x[1];
            maxima[0] = std::max(maxima[0], std::sqrt(vx * vx + vy * vy));
            maxima[1] = std::max(maxima[1], h);
            maxima[2] = std::max(maxima[2],
                                 x.distance(dealii::Point<2>(p[property::initial_x],
                                                             p[property::initial_y])));
            maxima[3] = std::max(maxima[3], x[0]);
            maxima[4] = std::max(maxima[4], -x[0]);
            maxima[5] = std::max(maxima[5], x[1]);
            maxima[6] = std::max(maxima[6], -x[1]);
          }
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 7),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 7));
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(maxima, 7),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(maxima, 7));
      Integrals result;
      result.mass             = sums[0];
      result.momentum_x       = sums[1];
      result.momentum_y       = sums[2];
      result.kinetic_energy   = sums[3];
      result.potential_energy = sums[4];
      result.centroid_x       = sums[0] > 0. ? sums[5] / sums[0] : 0.;
      result.centroid_y       = sums[0] > 0. ? sums[6] / sums[0] : 0.;
      result.max_speed        = maxima[0];
      result.max_depth        = maxima[1];
      result.max_travel       = maxima[2];
      result.x_max            = maxima[3];
      result.x_min            = -maxima[4];
      result.y_max            = maxima[5];
      result.y_min            = -maxima[6];
      result.covered_area
        = dealii::Utilities::MPI::sum(covered, MPI_COMM_WORLD) * prm.cell_size * prm.cell_size;
      result.lost_mass   = dealii::Utilities::MPI::sum(cloud.lost_mass, MPI_COMM_WORLD);
      result.n_particles = cloud.particles().n_global_particles();
      return result;
    }



    DepthAveragedModel::StillStateErrors
    DepthAveragedModel::still_state_errors(
      const particles::PointCloud                           &cloud,
      const std::function<double(const dealii::Point<2> &)> &exact_depth) const
    {
      StillStateErrors errors;
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p    = particle.get_properties();
        const double h    = p[property::depth];
        const double area = p[property::volume] / h;
        const double e[3] = {h - exact_depth(particle.get_location()),
                             h * p[property::velocity_x],
                             h * p[property::velocity_y]};
        for (unsigned int i = 0; i < 3; ++i)
          {
            errors.l1[i] += std::abs(e[i]) * area;
            errors.linf[i] = std::max(errors.linf[i], std::abs(e[i]));
          }
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(errors.l1, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(errors.l1, 3));
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(errors.linf, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(errors.linf, 3));
      return errors;
    }



    DepthAveragedModel::TranslationErrors
    DepthAveragedModel::translation_errors(
      const particles::PointCloud                                         &cloud,
      const double                                                         t,
      const std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)> &initial_velocity,
      const std::function<double(const dealii::Point<2> &)>               &initial_depth) const
    {
      // Sums: |h_p - h_p0| A_p0, h_p0 A_p0 = V_p; maxima: relative depth error, distance.
      double sums[2] = {0., 0.}, maxima[2] = {0., 0.};
      cloud.for_each_particle([&](const auto &particle) {
        const auto             p = particle.get_properties();
        const dealii::Point<2> x0(p[property::initial_x], p[property::initial_y]);
        const double           h0    = initial_depth(x0);
        const dealii::Point<2> exact = x0 + t * initial_velocity(x0);
        const double           e     = std::abs(p[property::depth] - h0);
        sums[0] += e * p[property::volume] / h0;
        sums[1] += p[property::volume];
        maxima[0] = std::max(maxima[0], e / h0);
        maxima[1] = std::max(maxima[1], particle.get_location().distance(exact));
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 2),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 2));
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(maxima, 2),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(maxima, 2));
      TranslationErrors errors;
      errors.depth_l1     = sums[1] > 0. ? sums[0] / sums[1] : 0.;
      errors.depth_max    = maxima[0];
      errors.position_max = maxima[1];
      return errors;
    }



    std::string
    DepthAveragedModel::find_invalid_particle(const particles::PointCloud &cloud) const
    {
      std::string problem;
      // The first such point in the grid's order.
      cloud.for_each_particle([&](const auto &particle) {
        if (!problem.empty())
          return;
        const auto p  = particle.get_properties();
        bool       ok = p[property::depth] > 0.;
        for (unsigned int i = 0; i < property::n_properties; ++i)
          ok = ok && std::isfinite(p[i]);
        for (unsigned int d = 0; d < 2; ++d)
          ok = ok && std::isfinite(particle.get_location()[d]);
        if (!ok)
          {
            std::ostringstream out;
            out << "material point " << particle.get_id() << " at (" << particle.get_location()
                << ") has "
                << (std::isfinite(p[property::depth]) && p[property::depth] <= 0. ?
                      "a depth that is not positive" :
                      "non-finite values")
                << " (depth " << p[property::depth] << " m, velocity " << p[property::velocity_x]
                << ", " << p[property::velocity_y] << " m/s)";
            problem = out.str();
          }
      });
      if (problem.empty())
        problem = cloud.wall_crossing;
      return rank_reports::first_nonempty(problem);
    }



    std::string
    DepthAveragedModel::describe_fastest_particle(const particles::PointCloud &cloud) const
    {
      double             fastest = -1.;
      std::ostringstream out;
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p     = particle.get_properties();
        const double speed = std::hypot(p[property::velocity_x], p[property::velocity_y]);
        if (speed > fastest)
          {
            fastest = speed;
            out.str("");
            out << "material point " << particle.get_id() << " at (" << particle.get_location()
                << ") with speed " << speed << " m/s and depth " << p[property::depth] << " m";
          }
      });
      return rank_reports::of_largest(fastest, out.str());
    }



    void
    DepthAveragedModel::finish_nodal_fields(grid::NodalWorkspace &nodes) const
    {
      if (!project_depth)
        return;
      auto &depth = nodes.fields[depth_field];
      for (const unsigned int i : nodes.active())
        depth.local_element(i) *= nodes.inverse_area[i];
      depth.update_ghost_values();
      nodes.interpolate_hanging_nodes(depth);
    }
  } // namespace depth_averaged

  template class engine::TransferKernels<depth_averaged::DepthAveragedModel>;
  template class engine::ParticleEngine<depth_averaged::DepthAveragedModel>;
} // namespace slidewave
