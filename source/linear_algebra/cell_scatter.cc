#include <algorithm>
#include <limits>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_scatter.h>

namespace slidewave
{
  namespace linear_algebra
  {
    void
    CellScatter::reinit(const dealii::DoFHandler<2>                  &dofs,
                        const dealii::AffineConstraints<double>      &constraints,
                        const dealii::TrilinosWrappers::SparseMatrix &matrix,
                        const VectorType                             &rhs)
    {
      using IntType                   = dealii::TrilinosWrappers::types::int_type;
      const Epetra_CrsMatrix &A       = matrix.trilinos_matrix();
      const Epetra_BlockMap  &rhs_map = rhs.trilinos_vector().Map();
      n_dofs                          = dofs.get_fe().n_dofs_per_cell();
      clear();
      std::vector<dealii::types::global_dof_index> indices(n_dofs);
      std::vector<int>                             cell_rows(n_dofs), cell_rhs(n_dofs);
      std::vector<int>                             local_columns(n_dofs);
      std::vector<std::uint16_t>                   cell_columns(n_dofs * n_dofs);
      grid::for_each_owned_cell_in_tree_order(dofs, [&](const auto &cell) {
        cell->get_dof_indices(indices);
        bool direct = true;
        for (unsigned int i = 0; i < n_dofs && direct; ++i)
          {
            const auto index = static_cast<IntType>(indices[i]);
            cell_rows[i]     = A.RowMap().LID(index);
            cell_rhs[i]      = rhs_map.LID(index);
            local_columns[i] = A.ColMap().LID(index);
            direct           = !constraints.is_constrained(indices[i]) && cell_rows[i] >= 0
                     && cell_rhs[i] >= 0 && local_columns[i] >= 0;
          }
        for (unsigned int i = 0; i < n_dofs && direct; ++i)
          {
            int     n_entries = 0;
            double *values    = nullptr;
            int    *row       = nullptr;
            A.ExtractMyRowView(cell_rows[i], n_entries, values, row);
            for (unsigned int j = 0; j < n_dofs && direct; ++j)
              {
                const int *at = std::find(row, row + n_entries, local_columns[j]);
                direct
                  = at != row + n_entries && n_entries <= std::numeric_limits<std::uint16_t>::max();
                if (direct)
                  cell_columns[i * n_dofs + j] = static_cast<std::uint16_t>(at - row);
              }
          }
        if (direct)
          {
            first_row.push_back(static_cast<int>(rows.size()));
            rows.insert(rows.end(), cell_rows.begin(), cell_rows.end());
            rhs_rows.insert(rhs_rows.end(), cell_rhs.begin(), cell_rhs.end());
            columns.insert(columns.end(), cell_columns.begin(), cell_columns.end());
          }
        else
          first_row.push_back(-1);
      });
    }



    void
    CellScatter::add(const unsigned int                                  cell,
                     const dealii::FullMatrix<double>                   &local_matrix,
                     const dealii::Vector<double>                       &local_rhs,
                     const std::vector<dealii::types::global_dof_index> &indices,
                     const dealii::AffineConstraints<double>            &constraints,
                     dealii::TrilinosWrappers::SparseMatrix             &matrix,
                     VectorType                                         &rhs) const
    {
      const int first = first_row[cell];
      if (first < 0)
        {
          constraints.distribute_local_to_global(local_matrix, local_rhs, indices, matrix, rhs);
          return;
        }
      add_rows(first, local_matrix, matrix);
      double *rhs_local = rhs.trilinos_vector()[0];
      for (unsigned int i = 0; i < n_dofs; ++i)
        rhs_local[rhs_rows[first + i]] += local_rhs(i);
    }



    void
    CellScatter::add_matrix(const unsigned int                                  cell,
                            const dealii::FullMatrix<double>                   &local_matrix,
                            const std::vector<dealii::types::global_dof_index> &indices,
                            const dealii::AffineConstraints<double>            &constraints,
                            dealii::TrilinosWrappers::SparseMatrix             &matrix) const
    {
      const int first = first_row[cell];
      if (first < 0)
        constraints.distribute_local_to_global(local_matrix, indices, matrix);
      else
        add_rows(first, local_matrix, matrix);
    }



    void
    CellScatter::add_rows(const int                               first,
                          const dealii::FullMatrix<double>       &local_matrix,
                          dealii::TrilinosWrappers::SparseMatrix &matrix) const
    {
      const Epetra_CrsMatrix &A        = matrix.trilinos_matrix();
      const std::uint16_t    *position = &columns[static_cast<std::size_t>(first) * n_dofs];
      for (unsigned int i = 0; i < n_dofs; ++i, position += n_dofs)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          int    *row       = nullptr;
          A.ExtractMyRowView(rows[first + i], n_entries, values, row);
          for (unsigned int j = 0; j < n_dofs; ++j)
            values[position[j]] += local_matrix(i, j);
        }
    }



    double
    CellScatter::direct_fraction() const
    {
      if (first_row.empty())
        return 0.;
      return static_cast<double>(std::count_if(first_row.begin(),
                                               first_row.end(),
                                               [](const int f) { return f >= 0; }))
             / first_row.size();
    }
  } // namespace linear_algebra
} // namespace slidewave
