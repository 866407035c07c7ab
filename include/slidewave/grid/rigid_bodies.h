#ifndef slidewave_grid_rigid_bodies_h
#define slidewave_grid_rigid_bodies_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <slidewave/grid/rigid_solid.h>
#include <slidewave/grid/rigid_wall.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    // The subsections "Rigid wall 1" ... of a scene: each, by its 'Type', unused ('none'),
    // a segment ('roller' or 'fixed': a RigidWall) or a polygon ('solid': a RigidSolid).
    // One syntax for both: the subsection's entries are declared and dispatched here.

    /** Subsections "Rigid wall 1" ... a scene may declare. */
    constexpr unsigned int max_rigid_bodies = 4;

    /** Declares the subsections "Rigid wall 1" ... "Rigid wall max_rigid_bodies" in the
     *  handler's current subsection, each with 'Type', a wall's ends (RigidWall), a
     *  solid's polygon (RigidSolid) and 'Release time'. */
    void
    declare_rigid_body_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads those subsections of the section at @p path, in order: each 'roller' or
     * 'fixed' one into @p walls, each 'solid' into @p solids, checked as soon as it is read
     * (RigidSolid::check_in_grid()) against the grid [@p lower_left, @p upper_right] of
     * cells @p cell_size, @p adaptive or not. Both lists are cleared first. Throws an
     * InputError naming the first invalid parameter.
     */
    void
    parse_rigid_body_parameters(dealii::ParameterHandler &prm,
                                const std::string        &path,
                                const dealii::Point<2>   &lower_left,
                                const dealii::Point<2>   &upper_right,
                                double                    cell_size,
                                bool                      adaptive,
                                std::vector<RigidWall>   &walls,
                                std::vector<RigidSolid>  &solids);

    /** The 'Release time' of the "Rigid wall N" at @p path (the handler inside it): the
     *  time [s], or infinity for 'never'. Throws an InputError otherwise. */
    double
    parse_release_time(dealii::ParameterHandler &prm, const std::string &path);
  } // namespace grid
} // namespace slidewave

#endif
