#ifndef slidewave_water_shallow_water_1d_h
#define slidewave_water_shallow_water_1d_h

#include <deal.II/base/parameter_handler.h>
#include <slidewave/water/shallow_water_parameters.h>
#include <slidewave/water/water_boundary.h>
#include <slidewave/water/water_mesh.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace water
  {
    /**
     * The 1D shallow water equations (paper 000, Eqs. 9 and 24) on non-uniform control
     * volumes, solved with a Godunov-type finite-volume scheme:
     *
     * - fluxes: Roe (Eqs. 30–32, with an entropy fix) or HLL;
     * - first order, or second order by MUSCL reconstruction of depth, free surface and
     *   velocity on non-uniform cells with a minmod, van Leer or superbee limiter;
     * - bed source: hydrostatic reconstruction (Audusse et al. 2004) at the interfaces plus a
     *   centred cell term, so that a lake at rest, wet or partly dry, stays at rest to
     *   round-off on any mesh, and depths stay non-negative;
     * - time: forward Euler (paper, Eq. 28; with second order, the face values get a
     *   Hancock half-step predictor, MUSCL-Hancock) or SSP-RK2 (Heun), then Manning friction
     *   semi-implicitly (Eqs. 35–36), stable for any depth;
     * - time step: the CFL condition of Eq. 37 cell by cell, dt = C min_i Δx_i / (|u_i| + c_i).
     *
     * The bed B is given per cell and can be replaced at any time (set_bed()): the water
     * depth h is kept, so the free surface moves with the bed. The class holds all its work
     * arrays: advance() allocates nothing.
     */
    class ShallowWater1D
    {
    public:
      ShallowWater1D(const WaterMesh              &mesh,
                     const ShallowWaterParameters &parameters,
                     const WaterBoundary          &left_boundary  = WaterBoundary(),
                     const WaterBoundary          &right_boundary = WaterBoundary());

      /** Sets the state (depth h and discharge hu per cell). */
      void
      set_state(const std::vector<double> &depth, const std::vector<double> &discharge);

      /**
       * Sets the whole state exactly as it was saved (a run resumed from a checkpoint):
       * depth, discharge, bed and the volume that entered through the ends, bit for bit.
       */
      void
      restore(const std::vector<double> &depth,
              const std::vector<double> &discharge,
              const std::vector<double> &bed,
              double                     net_boundary_inflow);

      /** Replaces the bed elevation B per cell, keeping the depth (the water volume). */
      void
      set_bed(const std::vector<double> &bed);

      /** The time step allowed by the CFL condition (Eq. 37); +infinity for still water. */
      double
      stable_time_step() const;

      /** Advances the state from time @p t by @p dt (boundary values are taken at t). */
      void
      advance(double t, double dt);

      /**
       * Scans the state for non-finite values and negative depths. Returns the index of the
       * first bad cell, or n_cells() when all is well.
       */
      unsigned int
      find_invalid_cell() const;

      /** "negative water depth in water cell I (x = X m): h = H, hu = Q" (or non-finite). */
      std::string
      describe_invalid_cell(unsigned int i) const;

      const WaterMesh &
      mesh() const
      {
        return water_mesh;
      }

      const ShallowWaterParameters &
      parameters() const
      {
        return prm;
      }

      unsigned int
      n_cells() const
      {
        return water_mesh.n_cells();
      }

      const std::vector<double> &
      depth() const
      {
        return h;
      }

      const std::vector<double> &
      discharge() const
      {
        return hu;
      }

      const std::vector<double> &
      bed() const
      {
        return bed_elevation;
      }

      /** Velocity of cell @p i; zero in dry cells. */
      double
      velocity(unsigned int i) const
      {
        return h[i] > prm.dry_depth ? hu[i] / h[i] : 0.;
      }

      /** Total water volume per unit width Σ h_i Δx_i [m^2]. */
      double
      water_volume() const;

      /** Volume per unit width that entered through the two ends since the start [m^2]. */
      double
      net_boundary_inflow() const
      {
        return boundary_inflow;
      }

      /** Largest |u| over the wet cells [m/s]. */
      double
      max_speed() const;

      /** Largest free-surface elevation η = h + B over the wet cells [m]. */
      double
      max_free_surface() const;

      /** η interpolated linearly between cell centres at @p x (constant beyond them). */
      double
      free_surface_at(double x) const;

    private:
      /**
       * The rate of change dU/dt of the hyperbolic part with the bed source, for the state
       * (@p depth, @p discharge) with boundary values at time @p t. @p half_step > 0 turns
       * on the Hancock predictor of the face values (forward Euler). Returns the net
       * volume inflow rate through the two ends.
       */
      double
      compute_rate(const std::vector<double> &depth,
                   const std::vector<double> &discharge,
                   double                     t,
                   double                     half_step,
                   std::vector<double>       &rate_h,
                   std::vector<double>       &rate_hu);

      /** Face values of h, u and B on both sides of every cell. */
      void
      reconstruct(const std::vector<double> &depth,
                  const std::vector<double> &discharge,
                  double                     half_step);

      /** Zero discharge in dry cells, round-off negatives to zero. */
      void
      clean_dry_cells(std::vector<double> &depth, std::vector<double> &discharge) const;

      /** Manning friction, semi-implicit (paper 000, Eq. 36). */
      void
      apply_friction(double dt);

      WaterMesh              water_mesh;
      ShallowWaterParameters prm;
      WaterBoundary          left_boundary;
      WaterBoundary          right_boundary;

      std::vector<double> inverse_width;
      std::vector<double> center;
      /** 1 / (x_{i+1} - x_i), the inverse distances between neighbouring centres. */
      std::vector<double> inverse_spacing;

      std::vector<double> h, hu, bed_elevation;
      double              boundary_inflow = 0.;

      // Work arrays: stage state, rates, and face values (index i: faces of cell i, the
      // left face x_{i-1/2}^+ and the right face x_{i+1/2}^-).
      std::vector<double> h_stage, hu_stage, rate_h, rate_hu;
      std::vector<double> h_left_face, h_right_face, u_left_face, u_right_face;
      std::vector<double> bed_left_face, bed_right_face;
    };
  } // namespace water
} // namespace slidewave

#endif
