#ifndef slidewave_granular_coupling_point_values_h
#define slidewave_granular_coupling_point_values_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/granular/coupling_gathers.h>
#include <slidewave/granular/skeleton_fluid_exchange.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    /**
     * The water's and the skeleton's fields at the quadrature points of one cell with
     * grains, as the water's own terms see them (the same quadrature, Q1: 2 x 2 Gauss
     * points, and coefficients, fluid::PorousMediumValues): the fluid fraction n, the drag
     * C = n^2 mu(phi) / kappa, the water's velocity u and pressure gradient of state 0
     * (and of state 1, the step's start, on request), and the skeleton's velocity v_s from
     * its flux, (1 - n) v_s / (1 - n) (zero where n = 1). What the exchange's force on the
     * grains (SkeletonFluidExchange::to_skeleton) and the projected increment
     * (DragProjection) integrate, with the grid's own Q1 shape functions and weights.
     * The cells, numbered in tree order, are read through @p gathers (kept by the
     * caller between steps, prepared here) and summed in FEValues' order: the numbers of
     * FEValues::get_function_values(), bit for bit, without its lookups per degree of
     * freedom in the Trilinos vectors.
     */
    class CouplingPointValues
    {
    public:
      CouplingPointValues(const grid::BackgroundGrid         &grid,
                          const fluid::FreeSurfaceParameters &parameters,
                          const grid::FiniteElementField     &flow,
                          const grid::FiniteElementField     &phase,
                          const SkeletonFields               &fields,
                          CouplingGathers                    &gathers,
                          bool                                with_old_pressure = false);

      /** The values on the owned @p cell of the grid's DoFHandler numbered @p cell_number
       *  in tree order (grid::for_each_owned_cell_in_tree_order); false (nothing more
       *  evaluated) when the cell holds no grains (n = 1 at every point). */
      bool
      reinit(const dealii::DoFHandler<2>::active_cell_iterator &cell, unsigned int cell_number);

      unsigned int
      n_points() const
      {
        return n.size();
      }

      /** The grid's Q1 shape values and JxW on the cell of the last reinit(). */
      const dealii::FEValues<2> &
      grid_values() const
      {
        return fv_grid;
      }

      std::vector<double>               n, drag;
      std::vector<dealii::Tensor<1, 2>> u, grad_p, grad_p_old, v_s;

    private:
      const fluid::FreeSurfaceParameters &parameters;
      const grid::FiniteElementField     &flow;
      const grid::FiniteElementField     &phase;
      const SkeletonFields               &fields;
      const bool                          with_old_pressure;
      dealii::QGauss<2>                   quadrature;
      dealii::FEValues<2>                 fv_flow, fv_scalar, fv_solid, fv_grid;
      std::vector<double>                 inverse_permeability, phi;
      CouplingGathers                    &gathers;
      /** A cell's values of each field, and the flow's and the flux's shape functions'
       *  components. */
      std::vector<double>       dofs_scalar, dofs_flow, dofs_flow_old, dofs_solid;
      std::vector<unsigned int> flow_component, solid_component;

      /** The drag and the solid's velocity from n, phi, 1/kappa and the flux. */
      void
      finish();
    };
  } // namespace granular
} // namespace slidewave

#endif
