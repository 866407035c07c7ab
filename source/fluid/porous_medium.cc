#include <deal.II/fe/fe_values_extractors.h>
#include <slidewave/fluid/porous_medium.h>
#include <slidewave/linear_algebra/cell_evaluation.h>

namespace slidewave
{
  namespace fluid
  {
    PorousMediumValues::PorousMediumValues(const grid::BackgroundGrid  &grid,
                                           const PorousMedium          &medium,
                                           const dealii::Quadrature<2> &quadrature,
                                           const dealii::Quadrature<1> &face_quadrature,
                                           PorousMediumGathers         *gathers)
      : grid(grid)
      , medium(medium)
      , coefficients(quadrature.size())
      , face_coefficients(face_quadrature.size())
      , gathers(gathers)
    {
      if (gathers != nullptr)
        {
          const grid::FiniteElementField *fields[3]
            = {medium.fluid_fraction, medium.inverse_permeability, medium.solid_flux};
          std::vector<double> *dofs[3] = {&dofs_fraction, &dofs_permeability, &dofs_flux};
          for (unsigned int f = 0; f < 3; ++f)
            if (fields[f] != nullptr)
              {
                linear_algebra::CellGather &gather = (*gathers)[f];
                // (again when the field's layout changed: the grid adapted)
                if (gather.empty() || !gather.matches(fields[f]->values(0)))
                  gather.reinit(fields[f]->dof_handler(), fields[f]->values(0));
                dofs[f]->resize(fields[f]->finite_element().n_dofs_per_cell());
              }
          if (medium.solid_flux != nullptr)
            for (unsigned int i = 0; i < dofs_flux.size(); ++i)
              flux_component.push_back(
                medium.solid_flux->finite_element().system_to_component_index(i).first);
        }
      const grid::FiniteElementField *scalar
        = medium.fluid_fraction != nullptr ? medium.fluid_fraction : medium.inverse_permeability;
      const auto flags = dealii::update_values | dealii::update_gradients;
      if (scalar != nullptr)
        {
          fv_scalar
            = std::make_unique<dealii::FEValues<2>>(scalar->finite_element(), quadrature, flags);
          ff_scalar = std::make_unique<dealii::FEFaceValues<2>>(scalar->finite_element(),
                                                                face_quadrature,
                                                                flags);
        }
      if (medium.solid_flux != nullptr)
        {
          fv_solid = std::make_unique<dealii::FEValues<2>>(medium.solid_flux->finite_element(),
                                                           quadrature,
                                                           flags);
          ff_solid = std::make_unique<dealii::FEFaceValues<2>>(medium.solid_flux->finite_element(),
                                                               face_quadrature,
                                                               flags);
        }
    }



    void
    PorousMediumValues::evaluate(const dealii::Triangulation<2>::active_cell_iterator &cell,
                                 const int                                             face,
                                 const double                                          dt,
                                 const std::vector<double>                            &mu,
                                 const int                                             cell_number)
    {
      Assert(&cell->get_triangulation() == &grid.triangulation(),
             dealii::ExcMessage("PorousMediumValues: a cell of another triangulation"));
      auto              &result = face < 0 ? coefficients : face_coefficients;
      const unsigned int n_q    = result.size();
      n.assign(n_q, 1.);
      inverse_permeability.assign(n_q, 0.);
      div_flux.assign(n_q, 0.);
      grad_n.assign(n_q, dealii::Tensor<1, 2>());
      flux.assign(n_q, dealii::Tensor<1, 2>());
      // The cell's (or face's) values of a field.
      const auto values_on = [&](const grid::FiniteElementField &field,
                                 const bool vector) -> dealii::FEValuesBase<2> & {
        if (face < 0)
          {
            auto &fv = vector ? *fv_solid : *fv_scalar;
            fv.reinit(field.cell_on(cell));
            return fv;
          }
        auto &ff = vector ? *ff_solid : *ff_scalar;
        ff.reinit(field.cell_on(cell), static_cast<unsigned int>(face));
        return ff;
      };
      const dealii::FEValuesExtractors::Vector velocity(0);
      if (face < 0 && cell_number >= 0 && gathers != nullptr)
        {
          // The fields read by the gathers, summed as FEValues sums them (bit for bit the
          // same); the scalar fields share one element and so one set of shape functions.
          const unsigned int number = static_cast<unsigned int>(cell_number);
          if (fv_scalar != nullptr)
            values_on(medium.fluid_fraction != nullptr ? *medium.fluid_fraction :
                                                         *medium.inverse_permeability,
                      false);
          if (medium.fluid_fraction != nullptr)
            {
              (*gathers)[0].get(number, medium.fluid_fraction->values(0), dofs_fraction.data());
              linear_algebra::evaluate_scalar(*fv_scalar, dofs_fraction, &n, &grad_n);
            }
          if (medium.inverse_permeability != nullptr)
            {
              (*gathers)[1].get(number,
                                medium.inverse_permeability->values(0),
                                dofs_permeability.data());
              linear_algebra::evaluate_scalar(*fv_scalar, dofs_permeability, &inverse_permeability);
            }
          if (medium.solid_flux != nullptr)
            {
              values_on(*medium.solid_flux, true);
              (*gathers)[2].get(number, medium.solid_flux->values(0), dofs_flux.data());
              linear_algebra::evaluate_velocity(
                *fv_solid, flux_component, dofs_flux, &flux, nullptr, &div_flux);
            }
        }
      else
        {
          if (medium.fluid_fraction != nullptr)
            {
              auto &fv = values_on(*medium.fluid_fraction, false);
              fv.get_function_values(medium.fluid_fraction->values(0), n);
              fv.get_function_gradients(medium.fluid_fraction->values(0), grad_n);
            }
          if (medium.inverse_permeability != nullptr)
            values_on(*medium.inverse_permeability, false)
              .get_function_values(medium.inverse_permeability->values(0), inverse_permeability);
          if (medium.solid_flux != nullptr)
            {
              auto &fv = values_on(*medium.solid_flux, true);
              fv[velocity].get_function_values(medium.solid_flux->values(0), flux);
              fv[velocity].get_function_divergences(medium.solid_flux->values(0), div_flux);
            }
        }
      const double rho_s = medium.grain_density;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          PorousCoefficients &c = result[q];
          c.n                   = n[q];
          c.grad_n              = grad_n[q];
          // The solid's velocity from its flux (1 - n) v_s: a node the grains barely touch
          // hands over a flux as small as its grains, whatever its velocity.
          const double solid_share = 1. - n[q];
          c.v_s              = solid_share > 1e-12 ? flux[q] / solid_share : dealii::Tensor<1, 2>();
          const double C     = n[q] * n[q] * mu[q] * inverse_permeability[q];
          const double solid = 1. - n[q];
          c.solid_divergence = div_flux[q];
          c.drag             = C;
          c.drag_coefficient = C;
          if (rho_s > 0.)
            {
              // The skeleton's momentum eliminated (PorousMedium): no grains (solid = 0)
              // leaves the open water's equations.
              const double denominator = rho_s * solid + dt * C;
              const double Delta       = denominator > 0. ? dt / denominator : 0.;
              const double s           = C * Delta;
              c.drag                   = C * (1. - s);
              c.correction_flux        = -s * flux[q];
              c.pressure_share         = s * solid;
              c.pressure_diffusion     = solid * solid * Delta;
            }
        }
    }



    void
    PorousMediumValues::add_open_side_flux(const dealii::FEFaceValues<2>           &fv_face,
                                           const std::vector<dealii::Tensor<1, 2>> &grad_p_n,
                                           dealii::FullMatrix<double>              &local_matrix,
                                           dealii::Vector<double>                  &local_rhs) const
    {
      const dealii::FEValuesExtractors::Vector velocity(0);
      const dealii::FEValuesExtractors::Scalar pressure(2);
      for (unsigned int q = 0; q < face_coefficients.size(); ++q)
        {
          const PorousCoefficients &c = face_coefficients[q];
          if (c.pressure_share == 0. && c.pressure_diffusion == 0.)
            continue;
          const dealii::Tensor<1, 2> &normal = fv_face.normal_vector(q);
          const double                JxW    = fv_face.JxW(q);
          for (unsigned int i = 0; i < local_rhs.size(); ++i)
            {
              const double test = fv_face[pressure].value(i, q);
              if (test == 0.)
                continue;
              for (unsigned int j = 0; j < local_rhs.size(); ++j)
                local_matrix(i, j)
                  += test
                     * (c.pressure_share * (fv_face[velocity].value(j, q) * normal)
                        - c.pressure_diffusion * (fv_face[pressure].gradient(j, q) * normal))
                     * JxW;
              local_rhs(i)
                -= test * ((c.correction_flux + c.pressure_diffusion * grad_p_n[q]) * normal) * JxW;
            }
        }
    }
  } // namespace fluid
} // namespace slidewave
