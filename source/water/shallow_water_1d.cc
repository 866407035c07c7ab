#include <cmath>
#include <deal.II/base/exceptions.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/water/shallow_water_1d.h>

namespace slidewave
{
  namespace water
  {
    ShallowWater1D::ShallowWater1D(const WaterMesh              &mesh,
                                   const ShallowWaterParameters &parameters,
                                   const WaterBoundary          &left,
                                   const WaterBoundary          &right)
      : water_mesh(mesh)
      , prm(parameters)
      , left_boundary(left)
      , right_boundary(right)
    {
      const unsigned int n = water_mesh.n_cells();
      inverse_width.resize(n);
      center.resize(n);
      inverse_spacing.resize(n > 1 ? n - 1 : 0);
      for (unsigned int i = 0; i < n; ++i)
        {
          inverse_width[i] = 1. / water_mesh.width(i);
          center[i]        = water_mesh.center(i);
        }
      for (unsigned int i = 0; i + 1 < n; ++i)
        inverse_spacing[i] = 1. / (center[i + 1] - center[i]);
      for (auto *v : {&h,
                      &hu,
                      &bed_elevation,
                      &h_stage,
                      &hu_stage,
                      &rate_h,
                      &rate_hu,
                      &h_left_face,
                      &h_right_face,
                      &u_left_face,
                      &u_right_face,
                      &bed_left_face,
                      &bed_right_face})
        v->assign(n, 0.);
    }



    void
    ShallowWater1D::set_state(const std::vector<double> &depth,
                              const std::vector<double> &discharge)
    {
      AssertDimension(depth.size(), n_cells());
      AssertDimension(discharge.size(), n_cells());
      h  = depth;
      hu = discharge;
      clean_dry_cells(h, hu);
    }



    void
    ShallowWater1D::restore(const std::vector<double> &depth,
                            const std::vector<double> &discharge,
                            const std::vector<double> &bed,
                            const double               net_boundary_inflow)
    {
      AssertDimension(depth.size(), n_cells());
      AssertDimension(discharge.size(), n_cells());
      AssertDimension(bed.size(), n_cells());
      h               = depth;
      hu              = discharge;
      bed_elevation   = bed;
      boundary_inflow = net_boundary_inflow;
    }



    void
    ShallowWater1D::set_bed(const std::vector<double> &bed)
    {
      AssertDimension(bed.size(), n_cells());
      bed_elevation = bed;
    }



    double
    ShallowWater1D::stable_time_step() const
    {
      const double g      = prm.gravity;
      double       min_dt = std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < h.size(); ++i)
        if (h[i] > prm.dry_depth)
          {
            const double speed = std::abs(hu[i] / h[i]) + std::sqrt(g * h[i]);
            min_dt             = std::min(min_dt, water_mesh.width(i) / speed);
          }
      return prm.courant_number * min_dt;
    }



    void
    ShallowWater1D::clean_dry_cells(std::vector<double> &depth,
                                    std::vector<double> &discharge) const
    {
      const double film2 = prm.film_depth * prm.film_depth;
      for (unsigned int i = 0; i < depth.size(); ++i)
        if (depth[i] <= prm.dry_depth)
          {
            discharge[i] = 0.;
            // Round-off can leave a drained cell at -1e-17: that is zero water. A real
            // negative depth is left for the run-time guard to report.
            if (depth[i] < 0. && depth[i] > -prm.dry_depth)
              depth[i] = 0.;
          }
        else if (depth[i] < prm.film_depth)
          {
            // Thin film: desingularized velocity u = 2 h (hu) / (h^2 + h_film^2) (Kurganov
            // and Petrova 2007), which is hu/h for thick water and goes to zero with h, so
            // that films left behind by a receding shoreline do not race down the slope.
            const double h = depth[i];
            discharge[i]   = h * (2. * h * discharge[i] / (h * h + film2));
          }
    }



    void
    ShallowWater1D::apply_friction(const double dt)
    {
      if (prm.manning_coefficient == 0.)
        return;
      const double factor = dt * prm.gravity * prm.manning_coefficient * prm.manning_coefficient;
      for (unsigned int i = 0; i < h.size(); ++i)
        if (h[i] > prm.dry_depth)
          {
            const double speed = std::abs(hu[i] / h[i]);
            hu[i] /= 1. + factor * speed / std::pow(h[i], 4. / 3.);
          }
    }



    void
    ShallowWater1D::advance(const double t, const double dt)
    {
      const unsigned int n = h.size();
      if (prm.time_integrator == TimeIntegrator::forward_euler)
        {
          const double inflow = compute_rate(h, hu, t, 0.5 * dt, rate_h, rate_hu);
          for (unsigned int i = 0; i < n; ++i)
            {
              h[i] += dt * rate_h[i];
              hu[i] += dt * rate_hu[i];
            }
          boundary_inflow += dt * inflow;
        }
      else
        {
          // Heun / SSP-RK2: U1 = U + dt L(U); U <- (U + U1 + dt L(U1)) / 2.
          const double inflow_1 = compute_rate(h, hu, t, 0., rate_h, rate_hu);
          for (unsigned int i = 0; i < n; ++i)
            {
              h_stage[i]  = h[i] + dt * rate_h[i];
              hu_stage[i] = hu[i] + dt * rate_hu[i];
            }
          clean_dry_cells(h_stage, hu_stage);
          const double inflow_2 = compute_rate(h_stage, hu_stage, t + dt, 0., rate_h, rate_hu);
          for (unsigned int i = 0; i < n; ++i)
            {
              h[i]  = 0.5 * (h[i] + h_stage[i] + dt * rate_h[i]);
              hu[i] = 0.5 * (hu[i] + hu_stage[i] + dt * rate_hu[i]);
            }
          boundary_inflow += 0.5 * dt * (inflow_1 + inflow_2);
        }
      clean_dry_cells(h, hu);
      apply_friction(dt);
    }



    std::string
    ShallowWater1D::describe_invalid_cell(const unsigned int i) const
    {
      return std::string(std::isfinite(h[i]) && std::isfinite(hu[i]) ? "negative water depth" :
                                                                       "non-finite water state")
             + " in water cell " + std::to_string(i) + " (x = " + to_string(water_mesh.center(i))
             + " m): h = " + to_string(h[i]) + ", hu = " + to_string(hu[i]);
    }



    unsigned int
    ShallowWater1D::find_invalid_cell() const
    {
      for (unsigned int i = 0; i < h.size(); ++i)
        if (!std::isfinite(h[i]) || !std::isfinite(hu[i]) || h[i] < 0.)
          return i;
      return h.size();
    }



    double
    ShallowWater1D::water_volume() const
    {
      double volume = 0.;
      for (unsigned int i = 0; i < h.size(); ++i)
        volume += h[i] * water_mesh.width(i);
      return volume;
    }



    double
    ShallowWater1D::max_speed() const
    {
      double speed = 0.;
      for (unsigned int i = 0; i < h.size(); ++i)
        speed = std::max(speed, std::abs(velocity(i)));
      return speed;
    }



    double
    ShallowWater1D::max_free_surface() const
    {
      // Over the wet cells; where all is dry, the free surface is the bed.
      double eta     = -std::numeric_limits<double>::infinity();
      double max_bed = -std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < h.size(); ++i)
        {
          max_bed = std::max(max_bed, bed_elevation[i]);
          if (h[i] > prm.dry_depth)
            eta = std::max(eta, h[i] + bed_elevation[i]);
        }
      return std::isfinite(eta) ? eta : max_bed;
    }



    double
    ShallowWater1D::free_surface_at(const double x) const
    {
      const unsigned int n = h.size();
      if (x <= center[0])
        return h[0] + bed_elevation[0];
      if (x >= center[n - 1])
        return h[n - 1] + bed_elevation[n - 1];
      unsigned int i = water_mesh.cell_containing(x);
      if (x < center[i])
        --i;
      const double w = (x - center[i]) / (center[i + 1] - center[i]);
      return (1. - w) * (h[i] + bed_elevation[i]) + w * (h[i + 1] + bed_elevation[i + 1]);
    }
  } // namespace water
} // namespace slidewave
