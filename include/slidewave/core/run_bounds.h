#ifndef slidewave_core_run_bounds_h
#define slidewave_core_run_bounds_h

#include <slidewave/core/scene_parameters.h>
#include <string>

namespace slidewave
{
  namespace core
  {
    /** @name Bounds on how much a run may step and write (doc/stability.md) */
    /** @{ */
    /** Steps of one run: a scene that needs more is a mistake in its time step or end time,
     *  not a run anyone waits for. */
    constexpr double max_steps = 1e7;
    /** Outputs of one run (each writes a set of files: a run beyond this fills a disk or a
     *  file system's inode table, and nobody looks at 10^5 frames). */
    constexpr double max_outputs = 1e5;
    /** Checkpoints of one run (each rewrites the whole state). */
    constexpr double max_checkpoints = 1e5;
    /** The shortest 'Checkpoint/Wall time interval' [minutes]: a checkpoint of a large scene
     *  takes seconds; more often, the run would spend its time writing them. */
    constexpr double min_checkpoint_minutes = 0.1;
    /** @} */

    /**
     * Checks what the entries of @p scene alone bound: the number of outputs ('Time/Output
     * interval'), of steps at 'Time/Maximum time step' and of checkpoints at
     * 'Checkpoint/Step interval' with it, and 'Checkpoint/Wall time interval'. Throws an
     * InputError naming the entry, its value, the bound and why.
     */
    void
    check_run_bounds(const SceneParameters &scene);

    /**
     * Checks a run of steps of about @p dt from the start to the end time of @p scene: at
     * most max_steps steps and, with 'Checkpoint/Step interval', at most max_checkpoints
     * checkpoints. @p parameter (full path) and @p value name what sets @p dt, @p how says
     * how it was found ("the first step ..."), both for the message.
     */
    void
    check_step_count(const SceneParameters &scene,
                     double                 dt,
                     const std::string     &parameter,
                     const std::string     &value,
                     const std::string     &how);
  } // namespace core
} // namespace slidewave

#endif
