#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <slidewave/grid/background_grid.h>

namespace slidewave
{
  namespace grid
  {
    BackgroundGrid::BackgroundGrid(const dealii::Point<2> &lower_left,
                                   const dealii::Point<2> &upper_right,
                                   const double            cell_size,
                                   const unsigned int      adaptive_levels)
      : corner_low(lower_left)
      , corner_high(upper_right)
      , h(cell_size)
      , levels(adaptive_levels)
      , tria(MPI_COMM_WORLD, dealii::Triangulation<2>::limit_level_difference_at_vertices)
      , fe(1)
    {
    }



    void
    BackgroundGrid::create_coarse_grid(const CellWeight &weight)
    {
      // With adaptive refinement the base grid is 2^levels times coarser than 'Cell size';
      // the cells holding material (and a buffer around them) are refined to 'Cell size'.
      const double              base = h * (1u << levels);
      std::vector<unsigned int> subdivisions{
        static_cast<unsigned int>(std::round((corner_high[0] - corner_low[0]) / base)),
        static_cast<unsigned int>(std::round((corner_high[1] - corner_low[1]) / base))};
      // Every rank stores every coarse cell (p4est's trees), and deal.II's cell loops visit
      // them all: the base grid is built from as few coarse cells as the side ratio allows
      // and refined globally (refine_to_base(); a checkpoint restores the refinement
      // itself). The cells are the same; only their order (p4est's space-filling curve
      // within each coarse cell) and the memory per rank change.
      n_base_refinements = 0;
      while (subdivisions[0] % 2 == 0 && subdivisions[1] % 2 == 0)
        {
          subdivisions[0] /= 2;
          subdivisions[1] /= 2;
          ++n_base_refinements;
        }
      dealii::GridGenerator::subdivided_hyper_rectangle(
        tria, subdivisions, corner_low, corner_high, /*colorize=*/true);
      tria.signals.weight.connect(weight);
    }



    void
    BackgroundGrid::refine_to_base()
    {
      tria.refine_global(n_base_refinements);
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
    }



    void
    BackgroundGrid::attach(GridFollower &follower)
    {
      followers.push_back(&follower);
    }



    void
    BackgroundGrid::refine(const std::vector<bool> &refine)
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && refine[cell->active_cell_index()])
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
    }



    std::vector<bool>
    BackgroundGrid::grow(std::vector<bool> near, const unsigned int layers) const
    {
      for (unsigned int layer = 0; layer <= layers; ++layer)
        {
          // Ghost cells learn their owners' flags.
          dealii::GridTools::exchange_cell_data_to_ghosts<unsigned char, dealii::Triangulation<2>>(
            tria,
            [&](const ActiveCellIterator &cell) {
              return static_cast<unsigned char>(near[cell->active_cell_index()]);
            },
            [&](const ActiveCellIterator &cell, const unsigned char flag) {
              near[cell->active_cell_index()] = flag != 0;
            });
          if (layer == layers)
            break;
          std::vector<bool> grown = near;
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned() && !near[cell->active_cell_index()])
              for (const unsigned int v : cell->vertex_indices())
                for (const auto &other : vertex_to_cells[cell->vertex_index(v)])
                  if (!other->is_artificial() && near[other->active_cell_index()])
                    grown[cell->active_cell_index()] = true;
          near.swap(grown);
        }
      return near;
    }



    bool
    BackgroundGrid::flag_for_adaptation(const std::vector<bool> &keep_fine)
    {
      bool changes = false;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const bool         fine  = keep_fine[cell->active_cell_index()];
            const unsigned int level = cell->level();
            if (fine && level < n_base_refinements + levels)
              {
                cell->set_refine_flag();
                changes = true;
              }
            else if (!fine && level > n_base_refinements)
              {
                cell->set_coarsen_flag();
                changes = true;
              }
          }
      return dealii::Utilities::MPI::logical_or(changes, MPI_COMM_WORLD);
    }



    void
    BackgroundGrid::execute_coarsening_and_refinement()
    {
      for (GridFollower *follower : followers)
        follower->prepare_for_grid_change();
      tria.execute_coarsening_and_refinement(); // also repartitions by the cell weights
      finish_change();
    }



    void
    BackgroundGrid::repartition()
    {
      for (GridFollower *follower : followers)
        follower->prepare_for_grid_change();
      tria.repartition();
      finish_change();
    }



    void
    BackgroundGrid::repartition_initial()
    {
      tria.repartition();
    }



    void
    BackgroundGrid::finish_change()
    {
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
      dofs.distribute_dofs(fe);
      for (GridFollower *follower : followers)
        follower->grid_changed();
    }



    void
    BackgroundGrid::setup_dofs()
    {
      dofs.reinit(tria);
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
      dofs.distribute_dofs(fe);
    }



    double
    BackgroundGrid::imbalance(const double work)
    {
      const double max  = dealii::Utilities::MPI::max(work, MPI_COMM_WORLD);
      const double mean = dealii::Utilities::MPI::sum(work, MPI_COMM_WORLD)
                          / dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      return mean > 0. ? max / mean : 1.;
    }



    void
    BackgroundGrid::save(const std::string &prefix) const
    {
      tria.save(prefix);
    }



    void
    BackgroundGrid::load(const std::string &prefix)
    {
      tria.load(prefix);
    }
  } // namespace grid
} // namespace slidewave
