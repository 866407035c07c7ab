#ifndef slidewave_fluid_phase_field_system_h
#define slidewave_fluid_phase_field_system_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/fluid/navier_stokes_system.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <slidewave/linear_algebra/cell_scatter.h>
#include <slidewave/linear_algebra/incomplete_lu.h>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The phase field phi (1 water, 0 air, the surface at 0.5) carried by the flow
     * (paper 002, §3.4 and Appendix B): the conservative Allen-Cahn equation
     *
     *   d phi/dt + div(u phi) = div( gamma (epsilon grad phi - phi (1 - phi) n) ),
     *   n = grad phi / |grad phi|,
     *
     * (Chiu and Lin 2011), or paper 002's Allen-Cahn form with the reaction term
     * - gamma phi (1 - phi) (1 - 2 phi) / epsilon in place of the divergence of the
     * sharpening flux. Both keep the profile phi = 1 / (1 + exp(-d / epsilon)) of a flat
     * surface. The advection is in divergence form (u . grad phi + phi div u; the same
     * for a divergence-free velocity): summed over the test functions the discrete
     * equation leaves only the flux through the sides, so the conservative form keeps the
     * integral of phi (the water volume) to the solver's tolerance although the
     * stabilized velocity is divergence free only weakly; the other form shrinks curved
     * surfaces.
     *
     * Q1 on the background grid (the phase field's grid::FiniteElementField), SUPG with
     * tau_phi (paper 002, Eq. 95), the theta-scheme for advection and diffusion with the
     * Adams-Bashforth advection velocity, the sharpening or reaction term explicit. On an
     * inflow side the entering water fraction is imposed weakly and upwind. One
     * GMRES solve with ILU per step; the system follows the grid as the flow's does.
     *
     * <h3>In the pores of a solid (set_porous_medium())</h3>
     * There u is the pore velocity and the water's volume is that of n phi, with n the
     * fluid fraction. The water's and the solid's balances, d(n phi)/dt + div(n u phi) = 0
     * and dn/dt = div((1 - n) v_s), give
     *
     *   n d phi/dt + n u . grad phi + phi R
     *     = div(n gamma (epsilon grad phi - phi (1 - phi) nhat)),
     *   R = div(n u) + div((1 - n) v_s) = n div u + u . grad n + div((1 - n) v_s)
     *
     * (nhat the interface's normal), R the mixture's divergence, which the flow's
     * continuity makes zero (weakly) with the velocities it solved with. The phase field's
     * step comes before the flow's (FreeSurfaceSolver::advance()): it takes u^n and the
     * solid's flux of the step's start, (1 - n) v^n, the one the last flow solved with (a
     * skeleton whose momentum the flow eliminates hands it over apart from its predicted
     * v*, SkeletonFluidExchange), with this step's n: R is then small, not zero. With
     * n = 1 and no solid, R = div u and the equation is the open water's above, bit for
     * bit (on a build that contracts n * a + b the same way as a + b, as this one). The
     * advection n u . grad phi + phi div(n u) = div(n u phi) again leaves only the flux
     * n u . n phi through the sides when summed over the test functions, so the integral of
     * n phi (water_volume()) is kept in a fixed solid to the solver's tolerance; in a
     * moving one, from one step's row to the next, it changes by the integral of
     * phi^k (n^k - n^{k-1}) (the fluid fraction handed over at the step's start against
     * the last one: the points' last step) minus dt times that of phi^theta
     * div((1 - n^k) v^n), which cancel to first order. Without the porous terms, the
     * divergence form would read div u = -(u . grad n + div((1 - n) v_s)) / n as a source:
     * it drained the water where it entered a solid (phi fell to 0.81 in the seepage test).
     * The SUPG residual leaves out -kappa grad n . grad phi, the part of div(n kappa grad
     * phi) that Q1's second derivatives miss too.
     */
    class PhaseFieldSystem : public grid::GridFollower
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      PhaseFieldSystem(grid::BackgroundGrid           &grid,
                       const grid::FiniteElementField &flow,
                       grid::FiniteElementField       &phase,
                       const FreeSurfaceParameters    &parameters);

      /**
       * One step from phi^n to phi^{n+1} with the flow's states u^n, u^{n-1} and the
       * profile velocity @p gamma [m/s]: keeps phi^n (previous()) and writes phi^{n+1}
       * into the phase field (collective). Throws RunFailure when GMRES fails.
       */
      SolveReport
      step(const StepLengths &lengths, double gamma);

      /** The porous solid in the flow (its fluid fraction and solid flux: the fields must
       *  live on the same grid and outlive this object); default: none. */
      void
      set_porous_medium(const PorousMedium &medium);

      /** The water's volume: the integral of n phi, or of phi without a porous solid
       *  [m^2 per m of width] (collective). */
      double
      water_volume() const;

      /** The water that left through the sides in the last step [m^2 per m of width]
       *  (negative: it entered), the flux of the discrete equation: the water volume
       *  changes by exactly minus this (to the solver's tolerance; the flux n u . n phi in
       *  the pores, where the volume balance is exact in a fixed solid only). */
      double
      last_outflow() const
      {
        return outflow;
      }

      /** phi^n of the last step (ghosted, the phase field's dofs). */
      const VectorType &
      previous() const
      {
        return phase_old;
      }

      void
      grid_ready() override;

      void
      grid_changed() override;

    private:
      void
      setup_system();

      /** The Gauss points per direction of the cells' and sides' quadratures: enough for
       *  the advective flux to sum exactly to the sides' flux (the volume's balance). */
      unsigned int
      gauss_points() const;

      void
      assemble(const StepLengths &lengths, double gamma);

      /** dt times the water flux through the open and inflow sides in the step just
       *  solved (collective, summed in tree order). */
      double
      compute_outflow(const StepLengths &lengths) const;

      grid::BackgroundGrid           &grid;
      const grid::FiniteElementField &flow;
      grid::FiniteElementField       &phase;
      const FreeSurfaceParameters    &parameters;
      /** The fluid fraction and the solid's flux only (no drag). */
      PorousMedium                           porous;
      dealii::TrilinosWrappers::SparseMatrix matrix;
      /** ILU(0), its symbolic part kept until the next grid change. */
      std::unique_ptr<linear_algebra::IncompleteLU> ilu;
      /** Where the owned cells' entries and values sit in the matrix, the right-hand
       *  side and the phase field's, flow's and porous solid's ghosted vectors (cleared on
       *  grid changes and with a new porous solid, rebuilt by the next assembly). */
      linear_algebra::CellScatter scatter;
      linear_algebra::CellGather  phase_gather, flow_gather;
      PorousMediumGathers         porous_gathers;
      VectorType                  rhs, solution, phase_old;
      double                      outflow = 0.;
    };
  } // namespace fluid
} // namespace slidewave

#endif
