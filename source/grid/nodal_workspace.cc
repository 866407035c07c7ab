#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <slidewave/grid/nodal_workspace.h>

namespace slidewave
{
  namespace grid
  {
    NodalWorkspace::NodalWorkspace(const BackgroundGrid &grid,
                                   const bool            with_node_positions,
                                   const unsigned int    n_model_fields,
                                   const unsigned int    n_used_fields,
                                   const bool            with_lumped_area)
      : fields(n_used_fields)
      , grid(grid)
      , with_positions(with_node_positions)
      , stride(n_base_sums + n_model_fields)
      , with_area(with_lumped_area)
    {
    }



    void
    NodalWorkspace::reinit()
    {
      const dealii::DoFHandler<2> &dofs  = grid.dof_handler();
      const dealii::IndexSet       owned = dofs.locally_owned_dofs();
      dealii::IndexSet             relevant;
      dealii::DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      nodal_mass.reinit(owned, relevant, MPI_COMM_WORLD);
      for (unsigned int d = 0; d < 2; ++d)
        {
          momentum[d].reinit(nodal_mass);
          force[d].reinit(nodal_mass);
          velocity[d].reinit(nodal_mass);
          velocity_old[d].reinit(nodal_mass);
        }
      for (Vector &field : fields)
        field.reinit(nodal_mass);
      if (with_area)
        {
          const Vector area = grid.lumped_nodal_area();
          const auto  &part = *area.get_partitioner();
          inverse_area.assign(part.locally_owned_size() + part.n_ghost_indices(), 0.);
          for (unsigned int i = 0; i < inverse_area.size(); ++i)
            inverse_area[i] = area.local_element(i) > 0. ? 1. / area.local_element(i) : 0.;
        }
      if (with_positions)
        {
          // The ghost nodes too: a point near the partition's edge scatters to them.
          const auto &partitioner = *nodal_mass.get_partitioner();
          node_positions.resize(partitioner.locally_owned_size() + partitioner.n_ghost_indices());
          for (const auto &cell : dofs.active_cell_iterators())
            if (!cell->is_artificial())
              for (const unsigned int v : cell->vertex_indices())
                {
                  const auto index = cell->vertex_dof_index(v, 0);
                  if (partitioner.in_local_range(index) || partitioner.is_ghost_entry(index))
                    node_positions[partitioner.global_to_local(index)] = cell->vertex(v);
                }
        }
      const auto &partitioner = nodal_mass.get_partitioner();
      active_nodes.clear();
      const unsigned int n_local
        = partitioner->locally_owned_size() + partitioner->n_ghost_indices();
      node_is_active.assign(n_local, 0);
      node_sums.assign(stride * n_local, 0.);
      node_velocities.assign(n_velocities * n_local, 0.);
      import_nodes.clear();
      for (const auto &[first, last] : partitioner->import_indices())
        for (unsigned int i = first; i < last; ++i)
          import_nodes.push_back(i);
      std::sort(import_nodes.begin(), import_nodes.end());
      import_nodes.erase(std::unique(import_nodes.begin(), import_nodes.end()), import_nodes.end());

      // Hanging nodes: each constrained node's parents and weights, as local indices.
      hanging_start.assign(1, 0);
      hanging_node.clear();
      hanging_parent.clear();
      hanging_weight.clear();
      dealii::AffineConstraints<double> constraints(relevant);
      dealii::DoFTools::make_hanging_node_constraints(dofs, constraints);
      constraints.close();
      for (const auto index : relevant)
        if (constraints.is_constrained(index))
          {
            hanging_node.push_back(partitioner->global_to_local(index));
            for (const auto &entry : *constraints.get_constraint_entries(index))
              {
                hanging_parent.push_back(partitioner->global_to_local(entry.first));
                hanging_weight.push_back(entry.second);
              }
            hanging_start.push_back(hanging_parent.size());
          }
    }



    void
    NodalWorkspace::clear_active_nodes()
    {
      // A model may send its fields to the ghost nodes (update_ghost_values): those values
      // must not return to their owners with the next compress.
      for (Vector &field : fields)
        field.zero_out_ghost_values();
      for (const unsigned int i : active_nodes)
        {
          nodal_mass.local_element(i) = 0.;
          for (unsigned int d = 0; d < 2; ++d)
            {
              momentum[d].local_element(i)     = 0.;
              force[d].local_element(i)        = 0.;
              velocity[d].local_element(i)     = 0.;
              velocity_old[d].local_element(i) = 0.;
            }
          for (Vector &field : fields)
            field.local_element(i) = 0.;
          node_is_active[i] = 0;
        }
      active_nodes.clear();
    }



    void
    NodalWorkspace::complete_active_nodes()
    {
      for (unsigned int k = 0; k < hanging_node.size(); ++k)
        if (node_is_active[hanging_node[k]] != 0)
          for (unsigned int e = hanging_start[k]; e < hanging_start[k + 1]; ++e)
            mark_active(hanging_parent[e]);
      for (const unsigned int i : import_nodes)
        mark_active(i);
    }



    void
    NodalWorkspace::condense_hanging_nodes(Vector &v) const
    {
      // What was gathered on a hanging node belongs to the nodes it is interpolated from
      // (the transpose of the interpolation): mass, momentum and force are conserved.
      for (unsigned int k = 0; k < hanging_node.size(); ++k)
        {
          const double value = v.local_element(hanging_node[k]);
          for (unsigned int e = hanging_start[k]; e < hanging_start[k + 1]; ++e)
            v.local_element(hanging_parent[e]) += hanging_weight[e] * value;
          v.local_element(hanging_node[k]) = 0.;
        }
    }



    void
    NodalWorkspace::interpolate_hanging_nodes(Vector &v) const
    {
      // On ghosted vectors: a hanging node's value from its parents, so that the field is
      // continuous across the coarse-fine faces.
      for (unsigned int k = 0; k < hanging_node.size(); ++k)
        {
          double value = 0.;
          for (unsigned int e = hanging_start[k]; e < hanging_start[k + 1]; ++e)
            value += hanging_weight[e] * v.local_element(hanging_parent[e]);
          v.local_element(hanging_node[k]) = value;
        }
    }
  } // namespace grid
} // namespace slidewave
