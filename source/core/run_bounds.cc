#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>

namespace slidewave
{
  namespace core
  {
    void
    check_step_count(const SceneParameters &scene,
                     const double           dt,
                     const std::string     &parameter,
                     const std::string     &value,
                     const std::string     &how)
    {
      if (!(dt > 0.))
        return;
      const double length  = scene.end_time - scene.start_time;
      const double n_steps = length / dt;
      if (n_steps > max_steps)
        throw InputError(parameter,
                         value,
                         "a time step (" + how + ": " + to_string(dt)
                           + " s) that reaches the end time in at most 10^7 steps (it would "
                             "take "
                           + to_string(n_steps) + " from " + to_string(scene.start_time) + " s to "
                           + to_string(scene.end_time)
                           + " s); a longer time step or an earlier end time");
      if (scene.checkpoint_steps > 0 && n_steps / scene.checkpoint_steps > max_checkpoints)
        throw InputError("Checkpoint/Step interval",
                         std::to_string(scene.checkpoint_steps),
                         "an interval giving at most 10^5 checkpoints in a run (each "
                         "rewrites the whole state); with "
                           + to_string(n_steps) + " steps (" + how + ": " + to_string(dt)
                           + " s), this one gives " + to_string(n_steps / scene.checkpoint_steps)
                           + ": at least " + to_string(std::ceil(n_steps / max_checkpoints))
                           + " steps");
    }



    void
    check_run_bounds(const SceneParameters &scene)
    {
      const double length = scene.end_time - scene.start_time;
      if (scene.output_interval > 0. && length / scene.output_interval > max_outputs)
        throw InputError("Time/Output interval",
                         to_string(scene.output_interval),
                         "an interval giving at most 10^5 outputs from the start time "
                           + to_string(scene.start_time) + " s to the end time "
                           + to_string(scene.end_time) + " s (each output writes files; "
                           + "this one gives " + to_string(length / scene.output_interval)
                           + "): at least " + to_string(length / max_outputs)
                           + " s, or 0 for output at the start and the end only");
      if (scene.checkpoint_minutes > 0. && scene.checkpoint_minutes < min_checkpoint_minutes)
        throw InputError("Checkpoint/Wall time interval",
                         to_string(scene.checkpoint_minutes),
                         "0 (never) or at least " + to_string(min_checkpoint_minutes)
                           + " minutes (a checkpoint of a large scene takes seconds; more "
                             "often, the run would spend its time writing them)");
      if (scene.maximum_time_step > 0.)
        check_step_count(scene,
                         scene.maximum_time_step,
                         "Time/Maximum time step",
                         to_string(scene.maximum_time_step),
                         "at most 'Time/Maximum time step'");
    }
  } // namespace core
} // namespace slidewave
