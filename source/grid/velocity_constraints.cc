#include <algorithm>
#include <deal.II/dofs/dof_tools.h>
#include <slidewave/grid/velocity_constraints.h>

namespace slidewave
{
  namespace grid
  {
    VelocityConstraints::VelocityConstraints(const BackgroundGrid                &grid,
                                             const NodalWorkspace                &nodes,
                                             const std::array<GridBoundary, 4>   &sides,
                                             const std::vector<grid::RigidWall>  &walls,
                                             const std::vector<grid::RigidSolid> &solids)
      : grid(grid)
      , nodes(nodes)
      , sides(sides)
      , walls(walls)
      , solids(solids)
    {
    }



    void
    VelocityConstraints::reinit()
    {
      // Sides 0, 1 (left, right) hold the x velocity for rollers; 2, 3 the y velocity;
      // fixed sides hold both.
      const dealii::DoFHandler<2> &dofs = grid.dof_handler();
      for (auto &list : constrained_dofs)
        list.clear();
      for (unsigned int side = 0; side < 4; ++side)
        {
          if (sides[side] == GridBoundary::free)
            continue;
          const dealii::IndexSet on_side
            = dealii::DoFTools::extract_boundary_dofs(
                dofs, dealii::ComponentMask(), {static_cast<dealii::types::boundary_id>(side)})
              & dofs.locally_owned_dofs();
          const unsigned int normal = side < 2 ? 0 : 1;
          for (unsigned int d = 0; d < 2; ++d)
            if (d == normal || sides[side] == GridBoundary::fixed)
              for (const auto index : on_side)
                constrained_dofs[d].push_back(nodes.local_index(index));
        }
      find_wall_nodes();
    }



    template <typename Predicate>
    std::vector<unsigned int>
    VelocityConstraints::owned_nodes_where(const Predicate &holds) const
    {
      std::vector<unsigned int> held;
      for (const auto &cell : grid.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto dof = cell->vertex_dof_index(v, 0);
              if (nodes.is_owned(dof) && holds(cell->vertex(v)))
                held.push_back(nodes.local_index(dof));
            }
      std::sort(held.begin(), held.end());
      held.erase(std::unique(held.begin(), held.end()), held.end());
      return held;
    }



    void
    VelocityConstraints::find_wall_nodes()
    {
      // (The supports only zero velocities: their order does not matter.)
      supports.clear();
      const double tolerance = 1e-6 * grid.cell_size();
      for (const auto &wall : walls)
        {
          WallNodes held;
          held.release_time                       = wall.release_time;
          const std::vector<unsigned int> on_wall = owned_nodes_where(
            [&](const dealii::Point<2> &x) { return wall.contains(x, tolerance); });
          for (unsigned int d = 0; d < 2; ++d)
            if (d == wall.normal_component() || wall.condition == grid::RigidWall::Condition::fixed)
              held.nodes[d] = on_wall;
          supports.push_back(held);
        }
      // A solid holds both components (no slip).
      for (const auto &solid : solids)
        {
          WallNodes held;
          held.release_time = solid.release_time;
          held.nodes[0]     = owned_nodes_where(
            [&](const dealii::Point<2> &x) { return solid.contains(x, tolerance); });
          held.nodes[1] = held.nodes[0];
          supports.push_back(held);
        }
    }



    void
    VelocityConstraints::update_walls(const double time, const bool hold_all)
    {
      for (auto &support : supports)
        support.active = hold_all || time < support.release_time;
    }
  } // namespace grid
} // namespace slidewave
