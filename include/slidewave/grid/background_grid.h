#ifndef slidewave_grid_background_grid_h
#define slidewave_grid_background_grid_h

#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <set>
#include <slidewave/grid/grid_follower.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * How the grid changes during a run: adaptive refinement where the followers need it
     * and repartitioning by the followers' cell weights ("Adaptive grid" and "Load
     * balancing" of the scenes).
     */
    struct GridChanges
    {
      /** Refinement levels above the base grid (0: no adaptivity). */
      unsigned int adaptive_levels = 0;
      /** Steps between two adaptations. */
      unsigned int adaptivity_interval = 50;
      /** Layers of cells kept fine around the cells the followers need fine. */
      unsigned int buffer_cells = 2;
      /** Repartition when max over mean of the ranks' work exceeds this (<= 0: never). */
      double imbalance_threshold = 1.1;
      /** Steps between two checks of the balance (and a full sort of the points). */
      unsigned int balance_interval = 50;
      /** Each adaptation refines in as many passes as it takes for every cell the
       *  followers need fine to reach 'Cell size' (deal.II refines one level per pass);
       *  false: one pass (the soil's and the fluid's grids, which re-evaluate between
       *  adaptations). */
      bool refine_to_finest = false;
    };



    /**
     * The background grid shared by every physics of a scene (paper 000, §3.1; paper
     * 002, §3): a parallel::distributed::Triangulation of axis-aligned square cells over
     * the domain, with the scalar Q1 element and its DoFHandler (one degree of freedom
     * per node, the nodes of the material point method). The scene owns it; each physics
     * takes it by reference and attaches the objects that hold its data as GridFollower.
     * The grid drives every event of the cells' life for all of them in one place: the
     * set-up, adaptive refinement (the followers say where the grid must be fine),
     * partitioning by the sum of the followers' cell weights, repartitioning, and the
     * checkpoint files (the followers' data attached in attach order).
     */
    class BackgroundGrid
    {
    public:
      using CellIterator       = dealii::Triangulation<2>::cell_iterator;
      using ActiveCellIterator = dealii::Triangulation<2>::active_cell_iterator;

      /** Partitioning weight of a cell of its own, before the followers' shares
       *  (deal.II's convention; its 'weight' signal adds none of its own). */
      static constexpr unsigned int cell_base_weight = 1000;

      /**
       * A grid of square cells of side @p cell_size over [@p lower_left, @p upper_right];
       * with changes.adaptive_levels > 0 the base grid is 2^adaptive_levels times coarser
       * and refined where the followers need it. The cells are distributed over the ranks
       * of @p communicator (a scene uses all of them; a test reading a checkpoint on fewer
       * ranks than wrote it passes a smaller communicator).
       */
      BackgroundGrid(const dealii::Point<2> &lower_left,
                     const dealii::Point<2> &upper_right,
                     double                  cell_size,
                     const GridChanges      &changes      = GridChanges(),
                     MPI_Comm                communicator = MPI_COMM_WORLD);

      /**
       * Set-up: the coarse grid (as few cells as the sides allow), refined globally to
       * the base grid, then adaptive_levels times where the followers need it fine
       * (add_refinement_indicators, grown by the buffer), repartitioned by the followers'
       * weights (on several ranks, unless balancing is off), the dofs distributed, and
       * every follower's grid_ready(). Attach the followers first.
       */
      void
      create();

      /**
       * Resume: the coarse grid, every follower's before_checkpoint_load(), then the cells
       * written by save() under @p prefix (on any number of ranks), the dofs, every
       * follower's grid_ready() and then its checkpoint_loaded(), in attach order; on as
       * many ranks as wrote the checkpoint, finally the partition it was written with
       * (restore_partition()).
       */
      void
      load(const std::string &prefix);

      /** Writes the cells, their partition (each cell's rank; restore_partition()) and
       *  every follower's data (prepare_for_checkpoint, in attach order) under @p prefix
       *  (collective). */
      void
      save(const std::string &prefix);

      /** Attaches @p follower: it follows every later event of the cells. */
      void
      attach(GridFollower &follower);

      /**
       * The grid's changes due at step @p step (the number of steps done): every
       * adaptivity_interval steps an adaptation (and a repartition if the work is
       * unbalanced), otherwise every balance_interval steps a repartition if the work is
       * unbalanced. Returns whether the cells changed (collective).
       */
      bool
      change_if_due(unsigned int step);

      /** Refines where the followers need it (with refine_to_finest in as many passes as
       *  it takes for every such cell to reach 'Cell size'), coarsens elsewhere,
       *  repartitions if unbalanced; returns whether the cells changed (collective). */
      bool
      adapt();

      /** Repartitions by the cell weights when the imbalance exceeds the threshold (on
       *  several ranks); returns whether it did (collective). */
      bool
      balance();

      /** Global refinements of the coarse grid up to the base grid. */
      unsigned int
      base_refinements() const
      {
        return n_base_refinements;
      }

      /** Refinement levels above the base grid (0: no adaptivity). */
      unsigned int
      adaptive_levels() const
      {
        return settings.adaptive_levels;
      }

      const GridChanges &
      changes() const
      {
        return settings;
      }

      /** How often the cells were adapted or repartitioned during the steps. */
      unsigned int
      n_changes() const
      {
        return n_grid_changes;
      }

      /**
       * The cells flagged in @p near (owned cells, by active cell index) grown by
       * @p layers layers of vertex neighbours, across ranks (ghost cells learn their
       * owners' flags).
       */
      std::vector<bool>
      grow(std::vector<bool> near, unsigned int layers) const;

      /**
       * Flags the owned cells for refinement where @p keep_fine (up to 'Cell size') and,
       * with @p coarsen, for coarsening elsewhere (down to the base grid); returns whether
       * any rank flagged a cell (collective).
       */
      bool
      flag_for_adaptation(const std::vector<bool> &keep_fine, bool coarsen = true);

      /** Refines and coarsens the flagged cells (and repartitions by the cell weights),
       *  with the followers. */
      void
      execute_coarsening_and_refinement();

      /** Repartitions by the cell weights, with the followers. */
      void
      repartition();

      /** The partitioning weight of @p cell: cell_base_weight plus every follower's share,
       *  capped at 2^31 - 1 (p4est takes an int). */
      unsigned int
      cell_weight(const CellIterator &cell, dealii::Triangulation<2>::CellStatus status) const;

      /** Max over mean of the ranks' work, the sum of their owned cells' weights
       *  (collective). */
      double
      load_imbalance() const;

      /** Max over mean of @p work over the ranks of @p communicator (collective). */
      static double
      imbalance(double work, MPI_Comm communicator = MPI_COMM_WORLD);

      /** The ranks the cells are distributed over. */
      MPI_Comm
      communicator() const
      {
        return tria.get_communicator();
      }

      const dealii::parallel::distributed::Triangulation<2> &
      triangulation() const
      {
        return tria;
      }

      dealii::parallel::distributed::Triangulation<2> &
      triangulation()
      {
        return tria;
      }

      const dealii::DoFHandler<2> &
      dof_handler() const
      {
        return dofs;
      }

      /** The active cells around each vertex (rebuilt when the grid changes). */
      const std::vector<std::set<ActiveCellIterator>> &
      vertex_cells() const
      {
        return vertex_to_cells;
      }

      /**
       * The lumped area of each node: a quarter of every cell around it (owned and ghost
       * entries, ghosted). The one place it is computed: the depth the columns give a
       * node, its nodal mass per area and the error norms of the depth all divide by it.
       */
      dealii::LinearAlgebra::distributed::Vector<double>
      lumped_nodal_area() const;

      const dealii::Point<2> &
      lower_left() const
      {
        return corner_low;
      }

      const dealii::Point<2> &
      upper_right() const
      {
        return corner_high;
      }

      double
      cell_size() const
      {
        return h;
      }

    private:
      /** The coarse grid and its weight signal. */
      void
      create_coarse_grid();

      /** Distributes the dofs on the current cells and rebuilds the vertex map. */
      void
      distribute_dofs();

      /** Distributes the dofs and numbers them in the tree's order. */
      void
      number_dofs();

      /** Owned cells the followers need fine, grown by the buffer (collective). */
      std::vector<bool>
      cells_to_keep_fine() const;

      /** After the cells changed: the dofs and vertex map, then the followers. */
      void
      finish_change();

      /** One cell's record of the partition it was saved on. */
      struct SavedPartition
      {
        unsigned int n_ranks, rank, n_cells, count;
      };

      /**
       * deal.II partitions a loaded grid evenly by cells, not by the weights the saved
       * partition came from: the sums over cells and the solvers' block preconditioners
       * would then differ from the uninterrupted run's by round-off. save() gives every
       * cell its rank's number of cells n_r and a count k < n_r; with T the largest n_r,
       * a cell weighing floor(T / n_r), plus one for the first (T mod n_r) counts, makes
       * every saved rank's cells weigh exactly T, so p4est's weighted partition (cuts at
       * multiples of the total over the ranks) cuts exactly where the saved one did. Done
       * after the followers took their data back, as a repartition they follow; checked
       * (each rank's number of cells), warned about if it failed. On another number of
       * ranks the data is read and dropped. @p saved_partition: what load() read of the
       * saved partition, by active cell index.
       */
      void
      restore_partition(const std::vector<SavedPartition> &saved_partition);

      /** Per active cell index, while restore_partition() runs: the weight that restores
       *  the saved partition (empty otherwise: cell_weight() as usual). */
      std::vector<unsigned int>                       restoring_weights;
      dealii::Point<2>                                corner_low, corner_high;
      double                                          h;
      GridChanges                                     settings;
      unsigned int                                    n_base_refinements = 0;
      unsigned int                                    n_grid_changes     = 0;
      dealii::parallel::distributed::Triangulation<2> tria;
      dealii::FE_Q<2>                                 fe;
      dealii::DoFHandler<2>                           dofs;
      std::vector<std::set<ActiveCellIterator>>       vertex_to_cells;
      std::vector<GridFollower *>                     followers;
    };
  } // namespace grid
} // namespace slidewave

#endif
