#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <slidewave/app/application.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/output_locations.h>
#include <slidewave/core/parameter_documentation.h>
#include <slidewave/core/scene_file_check.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/coupling/coupled_scene.h>
#include <slidewave/depth_averaged/depth_averaged_scene.h>
#include <slidewave/fluid/free_surface_scene.h>
#include <slidewave/granular/granular_water_scene.h>
#include <slidewave/soil/material_point_scene.h>
#include <slidewave/water/water_scene.h>
#include <sstream>

namespace slidewave
{
  namespace
  {
    const char *usage
      = "Usage: slidewave [options] SCENE.prm\n"
        "\n"
        "Runs the scene described by the parameter file SCENE.prm (in parallel with\n"
        "'mpirun -np N slidewave SCENE.prm').\n"
        "\n"
        "Options:\n"
        "  --validate                 parse and check SCENE.prm, run nothing\n"
        "  --set 'PATH=VALUE'         override one parameter after reading the file, e.g.\n"
        "                             --set 'Shallow water/Mesh/Number of cells=400'\n"
        "  --resume                   resume from the newest checkpoint in the output\n"
        "                             directory (same as --set 'Checkpoint/Resume=true')\n"
        "  --print-parameters [FMT]   print every parameter with its default, allowed\n"
        "                             values and documentation; FMT is prm (default),\n"
        "                             json or markdown\n"
        "  --help                     this text\n"
        "  --version                  the version\n"
        "\n"
        "Exit status: 0 success, 1 bad input (nothing run), 2 the run became invalid\n"
        "(or an output could not be written, or memory ran out), 3 an exact-solution check\n"
        "exceeded its tolerance, 4 an unexpected error.\n";

    /** deal.II's exception text without its source location, on one line. */
    std::string
    one_line(const dealii::ExceptionBase &exception)
    {
      std::ostringstream info;
      exception.print_info(info);
      std::string text  = info.str(), result;
      bool        space = false;
      for (const char c : text)
        {
          if (std::isspace(static_cast<unsigned char>(c)))
            space = !result.empty();
          else
            {
              if (space)
                result += ' ';
              result += c;
              space = false;
            }
        }
      return result;
    }

    /**
     * deal.II's parse errors give a line number but not the subsection, and several
     * subsections have entries of the same name ("Type"). Replays the subsection/end lines
     * of @p file up to that line and returns " (in subsection 'A/B')", or "" at top level.
     */
    std::string
    subsection_at_line(const std::string &file, const std::string &message)
    {
      const auto at = message.find("Line <");
      if (at == std::string::npos)
        return "";
      const unsigned int       line_number = std::atoi(message.c_str() + at + 6);
      std::ifstream            in(file);
      std::vector<std::string> path;
      std::string              line;
      for (unsigned int n = 1; n < line_number && std::getline(in, line); ++n)
        {
          const std::string trimmed = dealii::Utilities::trim(line.substr(0, line.find('#')));
          if (trimmed.rfind("subsection ", 0) == 0)
            path.push_back(dealii::Utilities::trim(trimmed.substr(11)));
          else if (trimmed == "end" && !path.empty())
            path.pop_back();
        }
      if (path.empty())
        return "";
      std::string joined;
      for (const auto &p : path)
        joined += (joined.empty() ? "" : "/") + p;
      return " (in subsection '" + joined + "')";
    }

    /** Applies one --set override "a/b/Name=value". */
    void
    apply_override(dealii::ParameterHandler &prm, const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      if (equal == std::string::npos)
        throw InputError("--set", assignment, "an assignment 'Subsection/Name=value'");
      const std::string path  = dealii::Utilities::trim(assignment.substr(0, equal));
      const std::string value = dealii::Utilities::trim(assignment.substr(equal + 1));
      auto              parts = dealii::Utilities::split_string_list(path, '/');
      const std::string name  = parts.back();
      parts.pop_back();
      unsigned int depth = 0;
      try
        {
          for (const auto &subsection : parts)
            {
              prm.enter_subsection(subsection);
              ++depth;
            }
          prm.set(name, value);
        }
      catch (...)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          throw InputError(path,
                           value,
                           "a declared parameter and a value of its type (see "
                           "'slidewave --print-parameters')");
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
    }

    /**
     * Creates the output directory (rank 0), checks that it can be written (all ranks learn
     * the verdict) and copies the scene file into it.
     */
    void
    prepare_output_directory(const std::string &directory, const std::string &input_file)
    {
      core::prepare_output_locations(directory, {});
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          const auto target
            = std::filesystem::path(directory) / std::filesystem::path(input_file).filename();
          std::error_code copy_error;
          if (!std::filesystem::equivalent(input_file, target, copy_error))
            std::filesystem::copy_file(input_file,
                                       target,
                                       std::filesystem::copy_options::overwrite_existing,
                                       copy_error);
        }
    }


    /** Builds the scene of a physics (which reads and checks its parameters); runs it
     *  unless only validating. Returns an ExitStatus. */
    template <class Scene>
    int
    run_scene(const SceneParameters    &scene,
              dealii::ParameterHandler &prm,
              const bool                validate_only,
              const std::string        &input_file,
              std::ostream             &out)
    {
      Scene physics(scene, prm);
      // Before anything large is allocated: refused when it cannot fit.
      const core::MemoryEstimate memory = physics.memory_estimate();
      memory.check();
      if (validate_only)
        {
          out << input_file << ": valid; memory: " << memory.describe() << "\n";
          return success;
        }
      prepare_output_directory(scene.output_directory, input_file);
      return physics.run() ? success : verification_error;
    }

    /** What the command line asks for when it names a scene to read. */
    struct CommandLine
    {
      std::string              input_file;
      std::vector<std::string> overrides;
      bool                     validate_only = false;
    };

    /** Prints every parameter in @p format (prm, json or markdown). Returns an ExitStatus. */
    int
    print_all_parameters(const std::string &format, std::ostream &out, std::ostream &err)
    {
      dealii::ParameterHandler prm;
      declare_all_parameters(prm);
      if (format == "prm")
        prm.print_parameters(out,
                             dealii::ParameterHandler::PRM
                               | dealii::ParameterHandler::KeepDeclarationOrder);
      else if (format == "json")
        prm.print_parameters(out,
                             dealii::ParameterHandler::JSON
                               | dealii::ParameterHandler::KeepDeclarationOrder);
      else if (format == "markdown")
        print_parameters_markdown(prm, out);
      else
        {
          err << "slidewave: error: --print-parameters " << format
              << ": allowed formats are prm, json and markdown\n";
          return input_error;
        }
      return success;
    }

    /**
     * Parses the command line @p arguments into @p command_line, in order. Options that end
     * the program (--help, --version, --print-parameters) are served here, and an error is
     * reported here: then returns the ExitStatus; returns nothing when a scene is to be read.
     */
    std::optional<int>
    parse_command_line(const std::vector<std::string> &arguments,
                       CommandLine                    &command_line,
                       std::ostream                   &out,
                       std::ostream                   &err)
    {
      for (unsigned int a = 0; a < arguments.size(); ++a)
        {
          const std::string &arg = arguments[a];
          if (arg == "--help" || arg == "-h")
            {
              out << usage;
              return success;
            }
          if (arg == "--version")
            {
              out << "slidewave " << SLIDEWAVE_VERSION << " (deal.II " << DEAL_II_PACKAGE_VERSION
                  << ")\n";
              return success;
            }
          if (arg == "--print-parameters")
            return print_all_parameters(a + 1 < arguments.size() ? arguments[a + 1] : "prm",
                                        out,
                                        err);
          if (arg == "--validate")
            command_line.validate_only = true;
          else if (arg == "--resume")
            command_line.overrides.push_back("Checkpoint/Resume=true");
          else if (arg == "--set")
            {
              if (a + 1 >= arguments.size())
                {
                  err << "slidewave: error: --set needs an assignment 'PATH=VALUE'\n";
                  return input_error;
                }
              command_line.overrides.push_back(arguments[++a]);
            }
          else if (!arg.empty() && arg[0] == '-')
            {
              err << "slidewave: error: unknown option '" << arg << "'\n\n" << usage;
              return input_error;
            }
          else if (command_line.input_file.empty())
            command_line.input_file = arg;
          else
            {
              err << "slidewave: error: more than one scene file ('" << command_line.input_file
                  << "', '" << arg << "')\n\n"
                  << usage;
              return input_error;
            }
        }
      return std::nullopt;
    }

    /** Checks that a scene file was given and can be read; reports on @p err if not. */
    bool
    scene_file_is_readable(const std::string &input_file, std::ostream &err)
    {
      if (input_file.empty())
        {
          err << "slidewave: error: no scene file given\n\n" << usage;
          return false;
        }
      if (!std::filesystem::is_regular_file(input_file) || !std::ifstream(input_file))
        {
          err << "slidewave: error: cannot read the scene file '" << input_file << "'\n";
          return false;
        }
      return true;
    }

    /**
     * Declares every parameter into @p prm and parses @p input_file into it. Returns false
     * (after reporting on @p err) if deal.II rejects the file.
     */
    bool
    parse_scene_file(dealii::ParameterHandler &prm,
                     const std::string        &input_file,
                     std::ostream             &err)
    {
      declare_all_parameters(prm);
      // What deal.II would crash on or silently accept (include loops, a parameter set
      // twice, a byte-order mark): an InputError naming the file and the line.
      core::check_scene_file(input_file);
      try
        {
          prm.parse_input(input_file,
                          "",
                          /*skip_undefined=*/false,
                          /*assert_mandatory_entries_are_found=*/false);
        }
      catch (const dealii::ExceptionBase &e)
        {
          err << "slidewave: error: " << one_line(e) << subsection_at_line(input_file, one_line(e))
              << '\n';
          return false;
        }
      return true;
    }

    /** Runs (or only validates) the scene of the physics @p scene names. Returns an
     *  ExitStatus. */
    int
    dispatch_scene(const SceneParameters    &scene,
                   dealii::ParameterHandler &prm,
                   const bool                validate_only,
                   const std::string        &input_file,
                   std::ostream             &out)
    {
      switch (scene.physics)
        {
          case Physics::shallow_water:
            return run_scene<water::WaterScene>(scene, prm, validate_only, input_file, out);
          case Physics::material_points:
            return run_scene<soil::MaterialPointScene>(scene, prm, validate_only, input_file, out);
          case Physics::coupled:
            return run_scene<coupling::CoupledScene>(scene, prm, validate_only, input_file, out);
          case Physics::depth_averaged:
            return run_scene<depth_averaged::DepthAveragedScene>(
              scene, prm, validate_only, input_file, out);
          case Physics::free_surface_flow:
            return run_scene<fluid::FreeSurfaceScene>(scene, prm, validate_only, input_file, out);
          case Physics::granular_water:
            return run_scene<granular::GranularWaterScene>(
              scene, prm, validate_only, input_file, out);
          case Physics::none:
            break;
        }
      return input_error;
    }

    /**
     * Reads the scene file of @p command_line, applies its overrides, checks the scene and
     * runs it (or only validates it). Input errors and run failures are reported on @p err.
     * Returns an ExitStatus.
     */
    int
    read_and_run_scene(const CommandLine &command_line, std::ostream &out, std::ostream &err)
    {
      const std::string &input_file = command_line.input_file;
      try
        {
          dealii::ParameterHandler prm;
          if (!parse_scene_file(prm, input_file, err))
            return input_error;
          for (const auto &assignment : command_line.overrides)
            apply_override(prm, assignment);

          SceneParameters scene;
          scene.parse_parameters(prm, input_file);
          return dispatch_scene(scene, prm, command_line.validate_only, input_file, out);
        }
      catch (const InputError &e)
        {
          err << "slidewave: error in '" << input_file << "': " << e.what() << '\n';
          return input_error;
        }
      catch (const RunFailure &e)
        {
          err << "slidewave: run failed " << e.what()
              << "; the output written before this step is kept.\n";
          return run_failure;
        }
      catch (const OutputFailure &e)
        {
          err << "slidewave: output failed: " << e.what()
              << "; free space or make the output directory writable, then run again "
                 "(or resume from the last checkpoint).\n";
          return run_failure;
        }
      catch (const std::bad_alloc &)
        {
          err << "slidewave: out of memory: the scene '" << input_file
              << "' needs more memory than this machine could give (the estimate that "
                 "'slidewave --validate' prints was not enough: see 'Memory estimate' in "
                 "doc/stability.md); make the grid coarser or smaller, use fewer points per "
                 "cell, or run on more nodes.\n";
          return run_failure;
        }
      catch (const std::filesystem::filesystem_error &e)
        {
          err << "slidewave: file system error with '" << e.path1().string() << "'"
              << (e.path2().empty() ? std::string() : " and '" + e.path2().string() + "'") << ": "
              << e.code().message()
              << "; check that the output directory (parameter 'Output directory') and the "
                 "files the scene reads exist and can be written or read.\n";
          return run_failure;
        }
      catch (const dealii::ExceptionBase &e)
        {
          err << "slidewave: error while running '" << input_file << "': " << one_line(e) << '\n';
          return run_failure;
        }
      catch (const std::exception &e)
        {
          const std::string what = e.what();
          err << "slidewave: error while running '" << input_file
              << "': " << (what.empty() ? std::string("an exception without a message") : what)
              << " (please report it with the scene file)\n";
          return 4;
        }
    }
  } // namespace



  void
  declare_all_parameters(dealii::ParameterHandler &prm)
  {
    SceneParameters::declare_parameters(prm);
    water::WaterScene::declare_parameters(prm);
    soil::MaterialPointScene::declare_parameters(prm);
    coupling::CoupledScene::declare_parameters(prm);
    depth_averaged::DepthAveragedScene::declare_parameters(prm);
    fluid::FreeSurfaceScene::declare_parameters(prm);
    granular::GranularWaterScene::declare_parameters(prm);
  }



  int
  run_application(const std::vector<std::string> &arguments,
                  std::ostream                   &out_all,
                  std::ostream                   &err_all)
  {
    const bool    is_root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    std::ostream  null_stream(nullptr);
    std::ostream &out = is_root ? out_all : null_stream;
    std::ostream &err = is_root ? err_all : null_stream;

    CommandLine command_line;
    if (const auto done = parse_command_line(arguments, command_line, out, err))
      return *done;
    if (!scene_file_is_readable(command_line.input_file, err))
      return input_error;
    return read_and_run_scene(command_line, out, err);
  }
} // namespace slidewave
