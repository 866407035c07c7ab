#include <filesystem>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/core/scene_parameters.h>

namespace slidewave
{
  namespace
  {
    /** Declares the subsection Time: the time window, the step bound, the report intervals. */
    void
    declare_time_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;

      prm.enter_subsection("Time");
      {
        prm.declare_entry("Start time", "0", Double(), "Time at which the scene starts [s].");
        prm.declare_entry("End time",
                          "1",
                          Double(),
                          "Time at which the scene ends [s]; must be after the start time.");
        prm.declare_entry("Maximum time step",
                          "0",
                          Double(0.),
                          "Upper bound on the time step [s]; 0 means no bound beyond the "
                          "stability limit of the physics.");
        prm.declare_entry("Output interval",
                          "0",
                          Double(0.),
                          "Simulated time between two outputs (profiles, particle files) [s]. "
                          "Output is always written at the start and at the end; 0 means only "
                          "then. Time steps are shortened to land on output times (with "
                          "between one and two steps to go, two equal steps).");
        prm.declare_entry("Statistics interval",
                          "1",
                          Integer(1),
                          "A row is written to statistics.csv every this many steps (and at "
                          "every output time and at the end).");
      }
      prm.leave_subsection();
    }

    /** Declares the subsection Checkpoint: when to write checkpoints and whether to resume. */
    void
    declare_checkpoint_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Bool;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;

      prm.enter_subsection("Checkpoint");
      {
        prm.declare_entry("Step interval",
                          "0",
                          Integer(0),
                          "Write a checkpoint every this many steps (0: never). Checkpoints "
                          "go to OUTPUT/checkpoint (the previous one is kept as "
                          "checkpoint.previous); writing is atomic.");
        prm.declare_entry("Wall time interval",
                          "0",
                          Double(0.),
                          "Write a checkpoint every this many minutes of wall time (0: never).");
        prm.declare_entry("At end", "false", Bool(), "Write a checkpoint at the end of the run.");
        prm.declare_entry("Resume",
                          "false",
                          Bool(),
                          "Resume from the newest checkpoint in the output directory (same as "
                          "the command-line option --resume). The scene may change its end "
                          "time, output and checkpoint settings, and the number of MPI ranks; "
                          "the physics, grid and materials must be those of the checkpoint "
                          "(every physics; doc/checkpoints.md).");
      }
      prm.leave_subsection();
    }

    /** Declares the subsection Test: the deterministic reporting of the test suite. */
    void
    declare_test_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Bool;

      prm.enter_subsection("Test");
      {
        prm.declare_entry("Enable",
                          "false",
                          Bool(),
                          "Test mode: rank 0 prints only deterministic integral quantities at "
                          "fixed precision (no timers, no progress line), identical for any "
                          "number of MPI ranks.");
      }
      prm.leave_subsection();
    }
  } // namespace



  void
  SceneParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Selection;

    prm.declare_entry(
      "Physics",
      "none",
      Selection("none|shallow water|material points|coupled|depth averaged|free surface "
                "flow|granular water"),
      "The physics this scene switches on. 'shallow water': the 1D "
      "well-balanced finite-volume water column of paper 000 (subsection "
      "'Shallow water'). 'material points': the 2D plane-strain material "
      "point method for soil of paper 000 (subsection 'Material points'). "
      "'coupled': both, the soil moving the water's bed and the water "
      "loading the soil (paper 000, Algorithm 1; subsections 'Material "
      "points', 'Shallow water' and 'Coupling'). 'depth averaged': the "
      "depth-averaged material point method for flow-like landslides over "
      "a terrain of paper 001 (subsection 'Depth averaged'). 'free surface "
      "flow': water and air by stabilized finite elements with a phase-field "
      "surface on the background grid, paper 002's fluid (subsection 'Free "
      "surface flow'). 'granular water': a saturated or dry granular skeleton of material "
      "points in that flow, on the same grid, the two-phase MPM-FEM of paper 002 "
      "(subsections 'Material points', 'Free surface flow' and 'Granular water'). A scene "
      "must choose one.");
    prm.declare_entry("Output directory",
                      "",
                      dealii::Patterns::Anything(),
                      "Where results go (created if missing). Empty: 'output-<scene>' in the "
                      "working directory, <scene> being the scene file's name without '.prm'. "
                      "The scene file is copied into it.");

    declare_time_parameters(prm);
    declare_checkpoint_parameters(prm);
    declare_test_parameters(prm);
  }



  std::string
  SceneParameters::resolve_path(const std::string &file_name) const
  {
    if (file_name.empty() || std::filesystem::path(file_name).is_absolute()
        || scene_directory.empty())
      return file_name;
    return (std::filesystem::path(scene_directory) / file_name).string();
  }



  void
  SceneParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &input_file)
  {
    const std::string physics_name = prm.get("Physics");
    if (physics_name == "shallow water")
      physics = Physics::shallow_water;
    else if (physics_name == "material points")
      physics = Physics::material_points;
    else if (physics_name == "coupled")
      physics = Physics::coupled;
    else if (physics_name == "depth averaged")
      physics = Physics::depth_averaged;
    else if (physics_name == "free surface flow")
      physics = Physics::free_surface_flow;
    else if (physics_name == "granular water")
      physics = Physics::granular_water;
    else
      throw InputError("Physics",
                       physics_name,
                       "one of 'shallow water', 'material points', 'coupled', 'depth "
                       "averaged', 'free surface flow', 'granular water' (a scene must choose its "
                       "physics)");

    scene_directory  = std::filesystem::path(input_file).parent_path().string();
    output_directory = prm.get("Output directory");
    if (output_directory.empty())
      output_directory = "output-" + std::filesystem::path(input_file).stem().string();

    prm.enter_subsection("Time");
    {
      start_time          = prm.get_double("Start time");
      end_time            = prm.get_double("End time");
      maximum_time_step   = prm.get_double("Maximum time step");
      output_interval     = prm.get_double("Output interval");
      statistics_interval = prm.get_integer("Statistics interval");
    }
    prm.leave_subsection();
    if (!(end_time > start_time))
      throw InputError("Time/End time",
                       to_string(end_time),
                       "a time after 'Time/Start time' = " + to_string(start_time));

    prm.enter_subsection("Test");
    test_mode = prm.get_bool("Enable");
    prm.leave_subsection();

    prm.enter_subsection("Checkpoint");
    {
      checkpoint_steps   = prm.get_integer("Step interval");
      checkpoint_minutes = prm.get_double("Wall time interval");
      checkpoint_at_end  = prm.get_bool("At end");
      resume             = prm.get_bool("Resume");
    }
    prm.leave_subsection();
    // How many outputs, steps and checkpoints the entries allow (at --validate too).
    core::check_run_bounds(*this);
  }
} // namespace slidewave
