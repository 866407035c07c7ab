#ifndef slidewave_fluid_velocity_subscales_h
#define slidewave_fluid_velocity_subscales_h

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The dynamic velocity subscale of the flow's SUPG and PSPG (Codina, Principe,
     * Guasch and Badia 2007): u' at every quadrature point of the flow's cells, kept from
     * step to step and integrated in time,
     *
     *   rho (u'^{n+theta} - u'^n) / (theta dt) + rho u'^{n+theta} / tau_s = -R(u_h, p_h),
     *
     * R the momentum residual at t^{n+theta} that the quasi-static form uses, tau_s
     * Tezduyar's parameter without its time step. So
     *
     *   u'^{n+theta} = -(tau_t / rho) (R - rho u'^n / (theta dt)),
     *   tau_t = 1 / (1 / (theta dt) + 1 / tau_s),
     *
     * and the stabilization terms take tau_t in place of tau_m and the known part
     * rho u'^n / (theta dt) in their residual. In a steady flow u' tends to -tau_s R / rho,
     * whatever the step: PSPG keeps its strength when the steps are far below the flow's
     * own, where the quasi-static tau_m ~ dt / 2 lets an odd-even pressure mode grow
     * (Bochev, Gunzburger and Lehoucq 2007). u'^{n+theta} is kept as the new u'^{n+1}
     * (the subscale's backward Euler over theta dt: no oscillation of Crank-Nicolson
     * on its stiff relaxation when dt >> tau_s). The subscale's time derivative in the
     * Galerkin momentum equation is neglected.
     *
     * The values live in a discontinuous field (two components, FE_DGQArbitraryNodes on
     * the flow's Gauss points: the nodal values are the values at the quadrature points),
     * which the grid carries through refinement (interpolated) and checkpoints. Only a
     * scene with 'Subscales = dynamic' creates one.
     */
    class VelocitySubscales
    {
    public:
      /** What the assembly knows of the residual at a quadrature point: R(u, p) =
       *  mass u + (grad u) advection + pressure_factor grad p - known, and tau_t / rho. */
      struct Terms
      {
        double               mass = 0., pressure_factor = 0., tau_over_rho = 0.;
        dealii::Tensor<1, 2> advection, known;
      };

      /** The subscale of a flow of element degree @p degree (QGauss(degree + 1) points);
       *  attaches its field to @p grid (create it before the grid's create() or load()). */
      VelocitySubscales(grid::BackgroundGrid &grid, unsigned int degree);

      /** u'^n at the quadrature points of the owned cell @p cell (any iterator on the
       *  grid's triangulation) into @p values. */
      template <class Cell>
      void
      read(const Cell &cell, std::vector<dealii::Tensor<1, 2>> &values) const
      {
        read_cell(field.cell_on(cell), values);
      }

      /** Sizes the store of the terms for @p n_cells owned cells of the assembly. */
      void
      begin_assembly(unsigned int n_cells);

      /** The terms of quadrature point @p q of the assembly's @p cell_number-th cell. */
      void
      record(const unsigned int cell_number, const unsigned int q, const Terms &terms)
      {
        store[cell_number * n_q + q] = terms;
      }

      /**
       * After the solve: u'^{n+1} from the new velocity and pressure (state 0 of @p flow,
       * read through @p gather, the assembly's cells in its tree order) and the recorded
       * terms (collective).
       */
      void
      update(const grid::FiniteElementField &flow, const linear_algebra::CellGather &gather);

      /** Adds to @p estimate what the subscales of @p n_cells cells take when @p parameters
       *  (of the subsection @p section) ask for dynamic ones: two components per Gauss
       *  point, each an owned and a ghosted vector entry and a dof index, and the
       *  assembly's terms there. */
      static void
      add_to_memory_estimate(core::MemoryEstimate        &estimate,
                             const FreeSurfaceParameters &parameters,
                             const std::string           &section,
                             const double                 n_cells)
      {
        if (!parameters.dynamic_subscales)
          return;
        const double points = (parameters.element_degree + 1.) * (parameters.element_degree + 1.);
        estimate.add("velocity subscales at the grid cells' Gauss points",
                     n_cells,
                     points * (2. * (8. + 8. + 8.) + sizeof(Terms)),
                     section + "/Stabilization/Subscales",
                     "dynamic");
      }

    private:
      void
      read_cell(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                std::vector<dealii::Tensor<1, 2>>                 &values) const;

      grid::FiniteElementField field;
      unsigned int             degree, n_q;
      /** Each of the field's cell dofs: its component and its quadrature point. */
      std::vector<unsigned int> dof_component, dof_point;
      /** A cell's dof indices (scratch of read_cell() and update()). */
      mutable std::vector<dealii::types::global_dof_index> cell_indices;
      std::vector<Terms>                                   store;
    };
  } // namespace fluid
} // namespace slidewave

#endif
