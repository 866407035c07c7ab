#include <deal.II/fe/fe.h>
#include <slidewave/fluid/solid_constraints.h>

namespace slidewave
{
  namespace fluid
  {
    void
    add_solid_constraints(const dealii::DoFHandler<2>         &dofs,
                          const std::vector<grid::RigidSolid> &solids,
                          const double                         tolerance,
                          dealii::AffineConstraints<double>   &constraints)
    {
      if (solids.empty())
        return;
      const auto                                  &fe          = dofs.get_fe();
      const std::vector<dealii::Point<2>>          unit_points = fe.get_unit_support_points();
      std::vector<dealii::types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(cell_dofs);
            const dealii::Point<2> origin = cell->vertex(0);
            const double           hx     = cell->vertex(1)[0] - origin[0];
            const double           hy     = cell->vertex(2)[1] - origin[1];
            for (unsigned int i = 0; i < cell_dofs.size(); ++i)
              if (fe.system_to_component_index(i).first < 2
                  && constraints.can_store_line(cell_dofs[i])
                  && !constraints.is_constrained(cell_dofs[i]))
                {
                  const dealii::Point<2> x(origin[0] + unit_points[i][0] * hx,
                                           origin[1] + unit_points[i][1] * hy);
                  for (const auto &solid : solids)
                    if (solid.contains(x, tolerance))
                      {
                        constraints.add_line(cell_dofs[i]);
                        break;
                      }
                }
          }
    }
  } // namespace fluid
} // namespace slidewave
