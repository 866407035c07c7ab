#include <cmath>
#include <deal.II/base/utilities.h>
#include <exception>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/rigid_bodies.h>

namespace slidewave
{
  namespace grid
  {
    void
    declare_rigid_body_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      for (unsigned int w = 1; w <= max_rigid_bodies; ++w)
        {
          prm.enter_subsection("Rigid wall " + std::to_string(w));
          prm.declare_entry("Type",
                            "none",
                            Selection("none|roller|fixed|solid"),
                            "'none': this wall is not used. 'roller': the nodes on the wall "
                            "keep zero normal velocity (free slip). 'fixed': zero velocity (no "
                            "slip). 'solid': a rigid body, the polygon 'Polygon'; every node "
                            "inside it or on its edges keeps zero velocity (no slip; an "
                            "inclined plane across the cells becomes a staircase of held "
                            "nodes). In granular water the water's velocity is held at the "
                            "same nodes, and no point is created inside the solid.");
          RigidWall::declare_parameters(prm);
          RigidSolid::declare_parameters(prm);
          prm.declare_entry("Release time",
                            "never",
                            Anything(),
                            "'never' for a permanent wall, or the time [s] at which this "
                            "support is removed (it holds while t < release time; it also "
                            "holds during gravity loading).");
          prm.leave_subsection();
        }
    }



    void
    parse_rigid_body_parameters(dealii::ParameterHandler &prm,
                                const std::string        &path,
                                const dealii::Point<2>   &lower_left,
                                const dealii::Point<2>   &upper_right,
                                const double              cell_size,
                                const bool                adaptive,
                                std::vector<RigidWall>   &walls,
                                std::vector<RigidSolid>  &solids)
    {
      walls.clear();
      solids.clear();
      for (unsigned int w = 1; w <= max_rigid_bodies; ++w)
        {
          const std::string subsection = "Rigid wall " + std::to_string(w);
          prm.enter_subsection(subsection);
          const std::string type = prm.get("Type");
          if (type == "solid")
            {
              RigidSolid solid;
              solid.parse_parameters(prm, path + "/" + subsection);
              solid.check_in_grid(lower_left, upper_right, cell_size, adaptive);
              solids.push_back(solid);
            }
          else if (type != "none")
            {
              RigidWall wall;
              wall.parse_parameters(prm, path + "/" + subsection);
              walls.push_back(wall);
            }
          prm.leave_subsection();
        }
    }



    double
    parse_release_time(dealii::ParameterHandler &prm, const std::string &path)
    {
      const std::string release = dealii::Utilities::trim(prm.get("Release time"));
      if (release == "never")
        return std::numeric_limits<double>::infinity();
      double release_time = 0.;
      bool   ok           = true;
      try
        {
          std::size_t used = 0;
          release_time     = std::stod(release, &used);
          ok               = used == release.size() && std::isfinite(release_time);
        }
      catch (const std::exception &)
        {
          ok = false;
        }
      if (!ok)
        throw InputError(path + "/Release time", release, "'never' or a time [s]");
      return release_time;
    }
  } // namespace grid
} // namespace slidewave
