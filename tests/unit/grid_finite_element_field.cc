// A finite-element field lives on the background grid (grid::FiniteElementField, a
// GridFollower): its values follow every event of the cells, and it has its say in how the
// cells change. Two fields on one grid (in attach order, as two physics would be):
// 1. a linear function u = 1 + 2x - 3y stays exact at every node (max nodal error < 1e-12)
//    through refinement of some cells (hanging nodes appear), a repartition whose weights
//    changed, and coarsening back: Q1 holds it exactly, so a transfer can only lose it by a
//    mistake (a wrong child, a missing hanging-node constraint, a value left behind);
// 2. a smooth field sin(pi x) cos(pi y / 2) keeps its integral under refinement and
//    repartitioning (to 1e-12): interpolation from a parent to its children is exact for
//    the parent's bilinear function, so nothing but round-off may change it;
// 3. a checkpoint written by grid.save() and read by a fresh grid and fresh fields with
//    grid.load() restores every nodal value exactly (values keyed by node coordinates),
//    on the same ranks and on rank 0 alone (a sub-communicator: on two ranks, the
//    checkpoint written by two is read by one);
// 4. the field's refinement indicator (|grad u| h above a threshold) decides which cells
//    grid.adapt() refines, and its cell weight decides the partition: the rank owning the
//    heavy cells owns fewer cells than without the weight.
// 5. the field's values copied to the grid's own nodes (a field of a particle model's nodal
//    workspace, what the model's gather reads) give the linear function and its gradient
//    exactly at the nodes, hanging ones included, and at points.
// Every printed line is the same on one and two ranks.

#include <array>
#include <cmath>
#include <cstdio>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <map>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/nodal_workspace.h>
#include <string>
#include <utility>
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

  /** u = 1 + 2x - 3y: in the Q1 space, so every transfer must keep it exactly. */
  class Linear : public dealii::Function<2>
  {
  public:
    double
    value(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      return 1. + 2. * p[0] - 3. * p[1];
    }
  };

  /** sin(pi x) cos(pi y / 2): not in the Q1 space (its integral over the unit square is
   *  4/pi^2; the interpolant's differs by the interpolation error). */
  class Smooth : public dealii::Function<2>
  {
  public:
    double
    value(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      return std::sin(M_PI * p[0]) * std::cos(0.5 * M_PI * p[1]);
    }
  };

  /** A bump of width 0.1 m around (0.3, 0.3): steep on a ring, flat elsewhere. */
  class Bump : public dealii::Function<2>
  {
  public:
    double
    value(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      return std::exp(-(p - dealii::Point<2>(0.3, 0.3)).norm_square() / 0.02);
    }
  };

  /** Max over the nodes of |u_h - u| (collective). */
  double
  max_nodal_error(const grid::FiniteElementField &field, const dealii::Function<2> &exact)
  {
    double error = 0.;
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          error = std::max(error,
                           std::abs(field.values()[cell->vertex_dof_index(v, 0)]
                                    - exact.value(cell->vertex(v))));
    return dealii::Utilities::MPI::max(error, field.dof_handler().get_communicator());
  }

  using NodalValues = std::map<std::pair<double, double>, double>;

  /** Every node's value keyed by its coordinates, on rank 0 of the field's communicator
   *  (empty elsewhere; collective): independent of the partition and the dof numbering. */
  NodalValues
  nodal_values(const grid::FiniteElementField &field)
  {
    std::vector<std::array<double, 3>> mine;
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto i = cell->vertex_dof_index(v, 0);
            if (field.locally_owned_dofs().is_element(i))
              mine.push_back({{cell->vertex(v)[0], cell->vertex(v)[1], field.values()[i]}});
          }
    const auto  all = dealii::Utilities::MPI::gather(field.dof_handler().get_communicator(), mine);
    NodalValues values;
    for (const auto &part : all)
      for (const auto &node : part)
        values[{node[0], node[1]}] = node[2];
    return values;
  }

  /** The grid of the test: the unit square, 0.125 m base cells, two adaptive levels (down
   *  to 1/32 m), no buffer (the cells asked for are the cells refined). */
  grid::GridChanges
  grid_changes()
  {
    grid::GridChanges changes;
    changes.adaptive_levels = 2;
    changes.buffer_cells    = 0;
    return changes;
  }

  /** Adapts the grid: cells whose centre is in the lower left corner are refined if
   *  @p refine, every refined cell coarsened otherwise. Returns whether the cells changed. */
  bool
  adapt_lower_left(grid::BackgroundGrid &grid, const bool refine)
  {
    std::vector<bool> fine(grid.triangulation().n_active_cells(), false);
    if (refine)
      for (const auto &cell : grid.triangulation().active_cell_iterators())
        if (cell->is_locally_owned() && cell->center()[0] < 0.3 && cell->center()[1] < 0.3)
          fine[cell->active_cell_index()] = true;
    const bool changes = grid.flag_for_adaptation(fine);
    if (changes)
      grid.execute_coarsening_and_refinement();
    return changes;
  }

  /**
   * Coarsens every refined cell, round after round (one level per round; on several ranks a
   * family split between two ranks waits for the repartition of that round, so the
   * intermediate grids and the number of rounds depend on the ranks: not printed). Returns
   * whether @p linear stayed exact after every round (collective).
   */
  bool
  coarsen_to_base(grid::BackgroundGrid &grid, const grid::FiniteElementField &linear)
  {
    bool exact = true;
    for (unsigned int round = 0; round < 6 && adapt_lower_left(grid, false); ++round)
      exact = exact && max_nodal_error(linear, Linear()) < 1e-12;
    return exact;
  }

  unsigned int
  owned_cells(const grid::BackgroundGrid &grid)
  {
    return grid.triangulation().n_locally_owned_active_cells();
  }

  /** Whether @p cell is one of the heavy cells of the weight checks (lower left quadrant). */
  bool
  heavy(const grid::GridFollower::CellIterator &cell)
  {
    return cell->center()[0] < 0.5 && cell->center()[1] < 0.5;
  }

  /** Reads the checkpoint @p prefix into a fresh grid with two fresh fields on
   *  @p communicator; whether every nodal value of both equals @p linear and @p smooth
   *  (meaningful on rank 0 of @p communicator). */
  bool
  read_back(const std::string &prefix,
            const MPI_Comm     communicator,
            const NodalValues &linear,
            const NodalValues &smooth,
            unsigned int      &n_cells)
  {
    grid::BackgroundGrid grid(
      dealii::Point<2>(0., 0.), dealii::Point<2>(1., 1.), 1. / 32., grid_changes(), communicator);
    grid::FiniteElementField linear_field(grid), smooth_field(grid);
    grid.load(prefix);
    n_cells                      = grid.triangulation().n_global_active_cells();
    const NodalValues linear_now = nodal_values(linear_field);
    const NodalValues smooth_now = nodal_values(smooth_field);
    return linear_now == linear && smooth_now == smooth;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  root                       = rank == 0;
  const double tolerance     = 1e-12;

  grid::BackgroundGrid     grid(dealii::Point<2>(0., 0.),
                            dealii::Point<2>(1., 1.),
                            1. / 32.,
                            grid_changes());
  grid::FiniteElementField linear(grid), smooth(grid);
  bool                     weigh_heavy_cells = false;
  linear.set_cell_weight(
    [&weigh_heavy_cells](const grid::GridFollower::CellIterator &cell,
                         grid::GridFollower::CellStatus) -> unsigned long long {
      return weigh_heavy_cells && heavy(cell) ? 3000 : 0;
    });
  grid.create();
  linear.interpolate(Linear());
  smooth.interpolate(Smooth());
  const double       integral     = smooth.integral();
  const unsigned int n_base_cells = grid.triangulation().n_global_active_cells();
  if (root)
    std::printf("base grid: %u cells, %u dofs per field; integral of the smooth field %.10f\n",
                grid.triangulation().n_global_active_cells(),
                static_cast<unsigned int>(linear.dof_handler().n_dofs()),
                integral);
  check(max_nodal_error(linear, Linear()) < tolerance, "linear field interpolated exactly");

  // 1 and 2: refinement twice in the lower left corner.
  for (unsigned int round = 1; round <= 2; ++round)
    {
      const bool changed = adapt_lower_left(grid, true);
      if (root)
        std::printf("refinement %u: %s, %u cells, %u dofs per field\n",
                    round,
                    changed ? "changed" : "no change",
                    grid.triangulation().n_global_active_cells(),
                    static_cast<unsigned int>(linear.dof_handler().n_dofs()));
      check(max_nodal_error(linear, Linear()) < tolerance,
            "linear field exact after refinement (max nodal error < 1e-12)");
      check(std::abs(smooth.integral() - integral) < tolerance,
            "integral of the smooth field kept by refinement (to 1e-12)");
    }
  const unsigned int n_constraints
    = dealii::Utilities::MPI::sum(static_cast<unsigned int>(linear.constraints().n_constraints()),
                                  MPI_COMM_WORLD);
  check(n_constraints > 0, "hanging nodes constrained on the refined grid");

  // A repartition whose weights changed: the heavy cells (all refined or not) weigh 4x.
  const unsigned int owned_before = owned_cells(grid);
  weigh_heavy_cells               = true;
  grid.repartition();
  const bool moved
    = dealii::Utilities::MPI::logical_or(owned_cells(grid) != owned_before, MPI_COMM_WORLD);
  check(n_ranks == 1 ? !moved : moved,
        "repartition with changed weights moved cells (on one rank: none to move)");
  check(max_nodal_error(linear, Linear()) < tolerance,
        "linear field exact after repartitioning (max nodal error < 1e-12)");
  check(std::abs(smooth.integral() - integral) < tolerance,
        "integral of the smooth field kept by repartitioning (to 1e-12)");

  // 3. Checkpoint of the refined, repartitioned grid and its two fields.
  const std::string  prefix        = "fe_field_checkpoint";
  const NodalValues  linear_saved  = nodal_values(linear);
  const NodalValues  smooth_saved  = nodal_values(smooth);
  const unsigned int n_cells_saved = grid.triangulation().n_global_active_cells();
  grid.save(prefix);
  {
    unsigned int n_cells = 0;
    const bool   equal   = read_back(prefix, MPI_COMM_WORLD, linear_saved, smooth_saved, n_cells);
    check(equal && n_cells == n_cells_saved,
          "checkpoint read back on the same ranks: same cells, every nodal value equal");
  }
  {
    // Rank 0 alone reads what all ranks wrote (on two ranks: written by two, read by one).
    MPI_Comm alone;
    MPI_Comm_split(MPI_COMM_WORLD, root ? 0 : MPI_UNDEFINED, 0, &alone);
    bool equal = true;
    if (root)
      {
        unsigned int n_cells = 0;
        equal                = read_back(prefix, alone, linear_saved, smooth_saved, n_cells)
                && n_cells == n_cells_saved;
        MPI_Comm_free(&alone);
      }
    check(!dealii::Utilities::MPI::logical_or(!equal, MPI_COMM_WORLD),
          "checkpoint read back on rank 0 alone: same cells, every nodal value equal");
  }

  // 1. Coarsening back to the base grid.
  weigh_heavy_cells = false;
  check(coarsen_to_base(grid, linear)
          && grid.triangulation().n_global_active_cells() == n_base_cells,
        "coarsened back to the base grid, linear field exact after each round (max nodal error "
        "< 1e-12)");

  // 4a. The field's refinement indicator decides where grid.adapt() refines.
  smooth.interpolate(Bump());
  smooth.set_refinement_threshold(0.3);
  std::vector<bool> steep(grid.triangulation().n_active_cells(), false);
  smooth.add_refinement_indicators(steep);
  unsigned int n_steep = 0;
  for (const auto &cell : grid.triangulation().active_cell_iterators())
    if (cell->is_locally_owned() && steep[cell->active_cell_index()])
      ++n_steep;
  n_steep                    = dealii::Utilities::MPI::sum(n_steep, MPI_COMM_WORLD);
  const unsigned int n_base  = grid.triangulation().n_global_active_cells();
  const bool         adapted = grid.adapt();
  if (root)
    std::printf("bump: %u of %u cells with |grad u| h > 0.3; after adapt(): %u cells\n",
                n_steep,
                n_base,
                grid.triangulation().n_global_active_cells());
  check(adapted && n_steep > 0 && n_steep < n_base
          && grid.triangulation().n_global_active_cells() == n_base + 3 * n_steep,
        "adapt() refined exactly the cells the field's indicator flagged");
  check(max_nodal_error(linear, Linear()) < tolerance,
        "linear field exact after adapt() (max nodal error < 1e-12)");
  smooth.set_refinement_threshold(0.);
  check(coarsen_to_base(grid, linear) && grid.triangulation().n_global_active_cells() == n_base,
        "coarsened back to the base grid after adapt(), linear field exact");

  // 4b. The field's cell weight decides the partition.
  linear.set_weight_per_dof(10);
  bool weights_summed = true;
  for (const auto &cell : grid.triangulation().active_cell_iterators())
    if (cell->is_locally_owned())
      weights_summed = weights_summed
                       && grid.cell_weight(cell, dealii::Triangulation<2>::CELL_PERSIST)
                            == grid::BackgroundGrid::cell_base_weight + 4 * 10;
  check(!dealii::Utilities::MPI::logical_or(!weights_summed, MPI_COMM_WORLD),
        "cell weight = 1000 + 10 per dof of the cell");
  linear.set_weight_per_dof(0);
  grid.repartition();
  const unsigned int owned_without = owned_cells(grid);
  unsigned int       n_heavy = 0, heavy_owned = 0;
  for (const auto &cell : grid.triangulation().active_cell_iterators())
    if (cell->is_locally_owned() && heavy(cell))
      ++heavy_owned;
  n_heavy               = dealii::Utilities::MPI::sum(heavy_owned, MPI_COMM_WORLD);
  weigh_heavy_cells     = true;
  const bool rebalanced = grid.balance();
  check(n_ranks == 1 ? !rebalanced : rebalanced,
        "balance() repartitioned the unbalanced ranks (on one rank: nothing to balance)");
  // The rank owning the most heavy cells (the lowest such rank if several).
  heavy_owned = 0;
  for (const auto &cell : grid.triangulation().active_cell_iterators())
    if (cell->is_locally_owned() && heavy(cell))
      ++heavy_owned;
  const unsigned int most_heavy = dealii::Utilities::MPI::max(heavy_owned, MPI_COMM_WORLD);
  const unsigned int heavy_rank
    = dealii::Utilities::MPI::min(heavy_owned == most_heavy ? rank : n_ranks, MPI_COMM_WORLD);
  const int fewer = dealii::Utilities::MPI::sum(
    rank == heavy_rank ? (owned_cells(grid) < owned_without ? 1 : 0) : 0, MPI_COMM_WORLD);
  if (root)
    std::printf("weights: %u heavy cells (1000 + 3000) of %u\n",
                n_heavy,
                grid.triangulation().n_global_active_cells());
  check(n_ranks == 1 ? fewer == 0 : fewer == 1,
        "the rank owning the heavy cells owns fewer cells than without the weight (on one "
        "rank: all of them)");
  check(max_nodal_error(linear, Linear()) < tolerance,
        "linear field exact after balance() (max nodal error < 1e-12)");

  // 5. What a particle model gathers from a grid physics: the field's values at the grid's
  //    own nodes (copy_to_grid_nodes) in a field of the model's nodal workspace, on a grid
  //    with hanging nodes, and what the model's gather computes from them with the Q1
  //    weights at a point (here each cell's centre): u and grad u = (2, -3) exactly.
  adapt_lower_left(grid, true);
  grid::NodalWorkspace nodes(grid, /*with_node_positions=*/true, 1, 1);
  nodes.reinit();
  linear.copy_to_grid_nodes(nodes.fields[0]);
  const auto                                  &q1 = grid.dof_handler().get_fe();
  std::vector<dealii::types::global_dof_index> indices(q1.n_dofs_per_cell());
  const dealii::Point<2>                       centre(0.5, 0.5);
  const dealii::Tensor<1, 2>                   exact_gradient({2., -3.});
  double node_error = 0., centre_error = 0., gradient_error = 0.;
  for (const auto &cell : grid.dof_handler().active_cell_iterators())
    if (cell->is_locally_owned())
      {
        cell->get_dof_indices(indices);
        const double         h     = cell->extent_in_direction(0);
        double               value = 0.;
        dealii::Tensor<1, 2> gradient;
        for (unsigned int k = 0; k < indices.size(); ++k)
          {
            const double u_k = nodes.fields[0][indices[k]];
            node_error = std::max(node_error, std::abs(u_k - Linear().value(cell->vertex(k))));
            value += q1.shape_value(k, centre) * u_k;
            gradient += q1.shape_grad(k, centre) / h * u_k;
          }
        centre_error   = std::max(centre_error, std::abs(value - Linear().value(cell->center())));
        gradient_error = std::max(gradient_error, (gradient - exact_gradient).norm());
      }
  if (root)
    std::printf("gather: the field at the grid's nodes, %u cells\n",
                grid.triangulation().n_global_active_cells());
  check(dealii::Utilities::MPI::max(node_error, MPI_COMM_WORLD) < tolerance,
        "every node of the owned cells (hanging ones too) holds the field's value (< 1e-12)");
  check(dealii::Utilities::MPI::max(std::max(centre_error, gradient_error), MPI_COMM_WORLD)
          < tolerance,
        "value and gradient gathered at the cells' centres exact (< 1e-12)");

  if (root)
    std::printf("%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
