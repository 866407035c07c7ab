#ifndef slidewave_grid_nodal_workspace_h
#define slidewave_grid_nodal_workspace_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/grid_follower.h>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * The nodal quantities of the material point method on the background grid (paper
     * 000, Eqs. 14–19): lumped mass, momentum, force and the velocities before and after
     * the grid update, as deal.II distributed vectors (one per component, owned and ghost
     * nodes), plus what makes a step's grid work cheap:
     *
     * - the active nodes: the local indices of the nodes the points talk to, the parents
     *   of hanging ones among them and the owned nodes other ranks send to; outside them
     *   every nodal value is zero (a step clears last step's active nodes before it
     *   scatters);
     * - the nodal fields a particle model declares beyond those (its number of them,
     *   Model::n_nodal_fields, and how many a run uses): what its points scatter to the
     *   nodes and read back (a basal resistance, a volume, later a fluid's drag), each a
     *   distributed vector; the workspace holds no model's names;
     * - side-by-side arrays per node that the per-point loops read and write (the
     *   scatter's sums, five plus the model's fields, and the gather's four velocities);
     * - hanging-node condensation (sums to the parents) and interpolation (values from
     *   the parents), as local-index tables.
     *
     * A GridFollower: rebuilt on every change of the grid.
     */
    class NodalWorkspace : public GridFollower
    {
    public:
      using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

      /** Sums per node in node_sums before the model's fields: mass, momentum x, y,
       *  force x, y. */
      static constexpr unsigned int n_base_sums = 5;
      /** Values per node in node_velocities: v^new x, y, v^new - v^old x, y. */
      static constexpr unsigned int n_velocities = 4;

      /**
       * @p with_node_positions: keep the positions of the owned and ghost nodes (a
       * prescribed velocity field and APIC's affine transfer need them); @p n_model_fields: the
       * nodal fields the model declares (the stride of the scatter's sums is n_base_sums +
       * n_model_fields);
       * @p n_used_fields: how many of them (the first ones) this run uses, allocated as
       * vectors; @p with_lumped_area: keep 1 / the lumped area of each node.
       */
      NodalWorkspace(const BackgroundGrid &grid,
                     bool                  with_node_positions,
                     unsigned int          n_model_fields   = 0,
                     unsigned int          n_used_fields    = 0,
                     bool                  with_lumped_area = false);

      /** Vectors, arrays, import nodes and hanging nodes of the current grid. */
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

      /** Clears last step's nodal values on its active nodes and empties the list; the
       * scatter then marks the nodes of each cell it visits. */
      void
      clear_active_nodes();

      void
      mark_active(const unsigned int i)
      {
        if (node_is_active[i] == 0)
          {
            node_is_active[i] = 1;
            active_nodes.push_back(i);
          }
      }

      /** Adds the parents of active hanging nodes and the owned nodes other ranks send to. */
      void
      complete_active_nodes();

      /** Sums on hanging nodes go to their parents (before compress). */
      void
      condense_hanging_nodes(Vector &v) const;

      /** Hanging nodes take their parents' interpolated values (ghosted vectors). */
      void
      interpolate_hanging_nodes(Vector &v) const;

      /** The local indices of the hanging nodes (owned and ghost). */
      const std::vector<unsigned int> &
      hanging_nodes() const
      {
        return hanging_node;
      }

      /** The scatter's sums of local node @p i (n_sums() of them). */
      double *
      sums(const unsigned int i)
      {
        return node_sums.data() + stride * i;
      }

      /** Sums per node: n_base_sums plus the model's fields. */
      unsigned int
      n_sums() const
      {
        return stride;
      }

      /** The model's nodal fields this run uses. */
      unsigned int
      n_fields() const
      {
        return fields.size();
      }

      /** The gather's velocities of local node @p i (n_velocities of them). */
      double *
      velocities(const unsigned int i)
      {
        return node_velocities.data() + n_velocities * i;
      }

      const double *
      velocities(const unsigned int i) const
      {
        return node_velocities.data() + n_velocities * i;
      }

      const std::vector<unsigned int> &
      active() const
      {
        return active_nodes;
      }

      /** Position of owned or ghost node @p i (local index; only with_node_positions). */
      const dealii::Point<2> &
      position(const unsigned int i) const
      {
        return node_positions[i];
      }

      /** Local index of the global node (dof) @p index. */
      unsigned int
      local_index(const dealii::types::global_dof_index index) const
      {
        return nodal_mass.get_partitioner()->global_to_local(index);
      }

      bool
      is_owned(const dealii::types::global_dof_index index) const
      {
        return nodal_mass.get_partitioner()->in_local_range(index);
      }

      /** Lumped mass, momentum, force, velocity after and before the grid update. */
      Vector                nodal_mass;
      std::array<Vector, 2> momentum, force, velocity, velocity_old;
      /** The model's nodal fields (in the order of its declaration; n_used_fields of
       *  them), summed from the points like the mass. */
      std::vector<Vector> fields;
      /** 1 / the lumped area of each local node (with_lumped_area; otherwise empty). */
      std::vector<double> inverse_area;

    private:
      const BackgroundGrid &grid;
      const bool            with_positions;
      const unsigned int    stride;
      const bool            with_area;

      std::vector<unsigned int> active_nodes;
      /** Zero between steps. */
      std::vector<double>        node_sums;
      std::vector<double>        node_velocities;
      std::vector<unsigned char> node_is_active;
      /** Owned nodes (local indices) that are ghosts of other ranks. */
      std::vector<unsigned int> import_nodes;
      /** Hanging nodes (local indices) and their parents and weights:
       * hanging_parent[hanging_start[k] .. hanging_start[k+1]) for hanging_node[k]. */
      std::vector<unsigned int> hanging_node, hanging_start, hanging_parent;
      std::vector<double>       hanging_weight;
      /** Positions of the owned and ghost nodes (local index), only with_positions (a
       *  prescribed velocity, APIC). */
      std::vector<dealii::Point<2>> node_positions;
    };
  } // namespace grid
} // namespace slidewave

#endif
