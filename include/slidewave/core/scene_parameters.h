#ifndef slidewave_core_scene_parameters_h
#define slidewave_core_scene_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace slidewave
{
  /**
   * The physics a scene switches on. Only the components of the chosen physics are
   * created, allocated and computed, and only their parameters are read.
   */
  enum class Physics
  {
    none,
    shallow_water,
    material_points,
    coupled,           ///< material points under shallow water (paper 000, Algorithm 1)
    depth_averaged,    ///< depth-averaged material points over a terrain (paper 001)
    free_surface_flow, ///< water and air by stabilized finite elements (paper 002's fluid)
    granular_water     ///< a granular skeleton of material points in that flow (paper 002)
  };

  /**
   * The top level of a scene file: which physics, where the output goes, the time window and
   * how often to report. Every physics reads these; its own parameters live in its own
   * subsection.
   */
  struct SceneParameters
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads and checks the entries. @p input_file is the scene file: the default output
     * directory is derived from its name ("output-<name without .prm>").
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &input_file);

    /**
     * A file name given in the scene, resolved: relative names are taken relative to the
     * directory of the scene file, so that a scene and its data files move together.
     */
    std::string
    resolve_path(const std::string &file_name) const;

    Physics     physics = Physics::none;
    std::string scene_directory;
    std::string output_directory;

    double       start_time          = 0.;
    double       end_time            = 0.;
    double       maximum_time_step   = 0.;
    double       output_interval     = 0.;
    unsigned int statistics_interval = 1;

    /** Subsection Checkpoint. */
    unsigned int checkpoint_steps   = 0;
    double       checkpoint_minutes = 0.;
    bool         checkpoint_at_end  = false;
    bool         resume             = false;

    /** Deterministic, fixed-precision reporting for the test suite (subsection Test). */
    bool test_mode = false;
  };
} // namespace slidewave

#endif
