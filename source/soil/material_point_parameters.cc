#include <cmath>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/grid_extent.h>
#include <slidewave/grid/load_balancing_parameters.h>
#include <slidewave/grid/rigid_bodies.h>
#include <slidewave/particles/point_count.h>
#include <slidewave/soil/material_point_parameters.h>
#include <slidewave/soil/material_point_scheme_parameters.h>
#include <sstream>

namespace slidewave
{
  namespace soil
  {
    namespace
    {
      GridBoundary
      boundary_type(const std::string &name)
      {
        return name == "fixed"  ? GridBoundary::fixed :
               name == "roller" ? GridBoundary::roller :
                                  GridBoundary::free;
      }



      /** How the points find their cells after a step, and how the step is timed. */
      void
      declare_relocation_and_timing_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.declare_entry("Particle relocation",
                          "neighbour cells",
                          Selection("neighbour cells|full sort"),
                          "How the points find their cells after moving. 'neighbour cells': "
                          "each point looks in the cells of its old cell's patch (a step moves "
                          "a point less than a cell) and only the points that changed cell are "
                          "moved in the particle handler; when any point on any rank leaves "
                          "its rank's cells or the patch, and every 'Load balancing/Interval' "
                          "steps (to keep the points' memory in cell order), deal.II's full "
                          "sort runs instead. 'full sort': deal.II's sort every step. Both "
                          "give the same cells and reference coordinates.");
        prm.declare_entry("Detailed timing",
                          "false",
                          Bool(),
                          "Time the parts of each step (grid changes, particle to grid, grid "
                          "update, grid to particle with the stresses, MUSL re-map, sorting "
                          "the points into cells) as rows 'mpm step: ...' of the timer summary. "
                          "Each rank times its own parts (no barriers); with several ranks "
                          "a table of each part's least, mean and largest time over the ranks "
                          "comes first, and a rank waiting for another shows in the part where "
                          "it waits (the ghost exchange of the scatter, the relocation's "
                          "reduction).");
        prm.declare_entry("Step timeline",
                          "false",
                          Bool(),
                          "Write OUTPUT/step_timeline.csv at the end of the run: per step and "
                          "per rank the wall time of each part of the step, with the exchanges "
                          "between ranks (where a rank waits for a slower one) apart from the "
                          "rank's own work. For profiling runs: it keeps a row per step in "
                          "memory (doc/mpm.md, Where the time goes).");
      }



      /** Local damping, the points seeded per cell and the prescribed-velocity mode. */
      void
      declare_damping_and_point_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.declare_entry("Local damping",
                          "0",
                          Double(0., 1.),
                          "Cundall's local non-viscous damping coefficient of the nodal "
                          "forces, for quasi-static loading; 0 for dynamics.");
        prm.declare_entry("Particles per direction",
                          "2",
                          Integer(1, 10),
                          "Material points per cell per direction at the start (n x n per "
                          "cell, at the centres of n x n sub-cells).");
        prm.declare_entry("Prescribed velocity",
                          "",
                          Anything(),
                          "Kinematic verification mode: if not empty, two expressions of x, y "
                          "and t separated by ';' (e.g. '-(y-0.5); x-0.5', a rigid rotation): "
                          "the nodal velocities are this field instead of the solution of the "
                          "momentum balance (Eqs. 18-19); the points move with it and their "
                          "stresses follow from it as usual (strain rate, Jaumann rate, "
                          "B-bar), and their velocities are the field's at their positions "
                          "(PIC, whatever 'Velocity transfer' and 'FLIP fraction' say).");
      }



      /** Subsections "Grid", "Adaptive grid", "Load balancing" and "Boundary conditions". */
      void
      declare_grid_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Grid");
        grid::GridExtent::declare_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Adaptive grid");
        {
          prm.declare_entry("Enable",
                            "false",
                            Bool(),
                            "Refine the background grid where material is (to 'Cell size') and "
                            "keep it coarse elsewhere; re-evaluated every 'Interval' steps.");
          prm.declare_entry("Levels",
                            "2",
                            Integer(1, 8),
                            "Refinement levels: the coarsest cells are 2^Levels times 'Cell "
                            "size', which must divide the domain.");
          prm.declare_entry("Buffer cells",
                            "2",
                            Integer(0, 10),
                            "Layers of fine cells kept around the material (GIMP domains and "
                            "the motion until the next adaptation reach there).");
          prm.declare_entry("Interval",
                            "50",
                            Integer(1),
                            "Steps between adaptations; material must not cross the buffer in "
                            "that time.");
        }
        prm.leave_subsection();
        prm.enter_subsection("Load balancing");
        grid::LoadBalancingParameters::declare_parameters(
          prm,
          " With 'Physics = granular water' each degree of freedom of the water and of its "
          "phase field weighs 1000000 (16 per cell), whatever this is: the water's step is "
          "most of that physics' work, on every cell (doc/granular-water.md, Speed, "
          "\"Partition\").");
        prm.leave_subsection();
        prm.enter_subsection("Boundary conditions");
        for (const std::string side : {"Left", "Right", "Bottom", "Top"})
          prm.declare_entry(side,
                            side == "Bottom" ? "fixed" :
                            side == "Top"    ? "free" :
                                               "roller",
                            Selection("free|roller|fixed"),
                            "Grid velocity condition on this side: 'fixed' (no slip), "
                            "'roller' (free slip), 'free'.");
        prm.leave_subsection();
      }



      /** Subsection "Initial stress". */
      void
      declare_initial_stress_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Initial stress");
        {
          prm.declare_entry("Type",
                            "none",
                            Selection("none|geostatic|gravity loading|uniform"),
                            "'none': stress free. 'geostatic': sigma_yy = -g (weight of the "
                            "material above the point per unit width), sigma_xx = sigma_zz = "
                            "K0 sigma_yy (at rest, exact for horizontal layers). 'gravity "
                            "loading': gravity is applied with heavy local damping and all "
                            "rigid walls held, for 'Gravity loading time', before the start "
                            "time; then velocities are zeroed and the scene starts. "
                            "'uniform': 'Uniform stress' in every point.");
          prm.declare_entry("Uniform stress",
                            "0, 0, 0, 0",
                            Anything(),
                            "For 'uniform': sigma_xx, sigma_yy, sigma_xy, sigma_zz [Pa], "
                            "tension positive.");
          prm.declare_entry("K0",
                            "auto",
                            Anything(),
                            "Coefficient of earth pressure at rest for 'geostatic': a number "
                            "> 0, or 'auto': 1 - sin(phi) (Jaky) for Drucker-Prager, "
                            "nu / (1 - nu) for linear elastic materials.");
          prm.declare_entry("Gravity loading time",
                            "0.5",
                            Double(0.),
                            "Duration [s] of the gravity loading phase; give it several "
                            "periods of the slowest mode (about 4 H / c_p).");
          prm.declare_entry("Gravity loading damping",
                            "0.7",
                            Double(0., 1.),
                            "Cundall's local damping coefficient during gravity loading.");
        }
        prm.leave_subsection();
      }



      /** Subsections "Grid", "Adaptive grid", "Load balancing" and "Boundary conditions";
       *  the adaptive grid's coarsest cells must divide the domain. */
      void
      parse_grid_parameters(dealii::ParameterHandler &prm,
                            const std::string        &path,
                            MaterialPointParameters  &parameters)
      {
        prm.enter_subsection("Grid");
        {
          grid::GridExtent extent;
          extent.parse_parameters(prm, path + "/Grid");
          parameters.lower_left  = extent.lower_left;
          parameters.upper_right = extent.upper_right;
          parameters.cell_size   = extent.cell_size;
        }
        prm.leave_subsection();

        prm.enter_subsection("Adaptive grid");
        {
          parameters.adaptivity.enabled      = prm.get_bool("Enable");
          parameters.adaptivity.levels       = prm.get_integer("Levels");
          parameters.adaptivity.buffer_cells = prm.get_integer("Buffer cells");
          parameters.adaptivity.interval     = prm.get_integer("Interval");
          if (parameters.adaptivity.enabled)
            {
              const double base = parameters.cell_size * (1u << parameters.adaptivity.levels);
              for (unsigned int d = 0; d < 2; ++d)
                {
                  const double n = (parameters.upper_right[d] - parameters.lower_left[d]) / base;
                  if (std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
                    throw InputError(
                      path + "/Adaptive grid/Levels",
                      std::to_string(parameters.adaptivity.levels),
                      "a number of levels such that the coarsest cells (Cell "
                      "size x 2^Levels = "
                        + to_string(base) + " m) divide the domain sides ("
                        + to_string(parameters.upper_right[0] - parameters.lower_left[0]) + " x "
                        + to_string(parameters.upper_right[1] - parameters.lower_left[1]) + " m)");
                }
            }
        }
        prm.leave_subsection();

        prm.enter_subsection("Load balancing");
        {
          grid::LoadBalancingParameters balancing;
          balancing.parse_parameters(prm);
          parameters.adaptivity.particle_weight     = balancing.particle_weight;
          parameters.adaptivity.imbalance_threshold = balancing.imbalance_threshold;
          parameters.balance_interval               = balancing.interval;
        }
        prm.leave_subsection();

        prm.enter_subsection("Boundary conditions");
        parameters.boundaries = {{boundary_type(prm.get("Left")),
                                  boundary_type(prm.get("Right")),
                                  boundary_type(prm.get("Bottom")),
                                  boundary_type(prm.get("Top"))}};
        prm.leave_subsection();
      }



      /** "Prescribed velocity": empty, or the two components of the kinematic mode. */
      void
      parse_prescribed_velocity(dealii::ParameterHandler &prm,
                                const std::string        &path,
                                MaterialPointParameters  &parameters)
      {
        const std::string text = dealii::Utilities::trim(prm.get("Prescribed velocity"));
        parameters.prescribed_velocity.reset();
        if (!text.empty())
          {
            // deal.II prints muparser's diagnosis to std::cerr before it throws: keep it
            // quiet, the InputError says what is wrong.
            std::ostringstream diagnosis;
            std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
            try
              {
                if (dealii::Utilities::split_string_list(text, ';').size() != 2)
                  throw std::invalid_argument("two components");
                parameters.prescribed_velocity = std::make_shared<dealii::FunctionParser<2>>(2);
                parameters.prescribed_velocity->initialize("x,y,t",
                                                           text,
                                                           {{"pi", M_PI}},
                                                           /*time_dependent=*/true);
                parameters.prescribed_velocity->value(dealii::Point<2>(), 0);
                std::cerr.rdbuf(cerr_buffer);
              }
            catch (...)
              {
                std::cerr.rdbuf(cerr_buffer);
                throw InputError(path + "/Prescribed velocity",
                                 text,
                                 "empty, or two expressions of x, y and t separated by ';'");
              }
          }
      }



      /** Subsection "Initial stress": the type, the uniform stress, K0 and the gravity
       *  loading phase. */
      void
      parse_initial_stress_parameters(dealii::ParameterHandler &prm,
                                      const std::string        &path,
                                      MaterialPointParameters  &parameters)
      {
        prm.enter_subsection("Initial stress");
        {
          const std::string type    = prm.get("Type");
          parameters.initial_stress = type == "geostatic"       ? InitialStress::geostatic :
                                      type == "gravity loading" ? InitialStress::gravity_loading :
                                      type == "uniform"         ? InitialStress::uniform :
                                                                  InitialStress::none;
          {
            const auto stress
              = parse_number_list(path + "/Initial stress/Uniform stress",
                                  prm.get("Uniform stress"),
                                  "four finite numbers sigma_xx, sigma_yy, sigma_xy, sigma_zz [Pa]",
                                  4);
            std::copy(stress.begin(), stress.end(), parameters.uniform_stress.begin());
          }
          const std::string k0 = dealii::Utilities::trim(prm.get("K0"));
          if (k0 == "auto")
            parameters.lateral_stress_ratio = -1.;
          else
            {
              bool ok = true;
              try
                {
                  std::size_t used                = 0;
                  parameters.lateral_stress_ratio = std::stod(k0, &used);
                  ok = used == k0.size() && std::isfinite(parameters.lateral_stress_ratio)
                       && parameters.lateral_stress_ratio > 0.;
                }
              catch (const std::exception &)
                {
                  ok = false;
                }
              if (!ok)
                throw InputError(path + "/Initial stress/K0", k0, "'auto' or a number > 0");
            }
          parameters.gravity_loading_time    = prm.get_double("Gravity loading time");
          parameters.gravity_loading_damping = prm.get_double("Gravity loading damping");
          if (parameters.initial_stress == InitialStress::gravity_loading)
            require_positive(path + "/Initial stress/Gravity loading time",
                             parameters.gravity_loading_time);
        }
        prm.leave_subsection();
      }



      /** The "Region N" subsections in use, each checked to lie inside the grid. */
      void
      parse_regions(dealii::ParameterHandler &prm,
                    const std::string        &path,
                    MaterialPointParameters  &parameters)
      {
        parameters.regions.clear();
        for (unsigned int r = 1; r <= particles::MaterialRegion::max_regions; ++r)
          {
            prm.enter_subsection("Region " + std::to_string(r));
            particles::MaterialRegion region;
            const std::string         region_path = path + "/Region " + std::to_string(r);
            if (region.parse_parameters(prm, region_path))
              {
                const std::string entry = prm.get("Shape") == "rectangle" ? "Rectangle" : "Polygon";
                const auto        box   = region.bounding_box();
                for (unsigned int d = 0; d < 2; ++d)
                  if (box.first[d] < parameters.lower_left[d] - 1e-12
                      || box.second[d] > parameters.upper_right[d] + 1e-12)
                    throw InputError(region_path + "/" + entry,
                                     prm.get(entry),
                                     "a region inside the grid ["
                                       + to_string(parameters.lower_left[0]) + ", "
                                       + to_string(parameters.upper_right[0]) + "] x ["
                                       + to_string(parameters.lower_left[1]) + ", "
                                       + to_string(parameters.upper_right[1]) + "]");
                parameters.regions.push_back(region);
              }
            prm.leave_subsection();
          }
      }



      /** The "Material N" subsections the regions name, each read once; sets each region's
       *  material index. */
      void
      parse_used_materials(dealii::ParameterHandler &prm,
                           const std::string        &path,
                           MaterialPointParameters  &parameters)
      {
        parameters.materials.clear();
        for (unsigned int r = 0; r < parameters.regions.size(); ++r)
          {
            particles::MaterialRegion &region      = parameters.regions[r];
            const std::string          region_path = path + "/Region " + std::to_string(r + 1);
            std::vector<unsigned int>  slots;
            for (unsigned int m = 1; m <= MaterialPointParameters::max_materials; ++m)
              {
                prm.enter_subsection("Material " + std::to_string(m));
                if (dealii::Utilities::trim(prm.get("Name")) == region.material_name)
                  slots.push_back(m);
                prm.leave_subsection();
              }
            if (slots.empty())
              throw InputError(region_path + "/Material",
                               region.material_name,
                               "the name of a declared material ('Material N/Name')");
            if (slots.size() > 1)
              throw InputError(region_path + "/Material",
                               region.material_name,
                               "a material name declared once (it is the name of 'Material "
                                 + std::to_string(slots[0]) + "' and 'Material "
                                 + std::to_string(slots[1]) + "')");
            // Read each used material once, however many regions use it.
            region.material_index = parameters.materials.size();
            for (unsigned int k = 0; k < parameters.materials.size(); ++k)
              if (parameters.materials[k].name == region.material_name)
                region.material_index = k;
            if (region.material_index == parameters.materials.size())
              {
                const std::string slot = "Material " + std::to_string(slots[0]);
                prm.enter_subsection(slot);
                materials::MaterialParameters material;
                material.parse_parameters(prm, path + "/" + slot);
                material.name = region.material_name;
                prm.leave_subsection();
                parameters.materials.push_back(material);
              }
          }
      }
    } // namespace



    void
    MaterialPointParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      declare_scheme_parameters(prm);
      declare_relocation_and_timing_parameters(prm);
      declare_damping_and_point_parameters(prm);
      declare_grid_parameters(prm);
      grid::declare_rigid_body_parameters(prm);
      declare_initial_stress_parameters(prm);
      for (unsigned int m = 1; m <= max_materials; ++m)
        {
          prm.enter_subsection("Material " + std::to_string(m));
          materials::MaterialParameters::declare_parameters(prm);
          prm.leave_subsection();
        }
      for (unsigned int r = 1; r <= particles::MaterialRegion::max_regions; ++r)
        {
          prm.enter_subsection("Region " + std::to_string(r));
          particles::MaterialRegion::declare_parameters(prm);
          prm.leave_subsection();
        }
    }



    void
    MaterialPointParameters::parse_parameters(dealii::ParameterHandler &prm,
                                              const std::string        &path)
    {
      parse_scheme_parameters(prm, path, *this);
      detailed_timing         = prm.get_bool("Detailed timing");
      step_timeline           = prm.get_bool("Step timeline");
      full_sort_every_step    = prm.get("Particle relocation") == "full sort";
      damping                 = prm.get_double("Local damping");
      particles_per_direction = prm.get_integer("Particles per direction");

      parse_grid_parameters(prm, path, *this);

      grid::parse_rigid_body_parameters(
        prm, path, lower_left, upper_right, cell_size, adaptivity.enabled, walls, solids);

      parse_prescribed_velocity(prm, path, *this);

      parse_initial_stress_parameters(prm, path, *this);

      // Regions first: they say which materials the scene uses. Only those material
      // subsections are read (and checked); the others are ignored.
      parse_regions(prm, path, *this);
      parse_used_materials(prm, path, *this);
      // A finite-strain point's volume ratio is the J of its stress (FiniteStrainPoints).
      if (own_volumes)
        for (const auto &material : materials)
          if (material.model == materials::MaterialModel::hencky_drucker_prager)
            throw InputError(path + "/B-bar point volumes",
                             "own",
                             "cell mean with a 'hencky drucker prager' material ('" + material.name
                               + "': its volume ratio is its stress's J, which takes "
                                 "the cell's mean dilatation)");
      if (shape_function == grid::ShapeFunction::bspline && adaptivity.enabled)
        throw InputError(path + "/Shape functions",
                         "bspline",
                         "q1, gimp or cpgimp with an adaptive grid (a B-spline's domain is a "
                         "cell of the point's own cell's size, which would jump where the "
                         "cells change size)");
      if (regions.empty())
        throw InputError(path + "/Region 1/Shape",
                         "none",
                         "at least one region filled with material ('rectangle' or "
                         "'polygon')");
    }



    void
    MaterialPointParameters::add_to_memory_estimate(core::MemoryEstimate &estimate,
                                                    const std::string    &path) const
    {
      estimate.add("grid cells",
                   particles::grid_cell_count(lower_left, upper_right, cell_size),
                   core::MemoryEstimate::bytes_per_grid_cell,
                   path + "/Grid/Cell size",
                   to_string(cell_size));
      estimate.add("material points",
                   particles::point_count_bound(
                     regions, lower_left, upper_right, cell_size, particles_per_direction),
                   core::MemoryEstimate::bytes_per_point,
                   path + "/Particles per direction",
                   std::to_string(particles_per_direction));
    }
  } // namespace soil
} // namespace slidewave
