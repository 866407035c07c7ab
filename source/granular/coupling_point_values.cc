#include <algorithm>
#include <slidewave/granular/coupling_point_values.h>
#include <slidewave/linear_algebra/cell_evaluation.h>

namespace slidewave
{
  namespace granular
  {
    CouplingPointValues::CouplingPointValues(const grid::BackgroundGrid         &grid,
                                             const fluid::FreeSurfaceParameters &parameters,
                                             const grid::FiniteElementField     &flow,
                                             const grid::FiniteElementField     &phase,
                                             const SkeletonFields               &fields,
                                             CouplingGathers                    &gathers,
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
      , gathers(gathers)
    {
      const unsigned int n_q = quadrature.size();
      for (auto *v : {&n, &drag, &inverse_permeability, &phi})
        v->resize(n_q);
      for (auto *v : {&u, &grad_p, &grad_p_old, &v_s})
        v->resize(n_q);
      gathers.prepare(
        fields.fluid_fraction, fields.inverse_permeability, fields.solid_flux, &flow, &phase);
      // (the fluid fraction, the inverse permeability and the phase field share an element)
      dofs_scalar.resize(phase.finite_element().n_dofs_per_cell());
      AssertDimension(dofs_scalar.size(),
                      fields.fluid_fraction->finite_element().n_dofs_per_cell());
      const auto &fe_flow  = flow.finite_element();
      const auto &fe_solid = fields.solid_flux->finite_element();
      dofs_flow.resize(fe_flow.n_dofs_per_cell());
      dofs_flow_old.resize(fe_flow.n_dofs_per_cell());
      dofs_solid.resize(fe_solid.n_dofs_per_cell());
      for (unsigned int i = 0; i < fe_flow.n_dofs_per_cell(); ++i)
        flow_component.push_back(fe_flow.system_to_component_index(i).first);
      for (unsigned int i = 0; i < fe_solid.n_dofs_per_cell(); ++i)
        solid_component.push_back(fe_solid.system_to_component_index(i).first);
    }



    bool
    CouplingPointValues::reinit(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                                const unsigned int                                 cell_number)
    {
      fv_scalar.reinit(fields.fluid_fraction->cell_on(cell));
      gathers.fraction.get(cell_number, fields.fluid_fraction->values(0), dofs_scalar.data());
      linear_algebra::evaluate_scalar(fv_scalar, dofs_scalar, &n);
      if (*std::min_element(n.begin(), n.end()) >= 1.)
        return false; // no grains in the cell
      gathers.permeability.get(cell_number,
                               fields.inverse_permeability->values(0),
                               dofs_scalar.data());
      linear_algebra::evaluate_scalar(fv_scalar, dofs_scalar, &inverse_permeability);
      fv_scalar.reinit(phase.cell_on(cell));
      gathers.phase.get(cell_number, phase.values(0), dofs_scalar.data());
      linear_algebra::evaluate_scalar(fv_scalar, dofs_scalar, &phi);
      fv_flow.reinit(flow.cell_on(cell));
      gathers.flow.get(cell_number, flow.values(0), dofs_flow.data());
      if (with_old_pressure)
        gathers.flow.get(cell_number, flow.values(1), dofs_flow_old.data());
      // The pressure's gradients (component 2) and the velocity.
      linear_algebra::evaluate_component_gradient(fv_flow, flow_component, dofs_flow, 2, grad_p);
      if (with_old_pressure)
        linear_algebra::evaluate_component_gradient(
          fv_flow, flow_component, dofs_flow_old, 2, grad_p_old);
      linear_algebra::evaluate_velocity(fv_flow, flow_component, dofs_flow, &u);
      fv_solid.reinit(fields.solid_flux->cell_on(cell));
      gathers.solid.get(cell_number, fields.solid_flux->values(0), dofs_solid.data());
      linear_algebra::evaluate_velocity(fv_solid, solid_component, dofs_solid, &v_s);
      fv_grid.reinit(cell);
      finish();
      return true;
    }



    void
    CouplingPointValues::finish()
    {
      for (unsigned int q = 0; q < n.size(); ++q)
        {
          // The velocity from the flux (1 - n) v_s, and the water's drag coefficient.
          v_s[q]  = n[q] < 1. ? v_s[q] / (1. - n[q]) : dealii::Tensor<1, 2>();
          drag[q] = n[q] * n[q] * parameters.fluid.viscosity(phi[q]) * inverse_permeability[q];
        }
    }
  } // namespace granular
} // namespace slidewave
