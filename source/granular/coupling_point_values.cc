#include <algorithm>
#include <slidewave/granular/coupling_point_values.h>

namespace slidewave
{
  namespace granular
  {
    CouplingPointValues::CouplingPointValues(const grid::BackgroundGrid         &grid,
                                             const fluid::FreeSurfaceParameters &parameters,
                                             const grid::FiniteElementField     &flow,
                                             const grid::FiniteElementField     &phase,
                                             const SkeletonFields               &fields,
                                             const bool                          with_old_pressure)
      : parameters(parameters)
      , flow(flow)
      , phase(phase)
      , fields(fields)
      , with_old_pressure(with_old_pressure)
      , quadrature(flow.finite_element().degree + 1)
      , fv_flow(flow.finite_element(), quadrature, dealii::update_values | dealii::update_gradients)
      , fv_scalar(phase.finite_element(), quadrature, dealii::update_values)
      , fv_solid(fields.solid_flux->finite_element(), quadrature, dealii::update_values)
      , fv_grid(grid.dof_handler().get_fe(),
                quadrature,
                dealii::update_values | dealii::update_JxW_values)
    {
      const unsigned int n_q = quadrature.size();
      for (auto *v : {&n, &drag, &inverse_permeability, &phi})
        v->resize(n_q);
      for (auto *v : {&u, &grad_p, &grad_p_old, &v_s})
        v->resize(n_q);
    }



    bool
    CouplingPointValues::reinit(const dealii::DoFHandler<2>::active_cell_iterator &cell)
    {
      const dealii::FEValuesExtractors::Vector velocity(0);
      const dealii::FEValuesExtractors::Scalar pressure(2);
      fv_scalar.reinit(fields.fluid_fraction->cell_on(cell));
      fv_scalar.get_function_values(fields.fluid_fraction->values(0), n);
      if (*std::min_element(n.begin(), n.end()) >= 1.)
        return false; // no grains in the cell
      fv_scalar.get_function_values(fields.inverse_permeability->values(0), inverse_permeability);
      fv_scalar.reinit(phase.cell_on(cell));
      fv_scalar.get_function_values(phase.values(0), phi);
      fv_flow.reinit(flow.cell_on(cell));
      fv_flow[pressure].get_function_gradients(flow.values(0), grad_p);
      if (with_old_pressure)
        fv_flow[pressure].get_function_gradients(flow.values(1), grad_p_old);
      fv_flow[velocity].get_function_values(flow.values(0), u);
      fv_solid.reinit(fields.solid_flux->cell_on(cell));
      fv_solid[velocity].get_function_values(fields.solid_flux->values(0), v_s);
      fv_grid.reinit(cell);
      for (unsigned int q = 0; q < n.size(); ++q)
        {
          // The velocity from the flux (1 - n) v_s, and the water's drag coefficient.
          v_s[q]  = n[q] < 1. ? v_s[q] / (1. - n[q]) : dealii::Tensor<1, 2>();
          drag[q] = n[q] * n[q] * parameters.fluid.viscosity(phi[q]) * inverse_permeability[q];
        }
      return true;
    }
  } // namespace granular
} // namespace slidewave
