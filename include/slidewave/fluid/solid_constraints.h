#ifndef slidewave_fluid_solid_constraints_h
#define slidewave_fluid_solid_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <slidewave/grid/rigid_solid.h>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * Holds the velocity at zero inside rigid solids: every velocity dof (components 0
     * and 1 of the flow's element) whose support point lies inside a solid or on its
     * edges (within @p tolerance) and that @p constraints can store and does not
     * constrain yet (a hanging node keeps its interpolation, its parents inside the solid
     * are held) gets a zero line. The cells are axis-aligned
     * rectangles, so a support point is x = v_0 + (xi h_x, eta h_y). Works for Q1 and Q2.
     */
    void
    add_solid_constraints(const dealii::DoFHandler<2>         &dofs,
                          const std::vector<grid::RigidSolid> &solids,
                          double                               tolerance,
                          dealii::AffineConstraints<double>   &constraints);
  } // namespace fluid
} // namespace slidewave

#endif
