#include <algorithm>
#include <cmath>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <iostream>
#include <limits>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/tree_order.h>

namespace slidewave
{
  namespace grid
  {
    BackgroundGrid::BackgroundGrid(const dealii::Point<2> &lower_left,
                                   const dealii::Point<2> &upper_right,
                                   const double            cell_size,
                                   const GridChanges      &changes,
                                   MPI_Comm                communicator)
      : corner_low(lower_left)
      , corner_high(upper_right)
      , h(cell_size)
      , settings(changes)
      , tria(communicator, dealii::Triangulation<2>::limit_level_difference_at_vertices)
      , fe(1)
    {
    }



    void
    BackgroundGrid::create_coarse_grid()
    {
      // With adaptive refinement the base grid is 2^levels times coarser than 'Cell size';
      // the cells holding material (and a buffer around them) are refined to 'Cell size'.
      const double              base = h * (1u << settings.adaptive_levels);
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
      // The partition weighs each cell by its own weight plus every follower's share.
      tria.signals.weight.connect(
        [this](const CellIterator &cell, const dealii::Triangulation<2>::CellStatus status) {
          return cell_weight(cell, status);
        });
    }



    void
    BackgroundGrid::create()
    {
      create_coarse_grid();
      tria.refine_global(n_base_refinements);
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
      // Each adaptive level refines the cells the followers need fine (before any point
      // exists, a point cloud answers from the regions it will fill), once.
      for (unsigned int l = 0; l < settings.adaptive_levels; ++l)
        {
          const std::vector<bool> refine = cells_to_keep_fine();
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned() && refine[cell->active_cell_index()])
              cell->set_refine_flag();
          tria.execute_coarsening_and_refinement();
          vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
        }
      if (dealii::Utilities::MPI::n_mpi_processes(tria.get_communicator()) > 1
          && settings.imbalance_threshold > 0.)
        tria.repartition();
      distribute_dofs();
      for (GridFollower *follower : followers)
        follower->grid_ready();
    }



    void
    BackgroundGrid::load(const std::string &prefix)
    {
      create_coarse_grid();
      for (GridFollower *follower : followers)
        follower->before_checkpoint_load();
      tria.load(prefix);
      // What was saved of the partition, by active cell index, for restore_partition().
      std::vector<SavedPartition> saved_partition(tria.n_active_cells(),
                                                  SavedPartition{0, 0, 0, 0});

      // The partition was attached first among the fixed-size data (save()): its handle
      // comes first among them (the points' data are variable-size, numbered apart).
      const unsigned int handle = tria.register_data_attach(
        [](const CellIterator &, const dealii::Triangulation<2>::CellStatus) {
          return std::vector<char>();
        },
        /*returns_variable_size_data=*/false);
      tria.notify_ready_to_unpack(
        handle,
        [&saved_partition](const CellIterator &cell,
                           const dealii::Triangulation<2>::CellStatus,
                           const boost::iterator_range<std::vector<char>::const_iterator> &data) {
          AssertThrow(static_cast<std::size_t>(data.end() - data.begin()) == sizeof(SavedPartition),
                      dealii::ExcInternalError());
          std::memcpy(&saved_partition[cell->active_cell_index()],
                      &*data.begin(),
                      sizeof(SavedPartition));
        });
      distribute_dofs();
      for (GridFollower *follower : followers)
        follower->grid_ready();
      for (GridFollower *follower : followers)
        follower->checkpoint_loaded();
      restore_partition(saved_partition);
    }



    void
    BackgroundGrid::restore_partition(const std::vector<SavedPartition> &saved_partition)
    {
      const MPI_Comm     comm    = tria.get_communicator();
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      // Each saved rank's number of cells, as any cell of it tells (0: no cell seen here).
      std::vector<unsigned int> saved_cells(n_ranks, 0);
      unsigned int              saved_ranks = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const SavedPartition &saved = saved_partition[cell->active_cell_index()];
            saved_ranks                 = std::max(saved_ranks, saved.n_ranks);
            if (saved.n_ranks == n_ranks && saved.rank < n_ranks)
              saved_cells[saved.rank] = saved.n_cells;
          }
      saved_ranks = dealii::Utilities::MPI::max(saved_ranks, comm);
      MPI_Allreduce(MPI_IN_PLACE, saved_cells.data(), n_ranks, MPI_UNSIGNED, MPI_MAX, comm);
      const unsigned int fewest = *std::min_element(saved_cells.begin(), saved_cells.end());
      if (n_ranks == 1 || saved_ranks != n_ranks || fewest == 0)
        {
          if (n_ranks > 1 && saved_ranks == n_ranks
              && dealii::Utilities::MPI::this_mpi_process(comm) == 0)
            std::cerr << "Warning: a rank of the checkpoint held no cell, so its partition "
                         "is not restored; the resumed run agrees with the uninterrupted one "
                         "to round-off only."
                      << std::endl;
          return;
        }
      const unsigned int most = *std::max_element(saved_cells.begin(), saved_cells.end());
      restoring_weights.assign(tria.n_active_cells(), 0);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const SavedPartition &saved = saved_partition[cell->active_cell_index()];
            restoring_weights[cell->active_cell_index()]
              = most / saved.n_cells + (saved.count < most % saved.n_cells ? 1 : 0);
          }
      repartition();
      restoring_weights.clear();
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      const bool         restored
        = dealii::Utilities::MPI::min(
            tria.n_locally_owned_active_cells() == saved_cells[rank] ? 1u : 0u, comm)
          == 1;
      if (!restored && rank == 0)
        std::cerr << "Warning: the checkpoint's partition of the cells could not be "
                     "restored; the resumed run agrees with the uninterrupted one to "
                     "round-off only."
                  << std::endl;
    }



    void
    BackgroundGrid::save(const std::string &prefix)
    {
      // Each cell's rank, its number of cells and a count (restore_partition()); first,
      // so that load() finds it under the first handle.
      const SavedPartition partition{
        dealii::Utilities::MPI::n_mpi_processes(tria.get_communicator()),
        dealii::Utilities::MPI::this_mpi_process(tria.get_communicator()),
        tria.n_locally_owned_active_cells(),
        0};
      tria.register_data_attach(
        [partition, count = 0u](const CellIterator &,
                                const dealii::Triangulation<2>::CellStatus) mutable {
          SavedPartition cell_record = partition;
          cell_record.count          = count++;
          std::vector<char> data(sizeof(SavedPartition));
          std::memcpy(data.data(), &cell_record, sizeof(SavedPartition));
          return data;
        },
        /*returns_variable_size_data=*/false);
      for (GridFollower *follower : followers)
        follower->prepare_for_checkpoint();
      tria.save(prefix);
    }



    void
    BackgroundGrid::attach(GridFollower &follower)
    {
      followers.push_back(&follower);
    }



    std::vector<bool>
    BackgroundGrid::cells_to_keep_fine() const
    {
      std::vector<bool> keep_fine(tria.n_active_cells(), false);
      for (const GridFollower *follower : followers)
        follower->add_refinement_indicators(keep_fine);
      return grow(std::move(keep_fine), settings.buffer_cells);
    }



    unsigned int
    BackgroundGrid::cell_weight(const CellIterator                        &cell,
                                const dealii::Triangulation<2>::CellStatus status) const
    {
      if (!restoring_weights.empty())
        return restoring_weights[cell->active_cell_index()];
      unsigned long long weight = cell_base_weight;
      for (const GridFollower *follower : followers)
        weight += follower->cell_weight(cell, status);
      // p4est takes the weight as an int: saturate rather than wrap around.
      return static_cast<unsigned int>(
        std::min<unsigned long long>(weight, std::numeric_limits<int>::max()));
    }



    double
    BackgroundGrid::load_imbalance() const
    {
      // The work of a rank: its owned cells' weights as the partition counts them (not
      // capped: the sum is exact in a double up to 2^53).
      unsigned long long work = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            work += cell_base_weight;
            for (const GridFollower *follower : followers)
              work += follower->cell_weight(cell, dealii::Triangulation<2>::CELL_PERSIST);
          }
      return imbalance(static_cast<double>(work), tria.get_communicator());
    }



    bool
    BackgroundGrid::change_if_due(const unsigned int step)
    {
      if (step == 0)
        return false;
      if (settings.adaptive_levels > 0 && step % settings.adaptivity_interval == 0)
        return adapt();
      if (step % settings.balance_interval == 0)
        return balance();
      return false;
    }



    bool
    BackgroundGrid::adapt()
    {
      // deal.II refines a cell by one level per pass: material that moved into cells two
      // levels coarser than 'Cell size' since the last adaptation (a fast flow crossing
      // the rings of the levels between, issue 28) would stay on coarse cells. With
      // refine_to_finest the passes repeat until every cell that must be fine is (at most
      // 'Levels' passes); only the first coarsens.
      bool               changes = false;
      const unsigned int passes
        = settings.refine_to_finest ? std::max(1u, settings.adaptive_levels) : 1;
      for (unsigned int pass = 0; pass < passes; ++pass)
        {
          if (!flag_for_adaptation(cells_to_keep_fine(), /*coarsen=*/pass == 0))
            break;
          execute_coarsening_and_refinement(); // also repartitions by the cell weights
          changes = true;
        }
      const bool rebalance = !changes && settings.imbalance_threshold > 0.
                             && dealii::Utilities::MPI::n_mpi_processes(tria.get_communicator()) > 1
                             && load_imbalance() > settings.imbalance_threshold;
      if (!changes && !rebalance)
        return false;
      // What lives on the cells follows them through refinement, coarsening and
      // repartitioning.
      if (rebalance)
        repartition();
      ++n_grid_changes;
      return true;
    }



    bool
    BackgroundGrid::balance()
    {
      if (dealii::Utilities::MPI::n_mpi_processes(tria.get_communicator()) == 1
          || !(settings.imbalance_threshold > 0.)
          || load_imbalance() <= settings.imbalance_threshold)
        return false;
      repartition();
      ++n_grid_changes;
      return true;
    }



    std::vector<bool>
    BackgroundGrid::grow(std::vector<bool> near, const unsigned int layers) const
    {
      // Layer by layer from the cells flagged last (the front): only their vertex
      // neighbours can join the next layer, so the work is the flagged cells', not the
      // grid's (a grid that follows a flow over a regional DEM is mostly coarse cells far
      // from it).
      std::vector<ActiveCellIterator> front, next;
      std::vector<bool>               queued(near.size(), false);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && near[cell->active_cell_index()])
          front.push_back(cell);
      for (unsigned int layer = 0; layer <= layers; ++layer)
        {
          // Ghost cells learn their owners' flags; those newly flagged join the front.
          dealii::GridTools::exchange_cell_data_to_ghosts<unsigned char, dealii::Triangulation<2>>(
            tria,
            [&](const ActiveCellIterator &cell) {
              return static_cast<unsigned char>(near[cell->active_cell_index()]);
            },
            [&](const ActiveCellIterator &cell, const unsigned char flag) {
              if (flag != 0 && !near[cell->active_cell_index()])
                front.push_back(cell);
              near[cell->active_cell_index()] = flag != 0;
            });
          if (layer == layers)
            break;
          // A cell joins the layer if a cell flagged before is among the cells around one
          // of its own vertices (deal.II's vertex map also lists a coarse cell at the
          // hanging vertices on its edges: the relation is not symmetric, so the
          // candidates found from the front are checked from their own vertices).
          next.clear();
          const auto consider = [&](const unsigned int vertex) {
            for (const auto &other : vertex_to_cells[vertex])
              if (other->is_locally_owned() && !near[other->active_cell_index()]
                  && !queued[other->active_cell_index()])
                {
                  bool touches = false;
                  for (const unsigned int w : other->vertex_indices())
                    for (const auto &around : vertex_to_cells[other->vertex_index(w)])
                      touches = touches
                                || (!around->is_artificial() && near[around->active_cell_index()]);
                  if (touches)
                    {
                      queued[other->active_cell_index()] = true;
                      next.push_back(other);
                    }
                }
          };
          for (const auto &cell : front)
            {
              // Its vertices, and the hanging vertices in the middle of its edges (the
              // finer cells there touch it only at those).
              for (const unsigned int v : cell->vertex_indices())
                consider(cell->vertex_index(v));
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->has_children())
                  consider(cell->face(f)->child(0)->vertex_index(1));
            }
          for (const auto &cell : next)
            near[cell->active_cell_index()] = true;
          front.swap(next);
        }
      return near;
    }



    bool
    BackgroundGrid::flag_for_adaptation(const std::vector<bool> &keep_fine, const bool coarsen)
    {
      bool changes = false;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const bool         fine  = keep_fine[cell->active_cell_index()];
            const unsigned int level = cell->level();
            if (fine && level < n_base_refinements + settings.adaptive_levels)
              {
                cell->set_refine_flag();
                changes = true;
              }
            else if (coarsen && !fine && level > n_base_refinements)
              {
                cell->set_coarsen_flag();
                changes = true;
              }
          }
      return dealii::Utilities::MPI::logical_or(changes, tria.get_communicator());
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
    BackgroundGrid::finish_change()
    {
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
      number_dofs();
      for (GridFollower *follower : followers)
        follower->grid_changed();
    }



    void
    BackgroundGrid::distribute_dofs()
    {
      dofs.reinit(tria);
      vertex_to_cells = dealii::GridTools::vertex_to_cell_map(tria);
      number_dofs();
    }



    void
    BackgroundGrid::number_dofs()
    {
      dofs.distribute_dofs(fe);
      // Numbered along the cells' tree (p4est's space-filling curve), not in the order in
      // which refinement happened to create the cells: a grid read from a checkpoint then
      // has the nodes' numbers of the run that wrote it, and every sum over the nodes (the
      // nodal vectors' norms, the drag projection's conjugate gradients) repeats the
      // uninterrupted run to the last bit (FiniteElementField::setup_dofs() does the same).
      dealii::DoFRenumbering::hierarchical(dofs);
    }



    dealii::LinearAlgebra::distributed::Vector<double>
    BackgroundGrid::lumped_nodal_area() const
    {
      dealii::IndexSet relevant;
      dealii::DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      dealii::LinearAlgebra::distributed::Vector<double> area(dofs.locally_owned_dofs(),
                                                              relevant,
                                                              tria.get_communicator());
      std::vector<dealii::types::global_dof_index>       indices(4);
      // (in the tree's order: a node's sum of its cells' quarters repeats in a resumed run)
      for_each_owned_cell_in_tree_order(dofs, [&](const auto &cell) {
        cell->get_dof_indices(indices);
        const double quarter = 0.25 * cell->measure();
        for (const auto i : indices)
          area[i] += quarter;
      });
      area.compress(dealii::VectorOperation::add);
      area.update_ghost_values();
      return area;
    }



    double
    BackgroundGrid::imbalance(const double work, MPI_Comm communicator)
    {
      const double max  = dealii::Utilities::MPI::max(work, communicator);
      const double mean = dealii::Utilities::MPI::sum(work, communicator)
                          / dealii::Utilities::MPI::n_mpi_processes(communicator);
      return mean > 0. ? max / mean : 1.;
    }



  } // namespace grid
} // namespace slidewave
