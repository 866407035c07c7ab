#ifndef slidewave_grid_velocity_constraints_h
#define slidewave_grid_velocity_constraints_h

#include <array>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/grid_boundary.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/rigid_solid.h>
#include <slidewave/grid/rigid_wall.h>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * The nodal velocities held at zero (the boundary conditions of the grid update,
     * paper 000, Eqs. 18–19): on the sides of the grid (left, right, bottom, top: ids
     * 0–3) by their GridBoundary, on the rigid walls, in the normal direction (roller)
     * or both (fixed), and inside the rigid solids and on their edges, in both; a wall or
     * solid with a release time holds only until then. A GridFollower: the held nodes are
     * found anew on every change of the grid.
     */
    class VelocityConstraints : public GridFollower
    {
    public:
      /** The constraints on @p grid's nodes (@p nodes: their local indices) by @p sides,
       *  @p walls and @p solids (either empty: none). */
      VelocityConstraints(const BackgroundGrid                &grid,
                          const NodalWorkspace                &nodes,
                          const std::array<GridBoundary, 4>   &sides,
                          const std::vector<grid::RigidWall>  &walls,
                          const std::vector<grid::RigidSolid> &solids);

      /** The held nodes of the sides, walls and solids on the current grid. */
      void
      reinit();

      void
      grid_ready() override
      {
        reinit();
      }

      void
      grid_changed() override
      {
        reinit();
      }

      /** Which walls and solids hold at @p time: those not yet released, or all when
       *  @p hold_all (gravity loading). */
      void
      update_walls(double time, bool hold_all);

      /** Zeroes the held components of the nodal velocities @p vx, @p vy. */
      template <typename VectorType>
      void
      apply(VectorType &vx, VectorType &vy) const
      {
        for (const auto index : constrained_dofs[0])
          vx.local_element(index) = 0.;
        for (const auto index : constrained_dofs[1])
          vy.local_element(index) = 0.;
        for (const auto &support : supports)
          if (support.active)
            {
              for (const auto index : support.nodes[0])
                vx.local_element(index) = 0.;
              for (const auto index : support.nodes[1])
                vy.local_element(index) = 0.;
            }
      }

      const std::array<GridBoundary, 4> &
      boundaries() const
      {
        return sides;
      }

    private:
      /** The owned nodes of each rigid wall, then of each rigid solid. */
      void
      find_wall_nodes();

      /** The local indices, sorted and unique, of the owned nodes at which @p holds (a
       *  wall's or solid's contains() with the tolerance) is true. */
      template <typename Predicate>
      std::vector<unsigned int>
      owned_nodes_where(const Predicate &holds) const;

      const BackgroundGrid               &grid;
      const NodalWorkspace               &nodes;
      const std::array<GridBoundary, 4>   sides;
      const std::vector<grid::RigidWall>  walls;
      const std::vector<grid::RigidSolid> solids;

      /** Local indices of owned nodes where v_x (0) or v_y (1) is held at zero. */
      std::array<std::vector<unsigned int>, 2> constrained_dofs;

      /** A rigid wall's or solid's owned nodes (local indices) per held component. */
      struct WallNodes
      {
        std::array<std::vector<unsigned int>, 2> nodes;
        double                                   release_time;
        bool                                     active = true;
      };
      std::vector<WallNodes> supports;
    };
  } // namespace grid
} // namespace slidewave

#endif
