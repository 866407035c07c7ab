#include <cmath>
#include <slidewave/water/numerical_flux.h>
#include <slidewave/water/shallow_water_1d.h>
#include <type_traits>

// ShallowWater1D, its spatial discretization: the reconstruction of the face values
// (first order or MUSCL with a limiter), the numerical fluxes through the interfaces and
// the two ends with the hydrostatic reconstruction, and the centred bed source, which
// together give the rate of change dU/dt of compute_rate(). The time stepping and the
// rest of the class are in shallow_water_1d.cc.
namespace slidewave
{
  namespace water
  {
    namespace
    {
      template <Limiter limiter>
      inline double
      limited_slope(const double a, const double b)
      {
        if constexpr (limiter == Limiter::minmod)
          return slope_limiter::minmod(a, b);
        else if constexpr (limiter == Limiter::van_leer)
          return slope_limiter::van_leer(a, b);
        else
          return slope_limiter::superbee(a, b);
      }



      /**
       * MUSCL reconstruction on non-uniform cells of depth h, free surface η = h + B and
       * velocity u. The bed at the faces follows as B = η - h, so that a flat free surface
       * at rest is reconstructed flat and the hydrostatic reconstruction balances it exactly.
       * Cells at the ends of the domain, dry cells and cells next to dry ones keep constant
       * values; a reconstruction that would make a face depth negative is dropped.
       */
      template <Limiter limiter>
      void
      reconstruct_second_order(const std::vector<double> &h,
                               const std::vector<double> &hu,
                               const std::vector<double> &bed,
                               const std::vector<double> &inverse_spacing,
                               const std::vector<double> &inverse_width,
                               const double               dry_depth,
                               const double               gravity,
                               const double               half_step,
                               std::vector<double>       &h_l,
                               std::vector<double>       &h_r,
                               std::vector<double>       &u_l,
                               std::vector<double>       &u_r,
                               std::vector<double>       &b_l,
                               std::vector<double>       &b_r)
      {
        const unsigned int n = h.size();
        // Cell velocities once (one division per cell), into the left-face array, which
        // is overwritten cell by cell behind the sweep: cell i reads u[i+1] before cell
        // i+1 writes it, and u[i-1] is kept in a register.
        for (unsigned int i = 0; i < n; ++i)
          u_l[i] = h[i] > dry_depth ? hu[i] / h[i] : 0.;
        double u_previous = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double u_i    = u_l[i];
            const double u_left = u_previous;
            u_previous          = u_i;
            h_l[i] = h_r[i] = h[i];
            u_l[i] = u_r[i] = u_i;
            b_l[i] = b_r[i] = bed[i];
            if (i == 0 || i == n - 1 || h[i] <= dry_depth || h[i - 1] <= dry_depth
                || h[i + 1] <= dry_depth)
              continue;

            const double inv_dx_l   = inverse_spacing[i - 1];
            const double inv_dx_r   = inverse_spacing[i];
            const double half_width = 0.5 / inverse_width[i];

            const double slope_h
              = limited_slope<limiter>((h[i] - h[i - 1]) * inv_dx_l, (h[i + 1] - h[i]) * inv_dx_r);
            const double eta_m = h[i - 1] + bed[i - 1];
            const double eta_i = h[i] + bed[i];
            const double eta_p = h[i + 1] + bed[i + 1];
            const double slope_eta
              = limited_slope<limiter>((eta_i - eta_m) * inv_dx_l, (eta_p - eta_i) * inv_dx_r);
            const double slope_u
              = limited_slope<limiter>((u_i - u_left) * inv_dx_l, (u_l[i + 1] - u_i) * inv_dx_r);

            double dh = slope_h * half_width;
            if (h[i] - std::abs(dh) < 0.)
              dh = 0.;
            const double deta = slope_eta * half_width;
            const double du   = slope_u * half_width;

            // Hancock predictor (forward Euler only): evolve the face values by half a step
            // with the primitive equations h_t = -(u h_x + h u_x), u_t = -(u u_x + g eta_x),
            // which makes the one-stage scheme second order in time as well. The bed does
            // not move, so eta changes as h does and the face beds B = eta - h are
            // unchanged: a lake at rest (u = 0, eta_x = 0) is left exactly as it is.
            double dh_dt = 0., du_dt = 0.;
            if (half_step > 0.)
              {
                dh_dt = -half_step * (u_i * slope_h + h[i] * slope_u);
                du_dt = -half_step * (u_i * slope_u + gravity * slope_eta);
                if (h[i] - std::abs(dh) + dh_dt < 0.)
                  dh_dt = 0.;
              }

            h_l[i] = h[i] - dh + dh_dt;
            h_r[i] = h[i] + dh + dh_dt;
            u_l[i] = u_i - du + du_dt;
            u_r[i] = u_i + du + du_dt;
            b_l[i] = (eta_i - deta) - (h[i] - dh);
            b_r[i] = (eta_i + deta) - (h[i] + dh);
          }
      }



      template <NumericalFlux flux_type>
      inline void
      interface_flux(const double h_l,
                     const double q_l,
                     const double h_r,
                     const double q_r,
                     const double g,
                     const double dry_depth,
                     double      &flux_h,
                     double      &flux_q)
      {
        if constexpr (flux_type == NumericalFlux::roe)
          numerical_flux::roe(h_l, q_l, h_r, q_r, g, dry_depth, flux_h, flux_q);
        else
          numerical_flux::hll(h_l, q_l, h_r, q_r, g, dry_depth, flux_h, flux_q);
      }



      /**
       * The interior of the flux loop: for every interface, the hydrostatic reconstruction
       * (Audusse et al. 2004) of the two face states to the common bed max(B_l, B_r), the
       * numerical flux between them, and the pressure corrections g/2 (h^2 - h*^2) that
       * balance the bed slope inside the Riemann problem.
       */
      template <NumericalFlux flux_type>
      void
      add_interface_fluxes(const unsigned int         n,
                           const std::vector<double> &h_l,
                           const std::vector<double> &h_r,
                           const std::vector<double> &u_l,
                           const std::vector<double> &u_r,
                           const std::vector<double> &b_l,
                           const std::vector<double> &b_r,
                           const std::vector<double> &inverse_width,
                           const double               g,
                           const double               dry_depth,
                           std::vector<double>       &rate_h,
                           std::vector<double>       &rate_hu)
      {
        for (unsigned int j = 1; j < n; ++j)
          {
            // Left state: right face of cell j-1; right state: left face of cell j.
            const double hl = h_r[j - 1], hr = h_l[j];
            const double bl = b_r[j - 1], br = b_l[j];
            const double b_star  = std::max(bl, br);
            const double hl_star = std::max(0., hl + bl - b_star);
            const double hr_star = std::max(0., hr + br - b_star);

            double fh, fq;
            interface_flux<flux_type>(
              hl_star, hl_star * u_r[j - 1], hr_star, hr_star * u_l[j], g, dry_depth, fh, fq);

            const double correction_l = 0.5 * g * (hl - hl_star) * (hl + hl_star);
            const double correction_r = 0.5 * g * (hr - hr_star) * (hr + hr_star);
            rate_h[j - 1] -= fh * inverse_width[j - 1];
            rate_h[j] += fh * inverse_width[j];
            rate_hu[j - 1] -= (fq + correction_l) * inverse_width[j - 1];
            rate_hu[j] += (fq + correction_r) * inverse_width[j];
          }
      }

      inline void
      interface_flux_dispatch(const NumericalFlux flux_type,
                              const double        h_l,
                              const double        q_l,
                              const double        h_r,
                              const double        q_r,
                              const double        g,
                              const double        dry_depth,
                              double             &flux_h,
                              double             &flux_q)
      {
        if (flux_type == NumericalFlux::roe)
          numerical_flux::roe(h_l, q_l, h_r, q_r, g, dry_depth, flux_h, flux_q);
        else
          numerical_flux::hll(h_l, q_l, h_r, q_r, g, dry_depth, flux_h, flux_q);
      }



      /**
       * The flux through one end of the channel, cell @p i of @p n: the Riemann problem
       * between the inner face state (@p h_inside, @p u_inside on the face bed @p b_inside)
       * and the ghost state of @p boundary, with the same hydrostatic reconstruction as
       * inside, added to the end cell's rates. Returns the depth flux through the end.
       */
      double
      add_boundary_flux(const WaterBoundary       &boundary,
                        const bool                 left_end,
                        const NumericalFlux        flux_type,
                        const unsigned int         i,
                        const unsigned int         n,
                        const double               h_inside,
                        const double               u_inside,
                        const double               b_inside,
                        const std::vector<double> &bed_elevation,
                        const std::vector<double> &center,
                        const std::vector<double> &inverse_width,
                        const double               t,
                        const double               g,
                        const double               dry_depth,
                        std::vector<double>       &r_h,
                        std::vector<double>       &r_hu)
      {
        const bool is_wall = boundary.type() == WaterBoundary::Type::wall;

        double b_ghost = bed_elevation[i];
        if (!is_wall && n > 1)
          {
            const unsigned int k = left_end ? 1 : n - 2;
            b_ghost              = bed_elevation[i]
                      + (bed_elevation[i] - bed_elevation[k]) / std::abs(center[i] - center[k])
                          / inverse_width[i];
          }
        double h_ghost, u_ghost;
        boundary.ghost_state(h_inside, u_inside, t, g, dry_depth, left_end, h_ghost, u_ghost);

        const double b_star       = std::max(b_inside, b_ghost);
        const double h_in_star    = std::max(0., h_inside + b_inside - b_star);
        const double h_ghost_star = std::max(0., h_ghost + b_ghost - b_star);
        const double correction   = 0.5 * g * (h_inside - h_in_star) * (h_inside + h_in_star);

        double       fh, fq;
        const double q_in    = h_in_star * u_inside;
        const double q_ghost = h_ghost_star * u_ghost;
        if (left_end)
          interface_flux_dispatch(
            flux_type, h_ghost_star, q_ghost, h_in_star, q_in, g, dry_depth, fh, fq);
        else
          interface_flux_dispatch(
            flux_type, h_in_star, q_in, h_ghost_star, q_ghost, g, dry_depth, fh, fq);
        // A wall lets no water through: make that exact, not just round-off close.
        if (is_wall)
          fh = 0.;
        if (left_end)
          {
            r_h[i] += fh * inverse_width[i];
            r_hu[i] += (fq + correction) * inverse_width[i];
          }
        else
          {
            r_h[i] -= fh * inverse_width[i];
            r_hu[i] -= (fq + correction) * inverse_width[i];
          }
        return fh;
      }
    } // namespace



    void
    ShallowWater1D::reconstruct(const std::vector<double> &depth,
                                const std::vector<double> &discharge,
                                const double               half_step)
    {
      const unsigned int n = depth.size();
      if (prm.reconstruction == Reconstruction::first_order)
        {
          for (unsigned int i = 0; i < n; ++i)
            {
              h_left_face[i] = h_right_face[i] = depth[i];
              u_left_face[i]                   = u_right_face[i]
                = depth[i] > prm.dry_depth ? discharge[i] / depth[i] : 0.;
              bed_left_face[i] = bed_right_face[i] = bed_elevation[i];
            }
          return;
        }
      // The limiter is a template argument (inlined in the cell loop): one call per value.
      const auto second_order = [&](auto limiter) {
        reconstruct_second_order<decltype(limiter)::value>(depth,
                                                           discharge,
                                                           bed_elevation,
                                                           inverse_spacing,
                                                           inverse_width,
                                                           prm.dry_depth,
                                                           prm.gravity,
                                                           half_step,
                                                           h_left_face,
                                                           h_right_face,
                                                           u_left_face,
                                                           u_right_face,
                                                           bed_left_face,
                                                           bed_right_face);
      };
      switch (prm.limiter)
        {
          case Limiter::minmod:
            second_order(std::integral_constant<Limiter, Limiter::minmod>());
            break;
          case Limiter::van_leer:
            second_order(std::integral_constant<Limiter, Limiter::van_leer>());
            break;
          case Limiter::superbee:
            second_order(std::integral_constant<Limiter, Limiter::superbee>());
            break;
        }
    }



    double
    ShallowWater1D::compute_rate(const std::vector<double> &depth,
                                 const std::vector<double> &discharge,
                                 const double               t,
                                 const double               half_step,
                                 std::vector<double>       &r_h,
                                 std::vector<double>       &r_hu)
    {
      const unsigned int n         = depth.size();
      const double       g         = prm.gravity;
      const double       dry_depth = prm.dry_depth;

      reconstruct(depth, discharge, half_step);

      // Centred part of the bed source (zero for first order, where the face beds equal
      // the cell bed): -g (h_l + h_r)/2 (B_r - B_l) / Δx.
      for (unsigned int i = 0; i < n; ++i)
        {
          r_h[i]  = 0.;
          r_hu[i] = -g * 0.5 * (h_left_face[i] + h_right_face[i])
                    * (bed_right_face[i] - bed_left_face[i]) * inverse_width[i];
        }

      if (prm.flux == NumericalFlux::roe)
        add_interface_fluxes<NumericalFlux::roe>(n,
                                                 h_left_face,
                                                 h_right_face,
                                                 u_left_face,
                                                 u_right_face,
                                                 bed_left_face,
                                                 bed_right_face,
                                                 inverse_width,
                                                 g,
                                                 dry_depth,
                                                 r_h,
                                                 r_hu);
      else
        add_interface_fluxes<NumericalFlux::hll>(n,
                                                 h_left_face,
                                                 h_right_face,
                                                 u_left_face,
                                                 u_right_face,
                                                 bed_left_face,
                                                 bed_right_face,
                                                 inverse_width,
                                                 g,
                                                 dry_depth,
                                                 r_h,
                                                 r_hu);

      // The two ends: Riemann problem between the inner face state and the ghost state of
      // the boundary condition. Behind a wall the bed is mirrored (flat); behind an open end
      // it continues with the slope of the last two cells, so that flow down a sloping
      // channel feels the full gravity in the end cells too. The hydrostatic reconstruction
      // is the same as inside.
      double inflow = 0.;
      for (const bool left_end : {true, false})
        {
          const unsigned int   i        = left_end ? 0 : n - 1;
          const double         h_inside = left_end ? h_left_face[i] : h_right_face[i];
          const double         u_inside = left_end ? u_left_face[i] : u_right_face[i];
          const double         b_inside = left_end ? bed_left_face[i] : bed_right_face[i];
          const WaterBoundary &boundary = left_end ? left_boundary : right_boundary;
          const double         fh       = add_boundary_flux(boundary,
                                              left_end,
                                              prm.flux,
                                              i,
                                              n,
                                              h_inside,
                                              u_inside,
                                              b_inside,
                                              bed_elevation,
                                              center,
                                              inverse_width,
                                              t,
                                              g,
                                              dry_depth,
                                              r_h,
                                              r_hu);
          if (left_end)
            inflow += fh;
          else
            inflow -= fh;
        }
      return inflow;
    }
  } // namespace water
} // namespace slidewave
