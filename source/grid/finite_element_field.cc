#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>
#include <functional>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_evaluation.h>
#include <stdexcept>

namespace slidewave
{
  namespace grid
  {
    FiniteElementField::FiniteElementField(BackgroundGrid &grid)
      : FiniteElementField(grid, dealii::FE_Q<2>(1), 1)
    {
    }



    FiniteElementField::FiniteElementField(BackgroundGrid                 &grid,
                                           const dealii::FiniteElement<2> &element,
                                           const unsigned int              n_states)
      : grid(grid)
      , fe(element.clone())
      , owned_values(n_states)
      , ghosted_values(n_states)
    {
      Assert(n_states > 0, dealii::ExcMessage("A field keeps at least one state."));
      grid.attach(*this);
    }



    std::vector<const FiniteElementField::VectorType *>
    FiniteElementField::ghosted_pointers() const
    {
      std::vector<const VectorType *> pointers;
      for (const auto &v : ghosted_values)
        pointers.push_back(&v);
      return pointers;
    }



    std::vector<FiniteElementField::VectorType *>
    FiniteElementField::owned_pointers()
    {
      std::vector<VectorType *> pointers;
      for (auto &v : owned_values)
        pointers.push_back(&v);
      return pointers;
    }



    void
    FiniteElementField::setup_dofs()
    {
      dofs.distribute_dofs(*fe);
      integral_gather.clear();
      // Numbered along the cells' tree (p4est's space-filling curve), not in the order in
      // which refinement happened to create the cells: a grid read from a checkpoint has
      // the same numbers as the grid of the run that wrote it, so that an order-dependent
      // preconditioner (ILU) and every sum over dofs repeat the uninterrupted run exactly.
      dealii::DoFRenumbering::hierarchical(dofs);
      owned_dofs = dofs.locally_owned_dofs();
      dealii::DoFTools::extract_locally_relevant_dofs(dofs, relevant_dofs);

      hanging_node_constraints.clear();
      hanging_node_constraints.reinit(relevant_dofs);
      dealii::DoFTools::make_hanging_node_constraints(dofs, hanging_node_constraints);
      hanging_node_constraints.close();

      const MPI_Comm communicator = grid.communicator();
      for (auto &v : owned_values)
        v.reinit(owned_dofs, communicator);
      for (auto &v : ghosted_values)
        v.reinit(owned_dofs, relevant_dofs, communicator);
    }



    void
    FiniteElementField::reinit_matrix(dealii::TrilinosWrappers::SparseMatrix  &matrix,
                                      const dealii::AffineConstraints<double> &constraints) const
    {
      const MPI_Comm                 communicator = grid.communicator();
      dealii::DynamicSparsityPattern pattern(relevant_dofs);
      dealii::DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
      dealii::SparsityTools::distribute_sparsity_pattern(pattern,
                                                         owned_dofs,
                                                         communicator,
                                                         relevant_dofs);
      matrix.reinit(owned_dofs, owned_dofs, pattern, communicator);
    }



    void
    FiniteElementField::interpolate(const dealii::Function<2> &function, const unsigned int state)
    {
      dealii::VectorTools::interpolate(dofs, function, owned_values[state]);
      values_changed(state);
    }



    void
    FiniteElementField::values_changed(const unsigned int state)
    {
      // The value at a hanging node is the one of the coarse side's edge: without it the
      // field would jump across the edge (and a transfer would carry the jump along).
      hanging_node_constraints.distribute(owned_values[state]);
      ghosted_values[state] = owned_values[state];
    }



    void
    FiniteElementField::for_each_owned_cell_with_grid_dofs(
      const std::function<void(const std::vector<dealii::types::global_dof_index> &,
                               const std::vector<dealii::types::global_dof_index> &)> &f) const
    {
      const dealii::DoFHandler<2>                 &grid_dofs = grid.dof_handler();
      std::vector<dealii::types::global_dof_index> field_indices(fe->n_dofs_per_cell());
      std::vector<dealii::types::global_dof_index> grid_indices(
        grid_dofs.get_fe().n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(field_indices);
            const dealii::DoFHandler<2>::active_cell_iterator grid_cell(&grid.triangulation(),
                                                                        cell->level(),
                                                                        cell->index(),
                                                                        &grid_dofs);
            grid_cell->get_dof_indices(grid_indices);
            f(field_indices, grid_indices);
          }
    }



    void
    FiniteElementField::copy_to_grid_nodes(
      dealii::LinearAlgebra::distributed::Vector<double> &nodal) const
    {
      Assert(fe->n_components() == 1 && fe->degree == 1,
             dealii::ExcMessage("copy_to_grid_nodes() takes a scalar Q1 field"));
      nodal.zero_out_ghost_values();
      for_each_owned_cell_with_grid_dofs([&](const auto &field_indices, const auto &grid_indices) {
        for (unsigned int k = 0; k < grid_indices.size(); ++k)
          if (nodal.in_local_range(grid_indices[k]))
            nodal(grid_indices[k]) = ghosted_values[0][field_indices[k]];
      });
      nodal.update_ghost_values();
    }



    void
    FiniteElementField::copy_from_grid_nodes(
      const std::vector<const dealii::LinearAlgebra::distributed::Vector<double> *> &nodal)
    {
      Assert(fe->degree == 1 && nodal.size() == fe->n_components(),
             dealii::ExcMessage("copy_from_grid_nodes() takes a Q1 field and a vector per "
                                "component"));
      VectorType &owned = owned_values[0];
      for_each_owned_cell_with_grid_dofs([&](const auto &field_indices, const auto &grid_indices) {
        for (unsigned int k = 0; k < field_indices.size(); ++k)
          if (owned_dofs.is_element(field_indices[k]))
            {
              // The k-th shape function of the field sits at vertex v, component c.
              const auto [c, v]       = fe->system_to_component_index(k);
              owned[field_indices[k]] = (*nodal[c])(grid_indices[v]);
            }
      });
      owned.compress(dealii::VectorOperation::insert);
      values_changed(0);
    }



    double
    FiniteElementField::integral(const unsigned int state) const
    {
      Assert(fe->n_components() == 1, dealii::ExcMessage("integral() of a scalar field"));
      const dealii::QGauss<2> quadrature(2);
      dealii::FEValues<2>     fe_values(*fe,
                                    quadrature,
                                    dealii::update_values | dealii::update_JxW_values);
      std::vector<double>     u(quadrature.size()), cell_values(fe->n_dofs_per_cell());
      // The cells' values read by cached positions (the same sums as
      // FEValues::get_function_values(), bit for bit, without a lookup per value).
      if (integral_gather.empty())
        integral_gather.reinit(dofs, ghosted_values[0]);
      if (!integral_gather.matches(ghosted_values[state]))
        throw std::logic_error("FiniteElementField::integral: states of different layouts");
      double       sum         = 0.;
      unsigned int cell_number = 0;
      for_each_owned_cell_in_tree_order(dofs, [&](const auto &cell) {
        fe_values.reinit(cell);
        integral_gather.get(cell_number++, ghosted_values[state], cell_values.data());
        linear_algebra::evaluate_scalar(fe_values, cell_values, &u);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          sum += u[q] * fe_values.JxW(q);
      });
      return dealii::Utilities::MPI::sum(sum, grid.communicator());
    }



    void
    FiniteElementField::grid_ready()
    {
      // The triangulation was built anew from its coarse grid (create() or load()): the
      // DoFHandler is bound to it again.
      dofs.reinit(grid.triangulation());
      setup_dofs();
      transfer.reset();
    }



    void
    FiniteElementField::prepare_for_grid_change()
    {
      // The transfer reads the ghosted values of every owned cell now, and keeps a pointer
      // to them until the cells have changed: ghosted_values must not change before
      // grid_changed().
      transfer
        = std::make_unique<dealii::parallel::distributed::SolutionTransfer<2, VectorType>>(dofs);
      transfer->prepare_for_coarsening_and_refinement(ghosted_pointers());
    }



    void
    FiniteElementField::grid_changed()
    {
      // The transfer interpolates from the old dof indices it stored: the new dofs are
      // distributed first, then the vectors sized for them.
      setup_dofs();
      if (transfer)
        {
          std::vector<VectorType *> targets = owned_pointers();
          transfer->interpolate(targets);
          transfer.reset();
        }
      for (unsigned int s = 0; s < n_states(); ++s)
        values_changed(s);
    }



    void
    FiniteElementField::prepare_for_checkpoint()
    {
      // Per-cell values, written with the cells by the triangulation's save(): a run
      // resumed on another number of ranks gets each cell's values wherever the cell lands.
      transfer
        = std::make_unique<dealii::parallel::distributed::SolutionTransfer<2, VectorType>>(dofs);
      transfer->prepare_for_serialization(ghosted_pointers());
    }



    void
    FiniteElementField::checkpoint_loaded()
    {
      // grid_ready() has distributed the dofs on the cells that were read.
      transfer
        = std::make_unique<dealii::parallel::distributed::SolutionTransfer<2, VectorType>>(dofs);
      std::vector<VectorType *> targets = owned_pointers();
      transfer->deserialize(targets);
      transfer.reset();
      for (unsigned int s = 0; s < n_states(); ++s)
        values_changed(s);
    }



    void
    FiniteElementField::add_refinement_indicators(std::vector<bool> &keep_fine) const
    {
      // Before grid_ready() (the grid's initial adaptive levels) the field has no values:
      // it asks for nothing.
      if (!(gradient_threshold > 0.) || ghosted_values[0].size() != dofs.n_dofs()
          || !dofs.has_active_dofs())
        return;
      // The gradient of a Q1 function is largest at one of the corners of the cell; the
      // 2x2 Gauss points see it closely enough for an indicator and cost four points.
      const dealii::QGauss<2>           quadrature(2);
      dealii::FEValues<2>               fe_values(*fe, quadrature, dealii::update_gradients);
      std::vector<dealii::Tensor<1, 2>> gradients(quadrature.size());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values.get_function_gradients(ghosted_values[0], gradients);
            double steepest = 0.;
            for (const auto &gradient : gradients)
              steepest = std::max(steepest, gradient.norm());
            if (steepest * std::sqrt(cell->measure()) > gradient_threshold) // h of a square
              keep_fine[cell->active_cell_index()] = true;
          }
    }



    unsigned long long
    FiniteElementField::cell_weight(const CellIterator &cell, const CellStatus status) const
    {
      // Every cell of Q1 has the same number of dofs, whether it persists, is a parent to
      // be refined (each child weighs the same) or a parent made of coarsened children:
      // the share does not read the DoFHandler, which is out of date during the change.
      unsigned long long weight
        = static_cast<unsigned long long>(weight_per_dof) * fe->n_dofs_per_cell();
      if (user_weight)
        weight += user_weight(cell, status);
      return weight;
    }
  } // namespace grid
} // namespace slidewave
