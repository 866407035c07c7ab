#ifndef slidewave_grid_background_grid_h
#define slidewave_grid_background_grid_h

#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <functional>
#include <set>
#include <slidewave/grid/grid_follower.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * The background grid of the material point method (paper 000, §3.1): a
     * parallel::distributed::Triangulation of axis-aligned square cells over the domain,
     * with the scalar Q1 element and its DoFHandler (one degree of freedom per node); the
     * coarse grid, adaptivity (the caller says where the grid must be fine), partitioning
     * by cell weights that the caller gives, repartitioning, and the triangulation's
     * checkpoint files. Objects living on the grid attach themselves as GridFollower and
     * follow every refinement and repartitioning.
     */
    class BackgroundGrid
    {
    public:
      using CellIterator       = dealii::Triangulation<2>::cell_iterator;
      using ActiveCellIterator = dealii::Triangulation<2>::active_cell_iterator;
      /** The partitioning weight of a cell (deal.II's 'weight' signal). */
      using CellWeight
        = std::function<unsigned int(const CellIterator &, dealii::Triangulation<2>::CellStatus)>;

      /**
       * A grid of square cells of side @p cell_size over [@p lower_left, @p upper_right];
       * with @p adaptive_levels > 0 the base grid is 2^adaptive_levels times coarser and
       * refined where material is.
       */
      BackgroundGrid(const dealii::Point<2> &lower_left,
                     const dealii::Point<2> &upper_right,
                     double                  cell_size,
                     unsigned int            adaptive_levels);

      /**
       * The coarse grid (as few cells as the sides allow; base_refinements() global
       * refinements make the base grid), weighed for partitioning by @p weight.
       */
      void
      create_coarse_grid(const CellWeight &weight);

      /** Refines the coarse grid globally to the base grid (no follower is attached yet). */
      void
      refine_to_base();

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
        return levels;
      }

      /** Attaches @p follower: it follows every later change of the cells. */
      void
      attach(GridFollower &follower);

      /**
       * Refines the locally owned cells flagged in @p refine (by active cell index) once;
       * set-up only, before the degrees of freedom exist.
       */
      void
      refine(const std::vector<bool> &refine);

      /**
       * The cells flagged in @p near (owned cells, by active cell index) grown by
       * @p layers layers of vertex neighbours, across ranks (ghost cells learn their
       * owners' flags).
       */
      std::vector<bool>
      grow(std::vector<bool> near, unsigned int layers) const;

      /**
       * Flags the owned cells for refinement where @p keep_fine (up to 'Cell size') and
       * for coarsening elsewhere (down to the base grid); returns whether any rank flagged
       * a cell (collective).
       */
      bool
      flag_for_adaptation(const std::vector<bool> &keep_fine);

      /** Refines and coarsens the flagged cells (and repartitions by the cell weights),
       *  with the followers. */
      void
      execute_coarsening_and_refinement();

      /** Repartitions by the cell weights, with the followers. */
      void
      repartition();

      /** Repartitions before the degrees of freedom exist (set-up; no followers). */
      void
      repartition_initial();

      /** Distributes the degrees of freedom on the current cells (set-up and load). */
      void
      setup_dofs();

      /** Max over mean of @p work over the ranks (collective). */
      static double
      imbalance(double work);

      /** Writes the triangulation (and what the followers attached) under @p prefix. */
      void
      save(const std::string &prefix) const;

      /** Reads the triangulation written by save() into the coarse grid. */
      void
      load(const std::string &prefix);

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
      /** After the cells changed: the dofs and vertex map, then the followers. */
      void
      finish_change();

      dealii::Point<2>                                corner_low, corner_high;
      double                                          h;
      unsigned int                                    levels;
      unsigned int                                    n_base_refinements = 0;
      dealii::parallel::distributed::Triangulation<2> tria;
      dealii::FE_Q<2>                                 fe;
      dealii::DoFHandler<2>                           dofs;
      std::vector<std::set<ActiveCellIterator>>       vertex_to_cells;
      std::vector<GridFollower *>                     followers;
    };
  } // namespace grid
} // namespace slidewave

#endif
