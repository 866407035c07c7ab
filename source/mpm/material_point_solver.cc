#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <limits>
#include <optional>
#include <slidewave/core/input_error.h>
#include <slidewave/mpm/material_point_solver.h>
#include <slidewave/mpm/particle_properties.h>
#include <sstream>

namespace slidewave
{
  namespace mpm
  {
    namespace
    {
      std::vector<double>
      parse_numbers(const std::string &parameter, const std::string &text, const unsigned int count)
      {
        return parse_number_list(parameter,
                                 text,
                                 std::to_string(count) + " comma-separated numbers",
                                 count);
      }

      GridBoundary
      boundary_type(const std::string &name)
      {
        return name == "fixed"  ? GridBoundary::fixed :
               name == "roller" ? GridBoundary::roller :
                                  GridBoundary::free;
      }

    } // namespace



    void
    SolverParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Shape functions",
                        "q1",
                        Selection("q1|gimp|cpgimp"),
                        "'q1': bilinear functions of the cell holding the point (standard "
                        "MPM). 'gimp': uGIMP, Q1 averaged over a square domain of the "
                        "point's initial size (paper 000, Eq. 11), smooth across cell faces "
                        "(no cell-crossing noise). 'cpgimp': the domain stretches with the "
                        "point along x and y.");
      prm.declare_entry("Update scheme",
                        "usl",
                        Selection("usl|musl"),
                        "'usl': stresses from the updated nodal velocities (update stress "
                        "last, paper 000). 'musl': from nodal velocities re-mapped from the "
                        "updated particle velocities (less noisy for fast flows).");
      prm.declare_entry("FLIP fraction",
                        "0.99",
                        Double(0., 1.),
                        "Blend of the particle velocity update: 1 is pure FLIP (increments "
                        "of the nodal velocities, no dissipation, noisy), 0 pure PIC (nodal "
                        "velocities, dissipative).");
      prm.declare_entry("Time step multiplier",
                        "0.5",
                        Double(),
                        "alpha in dt = alpha h / max_p (c_p + |v_p|) (paper 000, Eq. 23); "
                        "in (0, 0.7071]: with lumped mass the highest mode of a 2D grid is "
                        "sqrt(2) times faster than along a line, so alpha above 1/sqrt(2) is "
                        "unstable (doc/stability.md).");
      prm.declare_entry("Fixed time step",
                        "0",
                        Double(0.),
                        "If > 0, this time step [s] instead of Eq. 23 (it is checked against "
                        "the stability limit at the start).");
      prm.declare_entry("B-bar",
                        "true",
                        Bool(),
                        "Average the volumetric strain increment over each cell (B-bar / "
                        "mean dilatation, paper 000 §3.1) against volumetric locking.");
      prm.declare_entry("Gravity", "0, -9.81", Anything(), "Gravity vector g_x, g_y [m/s^2].");
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
                        "B-bar).");
      prm.enter_subsection("Grid");
      {
        prm.declare_entry("Lower left", "0, 0", Anything(), "Corner x, y of the domain [m].");
        prm.declare_entry("Upper right", "1, 1", Anything(), "Corner x, y of the domain [m].");
        prm.declare_entry("Cell size",
                          "0.05",
                          Double(),
                          "Side of the square background cells [m]; the domain sides must "
                          "be (close to) multiples of it.");
      }
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
      {
        prm.declare_entry("Particle weight",
                          "1000000",
                          Integer(0),
                          "Cost of a material point relative to a cell's 1000 when the grid "
                          "is partitioned among MPI ranks (the work of a rank is 1000 per "
                          "cell plus this per point; a cell's weight is capped at 2^31 - 1, "
                          "p4est's limit). A step's grid work is over the nodes the points "
                          "talk to, so an empty cell costs next to nothing: the default makes "
                          "1000 empty cells weigh as much as a point (doc/mpm.md, "
                          "Throughput).");
        prm.declare_entry("Imbalance threshold",
                          "1.1",
                          Double(0.),
                          "Repartition when the most loaded rank has more than this times "
                          "the mean work (0: never, except when an adaptive grid changes).");
        prm.declare_entry("Interval", "50", Integer(1), "Steps between checks of the imbalance.");
      }
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
      for (unsigned int w = 1; w <= RigidWall::max_walls; ++w)
        {
          prm.enter_subsection("Rigid wall " + std::to_string(w));
          RigidWall::declare_parameters(prm);
          prm.leave_subsection();
        }
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
      for (unsigned int m = 1; m <= max_materials; ++m)
        {
          prm.enter_subsection("Material " + std::to_string(m));
          materials::MaterialParameters::declare_parameters(prm);
          prm.leave_subsection();
        }
      for (unsigned int r = 1; r <= MaterialRegion::max_regions; ++r)
        {
          prm.enter_subsection("Region " + std::to_string(r));
          MaterialRegion::declare_parameters(prm);
          prm.leave_subsection();
        }
    }



    void
    SolverParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      const std::string shape = prm.get("Shape functions");
      shape_function          = shape == "gimp"   ? ShapeFunction::gimp :
                                shape == "cpgimp" ? ShapeFunction::cpgimp :
                                                    ShapeFunction::q1;
      update_scheme = prm.get("Update scheme") == "musl" ? UpdateScheme::musl : UpdateScheme::usl;
      flip_fraction = prm.get_double("FLIP fraction");
      time_step_multiplier = prm.get_double("Time step multiplier");
      if (!(time_step_multiplier > 0. && time_step_multiplier <= max_time_step_multiplier))
        throw InputError(path + "/Time step multiplier",
                         prm.get("Time step multiplier"),
                         "a number in (0, 0.7071]: the explicit step on a 2D grid with lumped "
                         "mass is stable only up to alpha = 1/sqrt(2) in Eq. 23 "
                         "(doc/stability.md)");
      fixed_time_step         = prm.get_double("Fixed time step");
      b_bar                   = prm.get_bool("B-bar");
      detailed_timing         = prm.get_bool("Detailed timing");
      step_timeline           = prm.get_bool("Step timeline");
      full_sort_every_step    = prm.get("Particle relocation") == "full sort";
      const auto g            = parse_numbers(path + "/Gravity", prm.get("Gravity"), 2);
      gravity[0]              = g[0];
      gravity[1]              = g[1];
      damping                 = prm.get_double("Local damping");
      particles_per_direction = prm.get_integer("Particles per direction");

      prm.enter_subsection("Grid");
      {
        const auto a = parse_numbers(path + "/Grid/Lower left", prm.get("Lower left"), 2);
        const auto b = parse_numbers(path + "/Grid/Upper right", prm.get("Upper right"), 2);
        lower_left   = dealii::Point<2>(a[0], a[1]);
        upper_right  = dealii::Point<2>(b[0], b[1]);
        cell_size    = prm.get_double("Cell size");
        require_positive(path + "/Grid/Cell size", cell_size);
        if (!(b[0] > a[0]) || !(b[1] > a[1]))
          throw InputError(path + "/Grid/Upper right",
                           prm.get("Upper right"),
                           "a corner above and to the right of 'Lower left'");
        for (unsigned int d = 0; d < 2; ++d)
          {
            const double n = (b[d] - a[d]) / cell_size;
            if (std::abs(n - std::round(n)) > 1e-6 * n)
              throw InputError(path + "/Grid/Cell size",
                               to_string(cell_size),
                               "a size that divides the domain sides (" + to_string(b[0] - a[0])
                                 + " x " + to_string(b[1] - a[1]) + " m)");
          }
        // The supported size: beyond it the grid alone takes most of a machine's memory.
        const double n_cells
          = std::round((b[0] - a[0]) / cell_size) * std::round((b[1] - a[1]) / cell_size);
        if (n_cells > 1e7)
          throw InputError(path + "/Grid/Cell size",
                           to_string(cell_size),
                           "a size giving at most 10^7 grid cells (this one gives "
                             + to_string(n_cells) + ")");
      }
      prm.leave_subsection();

      prm.enter_subsection("Adaptive grid");
      {
        adaptivity.enabled      = prm.get_bool("Enable");
        adaptivity.levels       = prm.get_integer("Levels");
        adaptivity.buffer_cells = prm.get_integer("Buffer cells");
        adaptivity.interval     = prm.get_integer("Interval");
        if (adaptivity.enabled)
          {
            const double base = cell_size * (1u << adaptivity.levels);
            for (unsigned int d = 0; d < 2; ++d)
              {
                const double n = (upper_right[d] - lower_left[d]) / base;
                if (std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
                  throw InputError(path + "/Adaptive grid/Levels",
                                   std::to_string(adaptivity.levels),
                                   "a number of levels such that the coarsest cells (Cell "
                                   "size x 2^Levels = "
                                     + to_string(base) + " m) divide the domain sides ("
                                     + to_string(upper_right[0] - lower_left[0]) + " x "
                                     + to_string(upper_right[1] - lower_left[1]) + " m)");
              }
          }
      }
      prm.leave_subsection();

      prm.enter_subsection("Load balancing");
      {
        adaptivity.particle_weight     = prm.get_integer("Particle weight");
        adaptivity.imbalance_threshold = prm.get_double("Imbalance threshold");
        balance_interval               = prm.get_integer("Interval");
      }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      boundaries = {{boundary_type(prm.get("Left")),
                     boundary_type(prm.get("Right")),
                     boundary_type(prm.get("Bottom")),
                     boundary_type(prm.get("Top"))}};
      prm.leave_subsection();

      walls.clear();
      for (unsigned int w = 1; w <= RigidWall::max_walls; ++w)
        {
          prm.enter_subsection("Rigid wall " + std::to_string(w));
          RigidWall wall;
          if (wall.parse_parameters(prm, path + "/Rigid wall " + std::to_string(w)))
            walls.push_back(wall);
          prm.leave_subsection();
        }

      {
        const std::string text = dealii::Utilities::trim(prm.get("Prescribed velocity"));
        prescribed_velocity.reset();
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
                prescribed_velocity = std::make_shared<dealii::FunctionParser<2>>(2);
                prescribed_velocity->initialize("x,y,t",
                                                text,
                                                {{"pi", M_PI}},
                                                /*time_dependent=*/true);
                prescribed_velocity->value(dealii::Point<2>(), 0);
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

      prm.enter_subsection("Initial stress");
      {
        const std::string type = prm.get("Type");
        initial_stress         = type == "geostatic"       ? InitialStress::geostatic :
                                 type == "gravity loading" ? InitialStress::gravity_loading :
                                 type == "uniform"         ? InitialStress::uniform :
                                                             InitialStress::none;
        {
          const auto stress
            = parse_number_list(path + "/Initial stress/Uniform stress",
                                prm.get("Uniform stress"),
                                "four finite numbers sigma_xx, sigma_yy, sigma_xy, sigma_zz [Pa]",
                                4);
          std::copy(stress.begin(), stress.end(), uniform_stress.begin());
        }
        const std::string k0 = dealii::Utilities::trim(prm.get("K0"));
        if (k0 == "auto")
          lateral_stress_ratio = -1.;
        else
          {
            bool ok = true;
            try
              {
                std::size_t used     = 0;
                lateral_stress_ratio = std::stod(k0, &used);
                ok                   = used == k0.size() && std::isfinite(lateral_stress_ratio)
                     && lateral_stress_ratio > 0.;
              }
            catch (const std::exception &)
              {
                ok = false;
              }
            if (!ok)
              throw InputError(path + "/Initial stress/K0", k0, "'auto' or a number > 0");
          }
        gravity_loading_time    = prm.get_double("Gravity loading time");
        gravity_loading_damping = prm.get_double("Gravity loading damping");
        if (initial_stress == InitialStress::gravity_loading)
          require_positive(path + "/Initial stress/Gravity loading time", gravity_loading_time);
      }
      prm.leave_subsection();

      // Regions first: they say which materials the scene uses. Only those material
      // subsections are read (and checked); the others are ignored.
      regions.clear();
      for (unsigned int r = 1; r <= MaterialRegion::max_regions; ++r)
        {
          prm.enter_subsection("Region " + std::to_string(r));
          MaterialRegion    region;
          const std::string region_path = path + "/Region " + std::to_string(r);
          if (region.parse_parameters(prm, region_path))
            {
              const std::string entry = prm.get("Shape") == "rectangle" ? "Rectangle" : "Polygon";
              const auto        box   = region.bounding_box();
              for (unsigned int d = 0; d < 2; ++d)
                if (box.first[d] < lower_left[d] - 1e-12 || box.second[d] > upper_right[d] + 1e-12)
                  throw InputError(region_path + "/" + entry,
                                   prm.get(entry),
                                   "a region inside the grid [" + to_string(lower_left[0]) + ", "
                                     + to_string(upper_right[0]) + "] x ["
                                     + to_string(lower_left[1]) + ", " + to_string(upper_right[1])
                                     + "]");
              regions.push_back(region);
            }
          prm.leave_subsection();
        }

      materials.clear();
      for (unsigned int r = 0; r < regions.size(); ++r)
        {
          MaterialRegion           &region      = regions[r];
          const std::string         region_path = path + "/Region " + std::to_string(r + 1);
          std::vector<unsigned int> slots;
          for (unsigned int m = 1; m <= max_materials; ++m)
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
          region.material_index = materials.size();
          for (unsigned int k = 0; k < materials.size(); ++k)
            if (materials[k].name == region.material_name)
              region.material_index = k;
          if (region.material_index == materials.size())
            {
              const std::string slot = "Material " + std::to_string(slots[0]);
              prm.enter_subsection(slot);
              materials::MaterialParameters material;
              material.parse_parameters(prm, path + "/" + slot);
              material.name = region.material_name;
              prm.leave_subsection();
              materials.push_back(material);
            }
        }
      if (regions.empty())
        throw InputError(path + "/Region 1/Shape",
                         "none",
                         "at least one region filled with material ('rectangle' or "
                         "'polygon')");
    }



    MaterialPointSolver::MaterialPointSolver(const SolverParameters &parameters)
      : prm(parameters)
      , tria(MPI_COMM_WORLD, dealii::Triangulation<2>::limit_level_difference_at_vertices)
      , fe(1)
      , damping(parameters.damping)
    {
      for (const auto &material : prm.materials)
        materials.emplace_back(material);
      if (prm.step_timeline)
        timeline = std::make_unique<StepTimeline>();
    }



    void
    MaterialPointSolver::create_coarse_grid()
    {
      // With adaptive refinement the base grid is 2^levels times coarser than 'Cell size';
      // the cells holding material (and a buffer around them) are refined to 'Cell size'.
      const unsigned int        levels = prm.adaptivity.enabled ? prm.adaptivity.levels : 0;
      const double              base   = prm.cell_size * (1u << levels);
      std::vector<unsigned int> subdivisions{
        static_cast<unsigned int>(std::round((prm.upper_right[0] - prm.lower_left[0]) / base)),
        static_cast<unsigned int>(std::round((prm.upper_right[1] - prm.lower_left[1]) / base))};
      // Every rank stores every coarse cell (p4est's trees), and deal.II's cell loops visit
      // them all: the base grid is built from as few coarse cells as the side ratio allows
      // and refined globally (setup(); a checkpoint restores the refinement itself). The
      // cells are the same; only their order (p4est's space-filling curve within each
      // coarse cell) and the memory per rank change.
      base_refinements = 0;
      while (subdivisions[0] % 2 == 0 && subdivisions[1] % 2 == 0)
        {
          subdivisions[0] /= 2;
          subdivisions[1] /= 2;
          ++base_refinements;
        }
      dealii::GridGenerator::subdivided_hyper_rectangle(
        tria, subdivisions, prm.lower_left, prm.upper_right, /*colorize=*/true);
      tria.signals.weight.connect(
        [this](const dealii::Triangulation<2>::cell_iterator &cell,
               const dealii::Triangulation<2>::CellStatus     status) -> unsigned int {
          return cell_weight(cell, status);
        });
    }



    void
    MaterialPointSolver::initialize_particle_handler()
    {
      // The cells are axis-aligned rectangles: the Cartesian mapping finds a point's
      // reference coordinates directly (MappingQ1 would build an inverse approximation per
      // cell at every sort, a fifth of the step).
      static const dealii::MappingCartesian<2> mapping;
      particle_handler.initialize(tria,
                                  mapping,
                                  prm.point_forces ? property::n_properties_with_point_forces :
                                                     property::n_properties);
      particle_handler.signals.particle_lost.connect(
        [this](const dealii::Particles::ParticleIterator<2> &particle,
               const typename dealii::Triangulation<2>::active_cell_iterator &) {
          lost_mass += particle->get_properties()[property::mass];
          const dealii::Point<2> x    = particle->get_location();
          const unsigned int     side = x[0] < prm.lower_left[0]  ? 0 :
                                        x[0] > prm.upper_right[0] ? 1 :
                                        x[1] < prm.lower_left[1]  ? 2 :
                                                                    3;
          if (prm.boundaries[side] != GridBoundary::free && wall_crossing.empty())
            {
              static const char *const names[4] = {"left", "right", "bottom", "top"};
              std::ostringstream       out;
              out << "material point " << particle->get_id() << " left the domain at (" << x
                  << ") through the " << names[side] << " side, which is "
                  << (prm.boundaries[side] == GridBoundary::fixed ? "fixed" : "a roller")
                  << " (points may leave only through a free side: the deformation in one "
                     "step is larger than the point's distance to the boundary; lower 'Time "
                     "step multiplier' or stiffen the material)";
              wall_crossing = out.str();
            }
        });
    }



    void
    MaterialPointSolver::setup(const double start_time, const std::function<void()> &apply_loads)
    {
      time = start_time;
      // Until the points exist, every partition of the grid (the refinements below, the
      // repartition) weighs the cells by the points they will get, so that each rank
      // creates the points it keeps: none move and their memory is in cell order.
      weights_from_regions = true;
      create_coarse_grid();
      tria.refine_global(base_refinements);
      if (prm.adaptivity.enabled)
        for (unsigned int l = 0; l < prm.adaptivity.levels; ++l)
          {
            vertex_cells        = dealii::GridTools::vertex_to_cell_map(tria);
            const auto material = cells_near_material(/*from_regions=*/true);
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned() && material[cell->active_cell_index()])
                cell->set_refine_flag();
            tria.execute_coarsening_and_refinement();
          }
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
          && prm.adaptivity.imbalance_threshold > 0.)
        tria.repartition();
      dofs.reinit(tria);
      setup_grid_data();
      initialize_particle_handler();
      create_particles();
      weights_from_regions = false;
      balance_load();
      // The first full sort builds deal.II's search structures of the grid (a few seconds
      // at a million cells): here, not in the first step that needs one. It also puts the
      // memory of points that arrived from other ranks in cell order.
      particle_handler.sort_particles_into_subdomains_and_cells();
      if (apply_loads)
        apply_loads();
      if (prm.initial_stress == InitialStress::uniform)
        for (auto &particle : particle_handler)
          {
            auto p                 = particle.get_properties();
            p[property::stress_xx] = prm.uniform_stress[0];
            p[property::stress_yy] = prm.uniform_stress[1];
            p[property::stress_xy] = prm.uniform_stress[2];
            p[property::stress_zz] = prm.uniform_stress[3];
          }
      else if (prm.initial_stress == InitialStress::geostatic)
        set_geostatic_stress();
      else if (prm.initial_stress == InitialStress::gravity_loading)
        load_gravity();
    }



    void
    MaterialPointSolver::save(const std::string &prefix)
    {
      particle_handler.prepare_for_serialization();
      tria.save(prefix);
    }



    void
    MaterialPointSolver::load(const std::string &prefix)
    {
      create_coarse_grid();
      initialize_particle_handler();
      tria.load(prefix);
      particle_handler.deserialize();
      dofs.reinit(tria);
      setup_grid_data();
    }



    MaterialPointSolver::State
    MaterialPointSolver::state() const
    {
      return {time, dealii::Utilities::MPI::sum(lost_mass, MPI_COMM_WORLD), n_steps};
    }



    void
    MaterialPointSolver::set_state(const State &state)
    {
      time    = state.time;
      n_steps = state.n_steps;
      // The lost mass is a sum over ranks: rank 0 carries what was lost before.
      lost_mass
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? state.lost_mass : 0.;
    }



    void
    MaterialPointSolver::setup_grid_data()
    {
      vertex_cells = dealii::GridTools::vertex_to_cell_map(tria);
      dofs.distribute_dofs(fe);

      const dealii::IndexSet owned = dofs.locally_owned_dofs();
      dealii::IndexSet       relevant;
      dealii::DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      nodal_mass.reinit(owned, relevant, MPI_COMM_WORLD);
      for (unsigned int d = 0; d < 2; ++d)
        {
          momentum[d].reinit(nodal_mass);
          force[d].reinit(nodal_mass);
          velocity[d].reinit(nodal_mass);
          velocity_old[d].reinit(nodal_mass);
        }
      if (prm.prescribed_velocity)
        {
          node_positions.resize(nodal_mass.locally_owned_size());
          const auto &partitioner = *nodal_mass.get_partitioner();
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const unsigned int v : cell->vertex_indices())
                if (partitioner.in_local_range(cell->vertex_dof_index(v, 0)))
                  node_positions[partitioner.global_to_local(cell->vertex_dof_index(v, 0))]
                    = cell->vertex(v);
        }
      const auto &partitioner = nodal_mass.get_partitioner();
      active_nodes.clear();
      const unsigned int n_local
        = partitioner->locally_owned_size() + partitioner->n_ghost_indices();
      node_is_active.assign(n_local, 0);
      node_sums.assign(5 * n_local, 0.);
      node_velocities.assign(4 * n_local, 0.);
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
      {
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

      // Sides 0, 1 (left, right) hold the x velocity for rollers; 2, 3 the y velocity;
      // fixed sides hold both.
      for (auto &list : constrained_dofs)
        list.clear();
      for (unsigned int side = 0; side < 4; ++side)
        {
          if (prm.boundaries[side] == GridBoundary::free)
            continue;
          const dealii::IndexSet on_side
            = dealii::DoFTools::extract_boundary_dofs(
                dofs, dealii::ComponentMask(), {static_cast<dealii::types::boundary_id>(side)})
              & owned;
          const unsigned int normal = side < 2 ? 0 : 1;
          for (unsigned int d = 0; d < 2; ++d)
            if (d == normal || prm.boundaries[side] == GridBoundary::fixed)
              for (const auto index : on_side)
                constrained_dofs[d].push_back(partitioner->global_to_local(index));
        }
      build_cell_patches();
      find_wall_nodes();
    }



    std::vector<bool>
    MaterialPointSolver::cells_near_material(const bool from_regions) const
    {
      // Cells holding material: from the regions (at set-up: any point of the finest
      // lattice of points in the cell lies in a region) or from the particles; then
      // 'Buffer cells' layers of vertex neighbours around them, across ranks.
      std::vector<bool>  near(tria.n_active_cells(), false);
      const unsigned int n = prm.particles_per_direction;
      for (const auto &cell : tria.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          bool has_material = false;
          if (from_regions)
            {
              const dealii::Point<2> origin = cell->vertex(0);
              const double           h      = cell->vertex(1)[0] - origin[0];
              const unsigned int m = n * static_cast<unsigned int>(std::round(h / prm.cell_size));
              for (unsigned int j = 0; j < m && !has_material; ++j)
                for (unsigned int i = 0; i < m && !has_material; ++i)
                  {
                    const dealii::Point<2> x(origin[0] + (i + 0.5) * h / m,
                                             origin[1] + (j + 0.5) * h / m);
                    for (const auto &region : prm.regions)
                      has_material = has_material || region.contains(x);
                  }
            }
          else
            has_material = particle_handler.n_particles_in_cell(cell) > 0;
          near[cell->active_cell_index()] = has_material;
        }
      const auto &vertex_to_cells = vertex_cells;
      for (unsigned int layer = 0; layer <= prm.adaptivity.buffer_cells; ++layer)
        {
          // Ghost cells learn their owners' flags.
          dealii::GridTools::exchange_cell_data_to_ghosts<unsigned char, dealii::Triangulation<2>>(
            tria,
            [&](const dealii::Triangulation<2>::active_cell_iterator &cell) {
              return static_cast<unsigned char>(near[cell->active_cell_index()]);
            },
            [&](const dealii::Triangulation<2>::active_cell_iterator &cell,
                const unsigned char flag) { near[cell->active_cell_index()] = flag != 0; });
          if (layer == prm.adaptivity.buffer_cells)
            break;
          std::vector<bool> grown = near;
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned() && !near[cell->active_cell_index()])
              for (const unsigned int v : cell->vertex_indices())
                for (const auto &other : vertex_to_cells[cell->vertex_index(v)])
                  if (!other->is_artificial() && near[other->active_cell_index()])
                    grown[cell->active_cell_index()] = true;
          near.swap(grown);
        }
      return near;
    }



    unsigned int
    MaterialPointSolver::cell_weight(const dealii::Triangulation<2>::cell_iterator &cell,
                                     const dealii::Triangulation<2>::CellStatus     status) const
    {
      // The base weight (deal.II's 'weight' signal, unlike the older 'cell_weight', adds
      // none itself) plus the cell's points: those it holds or, before they exist, those
      // the regions will put there with 'per_direction' of them per direction.
      const auto points = [this](const dealii::Triangulation<2>::cell_iterator &c,
                                 const unsigned int                             per_direction) {
        unsigned int n = 0;
        if (weights_from_regions)
          for_each_point_to_create(c, per_direction, [&n](const auto &...) { ++n; });
        else
          n = particle_handler.n_particles_in_cell(c);
        return n;
      };
      const unsigned int per_direction = prm.particles_per_direction;
      unsigned int       n             = 0;
      switch (status)
        {
          case dealii::Triangulation<2>::CELL_PERSIST:
            n = points(cell, per_direction);
            break;
          case dealii::Triangulation<2>::CELL_REFINE:
            // The children's lattices together are the parent's at twice the density.
            n = points(cell, 2 * per_direction);
            break;
          case dealii::Triangulation<2>::CELL_COARSEN:
            for (const auto &child : cell->child_iterators())
              n += points(child, per_direction);
            break;
          default:
            break;
        }
      // p4est takes the weight as an int: saturate rather than wrap around.
      const std::uint64_t weight
        = cell_base_weight + static_cast<std::uint64_t>(prm.adaptivity.particle_weight) * n;
      return static_cast<unsigned int>(
        std::min<std::uint64_t>(weight, std::numeric_limits<int>::max()));
    }



    double
    MaterialPointSolver::load_imbalance() const
    {
      // Max over mean of the ranks' work: cells x 1000 + points x particle weight.
      const double work
        = static_cast<double>(cell_base_weight) * tria.n_locally_owned_active_cells()
          + static_cast<double>(prm.adaptivity.particle_weight)
              * particle_handler.n_locally_owned_particles();
      const double max  = dealii::Utilities::MPI::max(work, MPI_COMM_WORLD);
      const double mean = dealii::Utilities::MPI::sum(work, MPI_COMM_WORLD)
                          / dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      return mean > 0. ? max / mean : 1.;
    }



    void
    MaterialPointSolver::balance_load()
    {
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1
          || !(prm.adaptivity.imbalance_threshold > 0.)
          || load_imbalance() <= prm.adaptivity.imbalance_threshold)
        return;
      // Points travel with their cells to their new ranks.
      particle_handler.prepare_for_coarsening_and_refinement();
      tria.repartition();
      particle_handler.unpack_after_coarsening_and_refinement();
      setup_grid_data();
      ++n_grid_changes;
    }



    void
    MaterialPointSolver::adapt_grid()
    {
      const auto         near    = cells_near_material(/*from_regions=*/false);
      const unsigned int levels  = prm.adaptivity.levels;
      bool               changes = false;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const bool         keep_fine = near[cell->active_cell_index()];
            const unsigned int level     = cell->level();
            if (keep_fine && level < base_refinements + levels)
              {
                cell->set_refine_flag();
                changes = true;
              }
            else if (!keep_fine && level > base_refinements)
              {
                cell->set_coarsen_flag();
                changes = true;
              }
          }
      changes              = dealii::Utilities::MPI::logical_or(changes, MPI_COMM_WORLD);
      const bool rebalance = !changes && prm.adaptivity.imbalance_threshold > 0.
                             && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
                             && load_imbalance() > prm.adaptivity.imbalance_threshold;
      if (!changes && !rebalance)
        return;
      // Points travel with their cells through refinement, coarsening and repartitioning.
      particle_handler.prepare_for_coarsening_and_refinement();
      if (changes)
        tria.execute_coarsening_and_refinement(); // also repartitions by the cell weights
      else
        tria.repartition();
      particle_handler.unpack_after_coarsening_and_refinement();
      setup_grid_data();
      ++n_grid_changes;
    }



    void
    MaterialPointSolver::build_cell_patches()
    {
      const auto &partitioner     = nodal_mass.get_partitioner();
      const auto &vertex_to_cells = vertex_cells;
      patch_start.assign(tria.n_active_cells() + 1, 0);
      own_cell.assign(tria.n_active_cells(), PatchCell{});
      patch_cells.clear();
      patch_cell_iterators.clear();
      std::vector<dealii::types::global_dof_index> dof_indices(4);
      const auto make_entry = [&](const dealii::DoFHandler<2>::active_cell_iterator &cell) {
        PatchCell entry;
        entry.x0 = cell->vertex(0)[0];
        entry.y0 = cell->vertex(0)[1];
        entry.hx = cell->vertex(1)[0] - entry.x0;
        entry.hy = cell->vertex(2)[1] - entry.y0;
        cell->get_dof_indices(dof_indices);
        for (unsigned int a = 0; a < 4; ++a)
          entry.node[a] = partitioner->global_to_local(dof_indices[a]);
        return entry;
      };
      for (const auto &cell : dofs.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          patch_start[index + 1]   = patch_start[index];
          if (!cell->is_locally_owned())
            continue;
          patch_cells.push_back(make_entry(cell));
          own_cell[index] = patch_cells.back();
          patch_cell_iterators.push_back(cell);
          std::vector<dealii::Triangulation<2>::active_cell_iterator> neighbours;
          for (const unsigned int v : cell->vertex_indices())
            for (const auto &other : vertex_to_cells[cell->vertex_index(v)])
              if (other != cell
                  && std::find(neighbours.begin(), neighbours.end(), other) == neighbours.end())
                neighbours.push_back(other);
          std::sort(neighbours.begin(), neighbours.end());
          for (const auto &other : neighbours)
            {
              patch_cells.push_back(make_entry(dealii::DoFHandler<2>::active_cell_iterator(
                &tria, other->level(), other->index(), &dofs)));
              patch_cell_iterators.push_back(other);
            }
          patch_start[index + 1] = patch_cells.size();
        }
    }



    void
    MaterialPointSolver::find_wall_nodes()
    {
      supports.clear();
      const auto  &partitioner = nodal_mass.get_partitioner();
      const double tolerance   = 1e-6 * prm.cell_size;
      for (const auto &wall : prm.walls)
        {
          WallNodes                 held;
          std::vector<unsigned int> on_wall;
          held.release_time = wall.release_time;
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const unsigned int v : cell->vertex_indices())
                {
                  const auto dof = cell->vertex_dof_index(v, 0);
                  if (partitioner->in_local_range(dof) && wall.contains(cell->vertex(v), tolerance))
                    on_wall.push_back(partitioner->global_to_local(dof));
                }
          std::sort(on_wall.begin(), on_wall.end());
          on_wall.erase(std::unique(on_wall.begin(), on_wall.end()), on_wall.end());
          for (unsigned int d = 0; d < 2; ++d)
            if (d == wall.normal_component() || wall.condition == RigidWall::Condition::fixed)
              held.nodes[d] = on_wall;
          supports.push_back(held);
        }
    }



    void
    MaterialPointSolver::set_geostatic_stress()
    {
      // The weight above each point, per unit width, from the points in its vertical strip
      // (strips of the initial point spacing, which the points of a region fill on a
      // lattice): a histogram of mass over strips and rows, summed over all ranks, then
      // summed from the top down.
      const double       spacing = prm.cell_size / prm.particles_per_direction;
      const unsigned int n_x
        = static_cast<unsigned int>(std::round((prm.upper_right[0] - prm.lower_left[0]) / spacing));
      const unsigned int n_y
        = static_cast<unsigned int>(std::round((prm.upper_right[1] - prm.lower_left[1]) / spacing));
      const auto bin = [&](const dealii::Point<2> &x, const unsigned int d, const unsigned int n) {
        const int i = static_cast<int>(std::floor((x[d] - prm.lower_left[d]) / spacing));
        return static_cast<unsigned int>(std::clamp(i, 0, static_cast<int>(n) - 1));
      };
      std::vector<double> mass(static_cast<std::size_t>(n_x) * n_y, 0.);
      // A downward point force (the water on the surface) weighs like mass F / g.
      const double g = std::abs(prm.gravity[1]);
      for (const auto &particle : particle_handler)
        {
          const auto p = particle.get_properties();
          mass[static_cast<std::size_t>(bin(particle.get_location(), 0, n_x)) * n_y
               + bin(particle.get_location(), 1, n_y)]
            += p[property::mass]
               - (prm.point_forces && g > 0. ? p[property::point_force_y] / g : 0.);
        }
      dealii::Utilities::MPI::sum(mass, MPI_COMM_WORLD, mass);
      // Weight above the bottom of each bin.
      for (unsigned int i = 0; i < n_x; ++i)
        for (int j = static_cast<int>(n_y) - 2; j >= 0; --j)
          mass[static_cast<std::size_t>(i) * n_y + j]
            += mass[static_cast<std::size_t>(i) * n_y + j + 1];

      for (auto &particle : particle_handler)
        {
          auto               p   = particle.get_properties();
          const unsigned int i   = bin(particle.get_location(), 0, n_x);
          const unsigned int j   = bin(particle.get_location(), 1, n_y);
          const double       own = p[property::mass]
                             - (prm.point_forces && g > 0. ? p[property::point_force_y] / g : 0.);
          const double above = (j + 1 < n_y ? mass[static_cast<std::size_t>(i) * n_y + j + 1] : 0.);
          const double sigma_v = -g * (above + 0.5 * own) / spacing;
          const auto &material = prm.materials[static_cast<unsigned int>(p[property::material_id])];
          double      k0       = prm.lateral_stress_ratio;
          if (k0 < 0.)
            k0 = material.model == materials::MaterialModel::drucker_prager ?
                   1. - std::sin(material.friction_angle * M_PI / 180.) :
                   material.poisson_ratio / (1. - material.poisson_ratio);
          p[property::stress_yy] = sigma_v;
          p[property::stress_xx] = k0 * sigma_v;
          p[property::stress_zz] = k0 * sigma_v;
          p[property::stress_xy] = 0.;
        }
    }



    void
    MaterialPointSolver::load_gravity()
    {
      const double start = time;
      double       t     = 0.;
      damping            = prm.gravity_loading_damping;
      loading_gravity    = true; // every wall holds
      const double end   = prm.gravity_loading_time;
      while (t < end * (1. - 1e-12))
        {
          const double dt = std::min(stable_time_step(), end - t);
          advance(dt);
          t += dt;
        }
      time            = start;
      damping         = prm.damping;
      loading_gravity = false;
      for (auto &particle : particle_handler)
        {
          auto p                  = particle.get_properties();
          p[property::velocity_x] = 0.;
          p[property::velocity_y] = 0.;
          p[property::initial_x]  = particle.get_location()[0];
          p[property::initial_y]  = particle.get_location()[1];
        }
    }



    void
    MaterialPointSolver::set_point_forces(
      const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
        &force)
    {
      Assert(prm.point_forces, dealii::ExcMessage("point forces were not switched on"));
      for (auto &particle : particle_handler)
        {
          const dealii::Tensor<1, 2> f = force(particle);
          auto                       p = particle.get_properties();
          p[property::point_force_x]   = f[0];
          p[property::point_force_y]   = f[1];
        }
    }



    dealii::Tensor<1, 2>
    MaterialPointSolver::total_point_force() const
    {
      dealii::Tensor<1, 2> total;
      if (prm.point_forces)
        for (const auto &particle : particle_handler)
          {
            const auto p = particle.get_properties();
            total[0] += p[property::point_force_x];
            total[1] += p[property::point_force_y];
          }
      return dealii::Utilities::MPI::sum(total, MPI_COMM_WORLD);
    }



    std::array<double, 3>
    MaterialPointSolver::nodal_totals()
    {
      particles_to_grid();
      std::array<double, 3> totals{{nodal_mass.l1_norm(), 0., 0.}};
      for (unsigned int d = 0; d < 2; ++d)
        totals[d + 1] = momentum[d].mean_value() * momentum[d].size();
      return totals;
    }



    template <typename Function>
    void
    MaterialPointSolver::for_each_point_to_create(
      const dealii::Triangulation<2>::cell_iterator &cell,
      const unsigned int                             n,
      const Function                                &f) const
    {
      const dealii::Point<2> origin = cell->vertex(0);
      const double           hx     = cell->vertex(1)[0] - origin[0];
      const double           hy     = cell->vertex(2)[1] - origin[1];
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          {
            const dealii::Point<2> reference((i + 0.5) / n, (j + 0.5) / n);
            const dealii::Point<2> position(origin[0] + reference[0] * hx,
                                            origin[1] + reference[1] * hy);
            for (unsigned int r = 0; r < prm.regions.size(); ++r)
              if (prm.regions[r].contains(position))
                {
                  f(position, reference, r, j * n + i);
                  break;
                }
          }
    }



    void
    MaterialPointSolver::create_particles()
    {
      const unsigned int  n = prm.particles_per_direction;
      std::vector<double> properties(particle_handler.n_properties_per_particle(), 0.);
      for (const auto &cell : tria.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const double hx = cell->vertex(1)[0] - cell->vertex(0)[0];
          const double hy = cell->vertex(2)[1] - cell->vertex(0)[1];
          for_each_point_to_create(
            cell,
            n,
            [&](const dealii::Point<2> &position,
                const dealii::Point<2> &reference,
                const unsigned int      region_index,
                const unsigned int      lattice_index) {
              const MaterialRegion &region = prm.regions[region_index];
              const unsigned int    m      = region.material_index;
              const double          volume = hx * hy / (n * n);
              std::fill(properties.begin(), properties.end(), 0.);
              properties[property::mass]           = prm.materials[m].density * volume;
              properties[property::volume]         = volume;
              properties[property::initial_volume] = volume;
              const dealii::Tensor<1, 2> v         = region.initial_velocity(position);
              properties[property::velocity_x]     = v[0];
              properties[property::velocity_y]     = v[1];
              properties[property::initial_x]      = position[0];
              properties[property::initial_y]      = position[1];
              properties[property::material_id]    = m;
              properties[property::domain_half_x]  = 0.5 * hx / n;
              properties[property::domain_half_y]  = 0.5 * hy / n;
              // Identifiers that do not depend on the partition: the global index of the
              // cell and the position in it.
              const dealii::types::particle_index id
                = cell->global_active_cell_index() * n * n + lattice_index;
              particle_handler.insert_particle(
                position, reference, id, cell, dealii::make_array_view(properties));
            });
        }
      particle_handler.update_cached_numbers();
    }



    double
    MaterialPointSolver::stability_limit() const
    {
      double max_speed = 0.;
      for (const auto &particle : particle_handler)
        {
          const auto   p       = particle.get_properties();
          const double density = p[property::mass] / p[property::volume];
          const double c       = std::sqrt(
            materials[static_cast<unsigned int>(p[property::material_id])].p_wave_modulus()
            / density);
          const double v = std::sqrt(p[property::velocity_x] * p[property::velocity_x]
                                     + p[property::velocity_y] * p[property::velocity_y]);
          max_speed      = std::max(max_speed, c + v);
        }
      max_speed = dealii::Utilities::MPI::max(max_speed, MPI_COMM_WORLD);
      return max_speed > 0. ? prm.cell_size / max_speed : std::numeric_limits<double>::infinity();
    }



    double
    MaterialPointSolver::stable_time_step() const
    {
      // A fixed time step is checked against the limit once, at the start (the scene);
      // the run-time guards watch what happens after.
      return prm.fixed_time_step > 0. ? prm.fixed_time_step :
                                        prm.time_step_multiplier * stability_limit();
    }



    template <typename ParticleAccessorType>
    inline void
    MaterialPointSolver::shape_weights(const ParticleAccessorType &particle,
                                       const unsigned int          cell_index,
                                       NodeWeights                &w) const
    {
      if (prm.shape_function == ShapeFunction::q1)
        {
          const dealii::Point<2> ref = particle.get_reference_location();
          q1_weights(own_cell[cell_index], ref[0], ref[1], w);
        }
      else
        {
          const PatchCell       *begin = patch_cells.data() + patch_start[cell_index];
          const PatchCell       *end   = patch_cells.data() + patch_start[cell_index + 1];
          const dealii::Point<2> x     = particle.get_location();
          const auto             p     = particle.get_properties();
          gimp_weights(
            begin, end, x[0], x[1], p[property::domain_half_x], p[property::domain_half_y], w);
        }
    }



    void
    MaterialPointSolver::clear_active_nodes()
    {
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
          node_is_active[i] = 0;
        }
      active_nodes.clear();
    }



    void
    MaterialPointSolver::complete_active_nodes()
    {
      for (unsigned int k = 0; k < hanging_node.size(); ++k)
        if (node_is_active[hanging_node[k]] != 0)
          for (unsigned int e = hanging_start[k]; e < hanging_start[k + 1]; ++e)
            mark_active(hanging_parent[e]);
      for (const unsigned int i : import_nodes)
        mark_active(i);
    }



    void
    MaterialPointSolver::particles_to_grid()
    {
      clear_active_nodes();
      NodeWeights  w;
      const double gx = prm.gravity[0], gy = prm.gravity[1];
      const bool   point_forces = prm.point_forces;
      // Q1 talks to the nodes of the point's cell, GIMP to those of the cell's patch.
      const bool whole_patch = prm.shape_function != ShapeFunction::q1;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        if (whole_patch)
          for (unsigned int e = patch_start[cell_index]; e < patch_start[cell_index + 1]; ++e)
            for (const unsigned int i : patch_cells[e].node)
              mark_active(i);
        else
          for (const unsigned int i : own_cell[cell_index].node)
            mark_active(i);
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            const auto   p  = particle.get_properties();
            const double m  = p[property::mass];
            const double V  = p[property::volume];
            const double vx = p[property::velocity_x], vy = p[property::velocity_y];
            const double sxx = p[property::stress_xx], syy = p[property::stress_yy],
                         sxy = p[property::stress_xy];
            const double fx  = point_forces ? p[property::point_force_x] : 0.;
            const double fy  = point_forces ? p[property::point_force_y] : 0.;
            for (unsigned int k = 0; k < w.n; ++k)
              {
                double      *sums = node_sums.data() + 5 * w.node[k];
                const double mk   = w.value[k] * m;
                sums[0] += mk;
                sums[1] += mk * vx;
                sums[2] += mk * vy;
                // Internal force -V sigma grad S (Eq. 16) plus gravity and the point
                // force (Eq. 15).
                sums[3] += -V * (sxx * w.grad_x[k] + sxy * w.grad_y[k]) + mk * gx + w.value[k] * fx;
                sums[4] += -V * (sxy * w.grad_x[k] + syy * w.grad_y[k]) + mk * gy + w.value[k] * fy;
              }
          }
      });
      // Into the distributed vectors (the scratch is left zero for the next step).
      for (const unsigned int i : active_nodes)
        {
          double *sums                 = node_sums.data() + 5 * i;
          nodal_mass.local_element(i)  = sums[0];
          momentum[0].local_element(i) = sums[1];
          momentum[1].local_element(i) = sums[2];
          force[0].local_element(i)    = sums[3];
          force[1].local_element(i)    = sums[4];
          std::fill(sums, sums + 5, 0.);
        }
      complete_active_nodes();
      condense_hanging_nodes(nodal_mass);
      for (unsigned int d = 0; d < 2; ++d)
        {
          condense_hanging_nodes(momentum[d]);
          condense_hanging_nodes(force[d]);
        }
      lap(StepTimeline::scatter);
      nodal_mass.compress(dealii::VectorOperation::add);
      for (unsigned int d = 0; d < 2; ++d)
        {
          momentum[d].compress(dealii::VectorOperation::add);
          force[d].compress(dealii::VectorOperation::add);
        }
      lap(StepTimeline::exchange_sums);
    }



    void
    MaterialPointSolver::condense_hanging_nodes(Vector &v) const
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
    MaterialPointSolver::interpolate_hanging_nodes(Vector &v) const
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



    void
    MaterialPointSolver::apply_boundary_conditions(Vector &vx, Vector &vy) const
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



    void
    MaterialPointSolver::update_grid(const double dt)
    {
      // Nodes with less than this mass are treated as empty: their velocity is zero.
      const double tiny  = empty_node_mass();
      const double alpha = damping;
      if (prm.prescribed_velocity)
        prescribe_nodal_velocities(dt);
      else
        {
          // Ghost entries among the active nodes hold no mass after the compress (their
          // velocities come from their owners below).
          for (const unsigned int i : active_nodes)
            {
              const double m = nodal_mass.local_element(i);
              for (unsigned int d = 0; d < 2; ++d)
                {
                  if (m > tiny)
                    {
                      const double v = momentum[d].local_element(i) / m;
                      double       f = force[d].local_element(i);
                      // Cundall's local damping: a force opposing the motion, proportional
                      // to the unbalanced force.
                      if (alpha > 0.)
                        f -= alpha * std::abs(f) * (v > 0. ? 1. : v < 0. ? -1. : 0.);
                      velocity_old[d].local_element(i) = v;
                      velocity[d].local_element(i)     = v + dt * f / m; // Eqs. 18-19
                    }
                  else
                    {
                      velocity_old[d].local_element(i) = 0.;
                      velocity[d].local_element(i)     = 0.;
                    }
                }
            }
        }
      apply_boundary_conditions(velocity[0], velocity[1]);
      apply_boundary_conditions(velocity_old[0], velocity_old[1]);
      lap(StepTimeline::grid_update);
      for (unsigned int d = 0; d < 2; ++d)
        {
          velocity[d].update_ghost_values();
          velocity_old[d].update_ghost_values();
        }
      lap(StepTimeline::exchange_velocities);
      for (unsigned int d = 0; d < 2; ++d)
        {
          interpolate_hanging_nodes(velocity[d]);
          interpolate_hanging_nodes(velocity_old[d]);
        }
      // What the gather reads per node, side by side: v^new and v^new - v^old.
      for (const unsigned int i : active_nodes)
        {
          double *v = node_velocities.data() + 4 * i;
          v[0]      = velocity[0].local_element(i);
          v[1]      = velocity[1].local_element(i);
          v[2]      = v[0] - velocity_old[0].local_element(i);
          v[3]      = v[1] - velocity_old[1].local_element(i);
        }
      lap(StepTimeline::grid_update);
    }



    void
    MaterialPointSolver::prescribe_nodal_velocities(const double dt)
    {
      // Kinematic mode: the field at the node at the start and the end of the step (zero
      // on nodes without mass, as in the dynamic update).
      const double   tiny  = empty_node_mass();
      const unsigned n_own = nodal_mass.locally_owned_size();
      for (const auto &[when, target] :
           {std::pair<double, std::array<Vector, 2> *>{time, &velocity_old},
            {time + dt, &velocity}})
        {
          prm.prescribed_velocity->set_time(when);
          for (unsigned int i = 0; i < n_own; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              (*target)[d].local_element(i)
                = nodal_mass.local_element(i) > tiny ?
                    prm.prescribed_velocity->value(node_positions[i], d) :
                    0.;
        }
    }



    double
    MaterialPointSolver::empty_node_mass() const
    {
      double density = 0.;
      for (const auto &material : prm.materials)
        density = std::max(density, material.density);
      return 1e-12 * prm.cell_size * prm.cell_size * (density > 0. ? density : 1.);
    }



    void
    MaterialPointSolver::remap_velocities_to_grid()
    {
      if (prm.prescribed_velocity)
        return; // the nodal velocities are given
      // MUSL: nodal momentum from the updated particle velocities, on the old positions.
      for (const unsigned int i : active_nodes)
        for (unsigned int d = 0; d < 2; ++d)
          momentum[d].local_element(i) = 0.;
      NodeWeights w;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            const auto   p  = particle.get_properties();
            const double px = p[property::mass] * p[property::velocity_x];
            const double py = p[property::mass] * p[property::velocity_y];
            for (unsigned int k = 0; k < w.n; ++k)
              {
                momentum[0].local_element(w.node[k]) += w.value[k] * px;
                momentum[1].local_element(w.node[k]) += w.value[k] * py;
              }
          }
      });
      for (unsigned int d = 0; d < 2; ++d)
        {
          condense_hanging_nodes(momentum[d]);
          momentum[d].compress(dealii::VectorOperation::add);
        }
      const double tiny = empty_node_mass();
      for (const unsigned int i : active_nodes)
        {
          const double m = nodal_mass.local_element(i);
          for (unsigned int d = 0; d < 2; ++d)
            velocity[d].local_element(i) = m > tiny ? momentum[d].local_element(i) / m : 0.;
        }
      apply_boundary_conditions(velocity[0], velocity[1]);
      for (unsigned int d = 0; d < 2; ++d)
        {
          velocity[d].update_ghost_values();
          interpolate_hanging_nodes(velocity[d]);
        }
    }



    void
    MaterialPointSolver::grid_to_particles(const double dt, const bool with_stresses)
    {
      // Velocities (PIC/FLIP, Eq. 20) and new positions (Eq. 21); the positions are
      // kept aside until the stresses have been updated on the old positions. With USL
      // the velocity gradients come from the same nodal velocities, so the stresses are
      // updated in the same pass.
      NodeWeights  w;
      const double flip = prm.flip_fraction;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        if (with_stresses)
          cell_gradients.resize(particle_handler.n_particles_in_cell(cell));
        unsigned int k = 0;
        for (auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            double               v_new[2] = {0., 0.}, dv[2] = {0., 0.};
            dealii::Tensor<2, 2> L;
            for (unsigned int e = 0; e < w.n; ++e)
              {
                const double *v  = node_velocities.data() + 4 * w.node[e];
                const double  vx = v[0];
                const double  vy = v[1];
                v_new[0] += w.value[e] * vx;
                v_new[1] += w.value[e] * vy;
                dv[0] += w.value[e] * v[2];
                dv[1] += w.value[e] * v[3];
                L[0][0] += vx * w.grad_x[e];
                L[0][1] += vx * w.grad_y[e];
                L[1][0] += vy * w.grad_x[e];
                L[1][1] += vy * w.grad_y[e];
              }
            auto p = particle.get_properties();
            p[property::velocity_x]
              = flip * (p[property::velocity_x] + dv[0]) + (1. - flip) * v_new[0];
            p[property::velocity_y]
              = flip * (p[property::velocity_y] + dv[1]) + (1. - flip) * v_new[1];
            new_positions[particle.get_local_index()]
              = particle.get_location() + dt * dealii::Tensor<1, 2>({v_new[0], v_new[1]});
            if (with_stresses)
              cell_gradients[k++] = L;
          }
        if (with_stresses)
          update_cell_stresses(particles_in_cell, dt);
      });
    }



    void
    MaterialPointSolver::update_stresses(const double dt)
    {
      NodeWeights w;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        cell_gradients.resize(particle_handler.n_particles_in_cell(cell));
        unsigned int k = 0;
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            dealii::Tensor<2, 2> L;
            for (unsigned int e = 0; e < w.n; ++e)
              {
                const double vx = velocity[0].local_element(w.node[e]);
                const double vy = velocity[1].local_element(w.node[e]);
                L[0][0] += vx * w.grad_x[e];
                L[0][1] += vx * w.grad_y[e];
                L[1][0] += vy * w.grad_x[e];
                L[1][1] += vy * w.grad_y[e];
              }
            cell_gradients[k++] = L;
          }
        update_cell_stresses(particles_in_cell, dt);
      });
    }



    void
    MaterialPointSolver::update_cell_stresses(
      const dealii::Particles::ParticleHandler<2>::particle_iterator_range &particles_in_cell,
      const double                                                          dt)
    {
      // With B-bar, the volumetric part of each point's strain increment is replaced by
      // its volume-weighted average over the cell (mean dilatation).
      double mean_volumetric = 0.;
      if (prm.b_bar)
        {
          double       volume_sum = 0., volumetric_sum = 0.;
          unsigned int k = 0;
          for (const auto &particle : particles_in_cell)
            {
              const dealii::Tensor<2, 2> &L = cell_gradients[k++];
              const double                V = particle.get_properties()[property::volume];
              volume_sum += V;
              volumetric_sum += V * (L[0][0] + L[1][1]);
            }
          mean_volumetric = volumetric_sum / volume_sum;
        }

      const bool   stretch_domain = prm.shape_function == ShapeFunction::cpgimp;
      const double max_half       = 0.5 * prm.cell_size;
      unsigned int k              = 0;
      for (auto &particle : particles_in_cell)
        {
          const dealii::Tensor<2, 2>   &L = cell_gradients[k++];
          dealii::SymmetricTensor<2, 3> strain_increment;
          strain_increment[0][0] = L[0][0] * dt;
          strain_increment[1][1] = L[1][1] * dt;
          strain_increment[0][1] = 0.5 * (L[0][1] + L[1][0]) * dt;
          if (prm.b_bar)
            {
              const double correction = 0.5 * (mean_volumetric - (L[0][0] + L[1][1])) * dt;
              strain_increment[0][0] += correction;
              strain_increment[1][1] += correction;
            }
          const double spin_xy = 0.5 * (L[0][1] - L[1][0]) * dt;

          auto                          p = particle.get_properties();
          dealii::SymmetricTensor<2, 3> stress;
          stress[0][0]   = p[property::stress_xx];
          stress[1][1]   = p[property::stress_yy];
          stress[0][1]   = p[property::stress_xy];
          stress[2][2]   = p[property::stress_zz];
          double plastic = p[property::equivalent_plastic_strain];
          materials[static_cast<unsigned int>(p[property::material_id])].update_stress(
            stress, strain_increment, spin_xy, plastic);
          p[property::stress_xx]                 = stress[0][0];
          p[property::stress_yy]                 = stress[1][1];
          p[property::stress_xy]                 = stress[0][1];
          p[property::stress_zz]                 = stress[2][2];
          p[property::equivalent_plastic_strain] = plastic;
          p[property::volume] *= 1. + strain_increment[0][0] + strain_increment[1][1];
          if (stretch_domain)
            {
              // cpGIMP: the domain follows the stretch of the point along the axes
              // (kept within half a cell so it stays inside the patch of cells).
              p[property::domain_half_x]
                = std::min(max_half, p[property::domain_half_x] * (1. + L[0][0] * dt));
              p[property::domain_half_y]
                = std::min(max_half, p[property::domain_half_y] * (1. + L[1][1] * dt));
            }
        }
    }



    void
    MaterialPointSolver::set_timer(dealii::TimerOutput &timer_output)
    {
      timer = prm.detailed_timing ? &timer_output : nullptr;
    }



    void
    MaterialPointSolver::advance(const double dt)
    {
      // A timer section per part of the step when 'Detailed timing' is on.
      std::optional<dealii::TimerOutput::Scope> part;
      const auto                                start = [&](const char *name) {
        if (timer != nullptr)
          {
            part.reset();
            part.emplace(*timer, name);
          }
      };
      if (timeline)
        timeline->begin_step(n_steps + 1);
      if (prm.adaptivity.enabled && n_steps > 0 && n_steps % prm.adaptivity.interval == 0)
        {
          start("mpm step: grid changes");
          adapt_grid();
        }
      else if (n_steps > 0 && n_steps % prm.balance_interval == 0)
        {
          start("mpm step: grid changes");
          balance_load();
        }
      lap(StepTimeline::grid_changes);
      ++n_steps;
      for (auto &support : supports)
        support.active = loading_gravity || time < support.release_time;
      start("mpm step: particles to grid");
      particles_to_grid();
      start("mpm step: grid update");
      update_grid(dt);
      // Indexed by the points' local indices (their memory slots), which may have gaps
      // after a relocation.
      new_positions.resize(particle_handler.get_property_pool().n_slots());
      start("mpm step: grid to particles");
      if (prm.update_scheme == UpdateScheme::usl)
        {
          grid_to_particles(dt, /*with_stresses=*/true);
          lap(StepTimeline::gather);
        }
      else
        {
          grid_to_particles(dt, /*with_stresses=*/false);
          lap(StepTimeline::gather);
          start("mpm step: MUSL re-map and stresses");
          remap_velocities_to_grid();
          update_stresses(dt);
          lap(StepTimeline::musl_remap);
        }
      start("mpm step: sort particles");
      const bool full_sort = prm.full_sort_every_step || n_steps % prm.balance_interval == 0;
      if (full_sort)
        for (auto &particle : particle_handler)
          particle.set_location(new_positions[particle.get_local_index()]);
      // relocate_within_patches() sets the locations itself, also when it gives up.
      if (full_sort || !relocate_within_patches())
        {
          lap(StepTimeline::relocation);
          ++n_full_sorts;
          particle_handler.sort_particles_into_subdomains_and_cells();
          lap(StepTimeline::full_sort);
        }
      lap(StepTimeline::relocation);
      time += dt;
    }



    bool
    MaterialPointSolver::relocate_within_patches()
    {
      // The reference coordinates exactly as deal.II's MappingCartesian computes them,
      // and its test for a point inside the unit cell, so that this path and the full
      // sort put every point in the same cell at the same reference coordinates.
      const auto locate
        = [](const PatchCell &c, const dealii::Point<2> &x, dealii::Point<2> &reference) {
            reference[0] = (x[0] - c.x0) / c.hx;
            reference[1] = (x[1] - c.y0) / c.hy;
            return reference[0] >= 0. && reference[0] <= 1. && reference[1] >= 0.
                   && reference[1] <= 1.;
          };
      moving_particles.clear();
      moving_data.clear();
      const unsigned int n_properties = particle_handler.n_properties_per_particle();
      bool               leaves_patch = false;
      dealii::Point<2>   reference;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        const unsigned int own        = patch_start[cell_index];
        const unsigned int end        = patch_start[cell_index + 1];
        for (auto particle = particles_in_cell.begin(); particle != particles_in_cell.end();
             ++particle)
          {
            const dealii::Point<2> &x = new_positions[particle->get_local_index()];
            particle->set_location(x);
            if (locate(own_cell[cell_index], x, reference))
              {
                particle->set_reference_location(reference);
                continue;
              }
            unsigned int target = end;
            for (unsigned int c = own + 1; c < end; ++c)
              if (locate(patch_cells[c], x, reference))
                {
                  target = c;
                  break;
                }
            if (target == end || !patch_cell_iterators[target]->is_locally_owned())
              {
                leaves_patch = true; // out of the domain, to another rank, beyond the patch
                continue;
              }
            // A copy of what the point carries, to insert it in its new cell (inserting can
            // grow the property pool and move the memory the point's properties are in).
            moving_particles.push_back(
              {particle, patch_cell_iterators[target], particle->get_id(), x, reference});
            const auto properties = particle->get_properties();
            moving_data.insert(moving_data.end(), properties.begin(), properties.end());
          }
      });
      // Collective: one reduction decides for all ranks.
      const unsigned int local[2]  = {leaves_patch ? 1u : 0u, moving_particles.empty() ? 0u : 1u};
      unsigned int       global[2] = {0, 0};
      lap(StepTimeline::relocation);
      dealii::Utilities::MPI::max(dealii::ArrayView<const unsigned int>(local, 2),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<unsigned int>(global, 2));
      lap(StepTimeline::relocation_reduction);
      if (global[0] != 0)
        return false; // the full sort takes over (the locations are set)
      if (global[1] == 0)
        return true;

      // As deal.II's sort does it, so that the points end up in the same order within
      // their cells: the moving points are appended to their new cells first, then
      // removed from their old ones back to front (the points were collected cell by cell
      // in increasing order within each cell; a removal moves a cell's last point into
      // the gap, so the iterators of the points still to be removed stay valid).
      for (unsigned int k = 0; k < moving_particles.size(); ++k)
        {
          const MovingParticle &moving = moving_particles[k];
          particle_handler.insert_particle(
            moving.location,
            moving.reference,
            moving.id,
            moving.cell,
            dealii::ArrayView<const double>(moving_data.data() + k * n_properties, n_properties));
        }
      for (auto moving = moving_particles.rbegin(); moving != moving_particles.rend(); ++moving)
        particle_handler.remove_particle(moving->particle);
      particle_handler.update_cached_numbers();
      return true;
    }



    std::string
    MaterialPointSolver::find_invalid_particle() const
    {
      std::string problem;
      for (const auto &particle : particle_handler)
        {
          const auto p  = particle.get_properties();
          bool       ok = p[property::volume] > 0.;
          for (unsigned int i = 0; i < property::n_properties; ++i)
            ok = ok && std::isfinite(p[i]);
          for (unsigned int d = 0; d < 2; ++d)
            ok = ok && std::isfinite(particle.get_location()[d]);
          if (!ok)
            {
              std::ostringstream out;
              out << "material point " << particle.get_id() << " at (" << particle.get_location()
                  << ") has "
                  << (std::isfinite(p[property::volume]) && p[property::volume] <= 0. ?
                        "a non-positive volume" :
                        "non-finite values")
                  << " (velocity " << p[property::velocity_x] << ", " << p[property::velocity_y]
                  << "; stress " << p[property::stress_xx] << ", " << p[property::stress_yy] << ", "
                  << p[property::stress_xy] << ")";
              problem = out.str();
              break;
            }
        }
      if (problem.empty())
        problem = wall_crossing;
      // Every rank learns the problem of the lowest rank that has one.
      const unsigned int my_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const unsigned int first   = dealii::Utilities::MPI::min(
        problem.empty() ? dealii::numbers::invalid_unsigned_int : my_rank, MPI_COMM_WORLD);
      if (first == dealii::numbers::invalid_unsigned_int)
        return "";
      return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, first);
    }



    MaterialPointSolver::EnergyBudget
    MaterialPointSolver::energy_budget() const
    {
      double sums[3] = {0., 0., 0.};
      for (const auto &particle : particle_handler)
        {
          const auto   p  = particle.get_properties();
          const double m  = p[property::mass];
          const double vx = p[property::velocity_x], vy = p[property::velocity_y];
          sums[0] += 0.5 * m * (vx * vx + vy * vy);
          const auto &elastic
            = materials[static_cast<unsigned int>(p[property::material_id])].elasticity();
          const double sxx = p[property::stress_xx], syy = p[property::stress_yy],
                       szz = p[property::stress_zz], sxy = p[property::stress_xy];
          const double mean = (sxx + syy + szz) / 3.;
          const double dev2 = (sxx - mean) * (sxx - mean) + (syy - mean) * (syy - mean)
                              + (szz - mean) * (szz - mean) + 2. * sxy * sxy;
          sums[1] += p[property::volume]
                     * (0.5 * mean * mean / elastic.bulk_modulus()
                        + 0.25 * dev2 / elastic.shear_modulus());
          sums[2] += m
                     * (prm.gravity[0] * (particle.get_location()[0] - p[property::initial_x])
                        + prm.gravity[1] * (particle.get_location()[1] - p[property::initial_y]));
        }
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 3));
      return {sums[0], sums[1], sums[2]};
    }



    std::string
    MaterialPointSolver::describe_fastest_particle() const
    {
      double             fastest = -1.;
      std::ostringstream out;
      for (const auto &particle : particle_handler)
        {
          const auto   p     = particle.get_properties();
          const double speed = std::sqrt(p[property::velocity_x] * p[property::velocity_x]
                                         + p[property::velocity_y] * p[property::velocity_y]);
          if (speed > fastest)
            {
              fastest = speed;
              out.str("");
              out << "material point " << particle.get_id() << " at (" << particle.get_location()
                  << ") with speed " << speed << " m/s";
            }
        }
      // The rank with the fastest point tells everybody.
      const auto         my_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const double       global  = dealii::Utilities::MPI::max(fastest, MPI_COMM_WORLD);
      const unsigned int owner   = dealii::Utilities::MPI::min(
        fastest == global ? my_rank : dealii::numbers::invalid_unsigned_int, MPI_COMM_WORLD);
      return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, out.str(), owner);
    }



    MaterialPointSolver::Integrals
    MaterialPointSolver::integrals() const
    {
      Integrals result;
      double    sums[4] = {0., 0., 0., 0.};
      double    maxima[3]
        = {0., -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
      for (const auto &particle : particle_handler)
        {
          const auto   p  = particle.get_properties();
          const double m  = p[property::mass];
          const double vx = p[property::velocity_x], vy = p[property::velocity_y];
          sums[0] += m;
          sums[1] += m * vx;
          sums[2] += m * vy;
          sums[3] += 0.5 * m * (vx * vx + vy * vy);
          maxima[0] = std::max(maxima[0], std::sqrt(vx * vx + vy * vy));
          maxima[1] = std::max(maxima[1], particle.get_location()[0]);
          maxima[2] = std::max(maxima[2], particle.get_location()[1]);
        }
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 4),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 4));
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(maxima, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(maxima, 3));
      result.mass           = sums[0];
      result.momentum_x     = sums[1];
      result.momentum_y     = sums[2];
      result.kinetic_energy = sums[3];
      result.max_speed      = maxima[0];
      result.runout         = maxima[1];
      result.max_height     = maxima[2];
      result.lost_mass      = dealii::Utilities::MPI::sum(lost_mass, MPI_COMM_WORLD);
      result.n_particles    = particle_handler.n_global_particles();
      return result;
    }
  } // namespace mpm
} // namespace slidewave
