#ifndef slidewave_grid_finite_element_field_h
#define slidewave_grid_finite_element_field_h

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/linear_algebra/cell_gather.h>

namespace slidewave
{
  namespace grid
  {
    /**
     * A continuous finite-element field living on the background grid and following
     * every event of its cells: by default the scalar Q1 Lagrange element with one vector
     * of values; a grid physics solved by finite elements gives its own element (an
     * FESystem such as velocity and pressure of the free-surface flow) and the number of
     * states it keeps (the values of the last steps a time scheme needs), and every state
     * travels with the cells.
     *
     * The field has its own DoFHandler on the grid's triangulation (the grid's own Q1
     * DoFHandler belongs to the material point method and is renumbered at the grid's
     * will), its hanging-node constraints, and its values in two Trilinos vectors: the
     * locally owned entries (what a solver writes) and a ghosted copy (what assembly,
     * the transfer and the indicators read). Through the grid's events:
     * - grid_ready(): the dofs are distributed, the constraints built, the vectors sized
     *   (zero);
     * - prepare_for_grid_change() / grid_changed(): deal.II's
     *   parallel::distributed::SolutionTransfer packs the values per cell before the
     *   cells change and interpolates them onto the new cells (Q1 interpolation from the
     *   parent to the children, the children's vertex values for the parent; unchanged
     *   cells keep their values on whichever rank they land), then the constraints make the
     *   field continuous at hanging nodes;
     * - prepare_for_checkpoint() / checkpoint_loaded(): the same per-cell values are
     *   written with the grid's cells and read back, on any number of ranks.
     *
     * It may also ask for fine cells where it is steep (|grad u| h above a threshold) and
     * add its work to the cells' partitioning weight (a weight per degree of freedom of
     * the cell, plus an optional user weight).
     */
    class FiniteElementField : public GridFollower
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      /** A user share of a cell's partitioning weight (see GridFollower::cell_weight()). */
      using CellWeight = std::function<unsigned long long(const CellIterator &, CellStatus)>;

      /** A scalar Q1 field on @p grid; attaches itself to the grid, so create it before
       *  the grid's create() or load(). The field is zero until interpolate() or a
       *  checkpoint. */
      explicit FiniteElementField(BackgroundGrid &grid);

      /** A field of the element @p element (copied) with @p n_states vectors of values
       *  (state 0 the newest), all of which follow the cells. */
      FiniteElementField(BackgroundGrid                 &grid,
                         const dealii::FiniteElement<2> &element,
                         unsigned int                    n_states);

      FiniteElementField(const FiniteElementField &) = delete;
      FiniteElementField &
      operator=(const FiniteElementField &)
        = delete;

      /** Sets state @p state to the interpolant of @p function (nodal values), made
       *  continuous at hanging nodes (collective). */
      void
      interpolate(const dealii::Function<2> &function, unsigned int state = 0);

      /** The locally owned values of @p state, for a solver to write; call
       *  values_changed() after. */
      VectorType &
      locally_owned_values(const unsigned int state = 0)
      {
        return owned_values[state];
      }

      const VectorType &
      locally_owned_values(const unsigned int state = 0) const
      {
        return owned_values[state];
      }

      /** After the owned values of @p state were written: hanging nodes made conforming
       *  and the ghosted copy updated (collective). */
      void
      values_changed(unsigned int state = 0);

      /** The values of @p state on the locally relevant dofs (owned and ghost). */
      const VectorType &
      values(const unsigned int state = 0) const
      {
        return ghosted_values[state];
      }

      /** How many states the field keeps. */
      unsigned int
      n_states() const
      {
        return owned_values.size();
      }

      /** The integral of a scalar field over the domain (2x2 Gauss points per cell, exact
       *  for the bilinear Q1 function on the grid's square cells; collective). */
      double
      integral(unsigned int state = 0) const;

      const dealii::DoFHandler<2> &
      dof_handler() const
      {
        return dofs;
      }

      /** This field's cell on the grid cell of @p cell, an iterator of another field (or of
       *  the grid) on the same triangulation. */
      template <class Cell>
      dealii::DoFHandler<2>::active_cell_iterator
      cell_on(const Cell &cell) const
      {
        return dealii::DoFHandler<2>::active_cell_iterator(&cell->get_triangulation(),
                                                           cell->level(),
                                                           cell->index(),
                                                           &dofs);
      }

      const dealii::FiniteElement<2> &
      finite_element() const
      {
        return *fe;
      }

      /** Sizes @p matrix for a system on this field's dofs: the distributed sparsity of
       *  the cells' couplings with @p constraints (the field's own, or a system's with
       *  its walls added) condensed in (collective). */
      void
      reinit_matrix(dealii::TrilinosWrappers::SparseMatrix  &matrix,
                    const dealii::AffineConstraints<double> &constraints) const;

      /** The hanging-node constraints of the current cells. */
      const dealii::AffineConstraints<double> &
      constraints() const
      {
        return hanging_node_constraints;
      }

      const dealii::IndexSet &
      locally_owned_dofs() const
      {
        return owned_dofs;
      }

      const dealii::IndexSet &
      locally_relevant_dofs() const
      {
        return relevant_dofs;
      }

      /** Cells where |grad u| h exceeds @p threshold (u in its units, h the cell side)
       *  are kept fine by the grid's adaptation; <= 0 (the default): no indicator. */
      void
      set_refinement_threshold(const double threshold)
      {
        gradient_threshold = threshold;
      }

      /** The field's share of a cell's partitioning weight: @p weight per degree of
       *  freedom of the cell (the grid counts 1000 for the cell itself; default 0). */
      void
      set_weight_per_dof(const unsigned int weight)
      {
        weight_per_dof = weight;
      }

      /** An additional share of the cells' weight computed by @p weight (empty: none). It
       *  is called during repartitioning: it may read the cell, not the field. */
      void
      set_cell_weight(CellWeight weight)
      {
        user_weight = std::move(weight);
      }

      /**
       * The field's values at the material points' nodes (the grid's own Q1 dofs) into
       * @p nodal, a vector with the grid's dof layout such as a field of the particle
       * model's NodalWorkspace: the way a particle model gathers a grid physics' field at
       * its points (its gather_fields reads the workspace's fields with the points' shape
       * weights, value and gradient). Both elements are Q1 on the same cells, so the values
       * go vertex by vertex; hanging nodes get the field's conforming value. Writes the
       * owned entries and updates the ghosts (collective). Scalar Q1 fields only.
       */
      void
      copy_to_grid_nodes(dealii::LinearAlgebra::distributed::Vector<double> &nodal) const;

      /**
       * The other way: state 0 of a Q1 field (scalar or vector) from values at the grid's
       * own nodes, component c from @p nodal[c] (ghosted vectors with the grid's dof
       * layout, such as what a particle model's points summed into its NodalWorkspace):
       * how a particle model hands its nodal fields (a solid's volume fraction, velocity,
       * drag) to a finite-element physics on the same cells. Writes the owned values and
       * calls values_changed() (collective).
       */
      void
      copy_from_grid_nodes(
        const std::vector<const dealii::LinearAlgebra::distributed::Vector<double> *> &nodal);

      void
      grid_ready() override;

      void
      prepare_for_grid_change() override;

      void
      grid_changed() override;

      void
      prepare_for_checkpoint() override;

      void
      checkpoint_loaded() override;

      void
      add_refinement_indicators(std::vector<bool> &keep_fine) const override;

      unsigned long long
      cell_weight(const CellIterator &cell, CellStatus status) const override;

    private:
      /** Distributes the dofs on the current cells, builds the constraints and sizes the
       *  vectors (zero). */
      void
      setup_dofs();

      /** Calls @p f with the field's and the grid's (scalar Q1) dof indices of every
       *  owned cell, in the order of the cells' vertices for Q1. */
      void
      for_each_owned_cell_with_grid_dofs(
        const std::function<void(const std::vector<dealii::types::global_dof_index> &,
                                 const std::vector<dealii::types::global_dof_index> &)> &f) const;

      /** The states' vectors as deal.II's transfer takes them. */
      std::vector<const VectorType *>
      ghosted_pointers() const;

      std::vector<VectorType *>
      owned_pointers();

      const BackgroundGrid                     &grid;
      std::unique_ptr<dealii::FiniteElement<2>> fe;
      dealii::DoFHandler<2>                     dofs;
      dealii::IndexSet                          owned_dofs, relevant_dofs;
      dealii::AffineConstraints<double>         hanging_node_constraints;
      std::vector<VectorType>                   owned_values, ghosted_values;
      /** Where the owned cells' values sit in the ghosted vectors (integral()). */
      mutable linear_algebra::CellGather integral_gather;
      double                             gradient_threshold = 0.;
      unsigned int                       weight_per_dof     = 0;
      CellWeight                         user_weight;
      /** The values packed for the next change or checkpoint; alive until they are
       *  taken back, since deal.II calls it when the cells are written or moved. */
      std::unique_ptr<dealii::parallel::distributed::SolutionTransfer<2, VectorType>> transfer;
    };
  } // namespace grid
} // namespace slidewave

#endif
