#ifndef slidewave_linear_algebra_cell_evaluation_h
#define slidewave_linear_algebra_cell_evaluation_h

#include <algorithm>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <vector>

namespace slidewave
{
  namespace linear_algebra
  {
    /**
     * A finite-element field at a cell's quadrature points from the cell's degree-of-
     * freedom values (read by CellGather): sum_i U_i N_i(x_q) and its gradient, summed
     * over the shape functions in the order FEValues::get_function_values() and
     * get_function_gradients() sum them, so the numbers are the same bit for bit.
     * Outputs that are null are not computed.
     */
    inline void
    evaluate_scalar(const dealii::FEValues<2>         &fv,
                    const std::vector<double>         &dofs,
                    std::vector<double>               *values,
                    std::vector<dealii::Tensor<1, 2>> *gradients = nullptr)
    {
      const unsigned int n_q = fv.n_quadrature_points;
      if (values != nullptr)
        {
          std::fill(values->begin(), values->end(), 0.);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            for (unsigned int q = 0; q < n_q; ++q)
              (*values)[q] += dofs[i] * fv.shape_value(i, q);
        }
      if (gradients != nullptr)
        {
          std::fill(gradients->begin(), gradients->end(), dealii::Tensor<1, 2>());
          for (unsigned int i = 0; i < dofs.size(); ++i)
            for (unsigned int q = 0; q < n_q; ++q)
              (*gradients)[q] += dofs[i] * fv.shape_grad(i, q);
        }
    }



    /**
     * The velocity (components 0 and 1 of a primitive FESystem; @p component: each shape
     * function's component) at a cell's quadrature points from the cell's degree-of-
     * freedom values, with its gradient and divergence, in FEValuesViews::Vector's order
     * of summation (bit for bit the same). Outputs that are null are not computed.
     */
    inline void
    evaluate_velocity(const dealii::FEValues<2>         &fv,
                      const std::vector<unsigned int>   &component,
                      const std::vector<double>         &dofs,
                      std::vector<dealii::Tensor<1, 2>> *values,
                      std::vector<dealii::Tensor<2, 2>> *gradients   = nullptr,
                      std::vector<double>               *divergences = nullptr)
    {
      const unsigned int n_q = fv.n_quadrature_points;
      if (values != nullptr)
        std::fill(values->begin(), values->end(), dealii::Tensor<1, 2>());
      if (gradients != nullptr)
        std::fill(gradients->begin(), gradients->end(), dealii::Tensor<2, 2>());
      if (divergences != nullptr)
        std::fill(divergences->begin(), divergences->end(), 0.);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          const unsigned int a = component[i];
          if (a >= 2)
            continue;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              if (values != nullptr)
                (*values)[q][a] += dofs[i] * fv.shape_value(i, q);
              if (gradients != nullptr)
                (*gradients)[q][a] += dofs[i] * fv.shape_grad(i, q);
              if (divergences != nullptr)
                (*divergences)[q] += dofs[i] * fv.shape_grad(i, q)[a];
            }
        }
    }



    /**
     * The gradient of the scalar component @p c of a primitive FESystem (@p component:
     * each shape function's component) at a cell's quadrature points, in
     * FEValuesViews::Scalar's order of summation (shape functions whose degree of
     * freedom is zero skipped, as it skips them): the same numbers, bit for bit.
     */
    inline void
    evaluate_component_gradient(const dealii::FEValues<2>         &fv,
                                const std::vector<unsigned int>   &component,
                                const std::vector<double>         &dofs,
                                const unsigned int                 c,
                                std::vector<dealii::Tensor<1, 2>> &gradients)
    {
      std::fill(gradients.begin(), gradients.end(), dealii::Tensor<1, 2>());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        if (component[i] == c && dofs[i] != 0.)
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            gradients[q] += dofs[i] * fv.shape_grad(i, q);
    }
  } // namespace linear_algebra
} // namespace slidewave

#endif
