// The background grid calls the objects attached to it around every change of its cells
// (grid::GridFollower), in the order they were attached, once the grid's own degrees of
// freedom are distributed on the new cells: a follower counting its calls sees one
// prepare/changed pair per refinement and per repartition, and the number of dofs it sees
// after a change is that of the new grid. Also the soil model's property layout: names,
// vectors and loads as the particle output, the checkpoints and the guards read them.

#include <cstdio>
#include <deal.II/base/mpi.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/soil/material_point_parameters.h>
#include <slidewave/soil/soil_model.h>
#include <string>
#include <vector>

using namespace slidewave;

namespace
{
  bool all_passed = true;
  bool root       = true;

  void
  check(const bool ok, const std::string &what)
  {
    all_passed = all_passed && ok;
    if (root)
      std::printf("  %s: %s\n", what.c_str(), ok ? "ok" : "FAILED");
  }

  class CountingFollower : public grid::GridFollower
  {
  public:
    CountingFollower(const grid::BackgroundGrid &grid,
                     std::vector<std::string>   &log,
                     std::string                 name)
      : grid(grid)
      , log(log)
      , name(std::move(name))
    {
    }

    void
    prepare_for_grid_change() override
    {
      ++n_prepared;
      log.push_back(name + " prepare");
    }

    void
    grid_changed() override
    {
      ++n_changed;
      dofs_seen = grid.dof_handler().n_dofs();
      log.push_back(name + " changed");
    }

    unsigned int                    n_prepared = 0, n_changed = 0;
    dealii::types::global_dof_index dofs_seen = 0;

  private:
    const grid::BackgroundGrid &grid;
    std::vector<std::string>   &log;
    std::string                 name;
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // A 1 m x 1 m grid of 0.125 m cells, two adaptive levels: the base grid has 0.5 m cells.
  grid::GridChanges grid_changes;
  grid_changes.adaptive_levels = 2;
  grid_changes.buffer_cells    = 0;
  grid::BackgroundGrid     grid(dealii::Point<2>(0., 0.),
                            dealii::Point<2>(1., 1.),
                            0.125,
                            grid_changes);
  std::vector<std::string> log;
  CountingFollower         first(grid, log, "first"), second(grid, log, "second");
  grid.attach(first);
  grid.attach(second);
  grid.create();
  if (root)
    std::printf("base grid: %u cells, %u dofs\n",
                grid.triangulation().n_global_active_cells(),
                static_cast<unsigned int>(grid.dof_handler().n_dofs()));

  // Refine the cells touching the lower left corner, twice, then coarsen everything back.
  for (unsigned int round = 0; round < 3; ++round)
    {
      std::vector<bool> fine(grid.triangulation().n_active_cells(), false);
      if (round < 2)
        for (const auto &cell : grid.triangulation().active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] < 0.3 && cell->center()[1] < 0.3)
            fine[cell->active_cell_index()] = true;
      const bool changes = grid.flag_for_adaptation(fine);
      if (changes)
        grid.execute_coarsening_and_refinement();
      if (root)
        std::printf("round %u: %s, %u cells, %u dofs\n",
                    round,
                    changes ? "changed" : "no change",
                    grid.triangulation().n_global_active_cells(),
                    static_cast<unsigned int>(grid.dof_handler().n_dofs()));
    }
  grid.repartition();
  check(first.n_prepared == 4 && first.n_changed == 4 && second.n_changed == 4,
        "one prepare/changed pair per change (3 adaptations, 1 repartition), per follower");
  check(first.dofs_seen == grid.dof_handler().n_dofs(), "a follower sees the dofs of the new grid");
  bool ordered = log.size() == 16;
  for (unsigned int i = 0; ordered && i < log.size(); i += 4)
    ordered = log[i] == "first prepare" && log[i + 1] == "second prepare"
              && log[i + 2] == "first changed" && log[i + 3] == "second changed";
  check(ordered, "followers called in the order they were attached");

  // The soil's layout, with and without point forces.
  for (const bool point_forces : {false, true})
    {
      soil::MaterialPointParameters prm;
      prm.point_forces = point_forces;
      const soil::SoilModel soil(prm);
      const auto           &layout = soil.layout();
      if (root)
        {
          std::printf("soil layout%s: %u properties\n",
                      point_forces ? " with point forces" : "",
                      layout.size());
          const auto names          = layout.output_names();
          const auto interpretation = layout.output_interpretation();
          for (unsigned int i = 0; i < layout.size(); ++i)
            std::printf("  %2u %-26s output '%s'%s%s\n",
                        i,
                        layout.name(i).c_str(),
                        names[i].c_str(),
                        interpretation[i]
                            == dealii::DataComponentInterpretation::component_is_part_of_vector ?
                          " (vector component)" :
                          "",
                        layout.is_state(i) ? "" : " (load, not checked by the guards)");
        }
      check(layout.index("mass") == soil::SoilModel::mass
              && layout.index("velocity_y") == soil::SoilModel::velocity_y
              && layout.index("domain_half_x") == soil::SoilModel::domain_half_x,
            "the layout's names at the model's indices");
    }

  if (root)
    std::printf("%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
