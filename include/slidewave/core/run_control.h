#ifndef slidewave_core_run_control_h
#define slidewave_core_run_control_h

#include <chrono>
#include <deal.II/base/timer.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/time_stepped_scene.h>

namespace slidewave
{
  /**
   * The one time loop of every scene: the time and output-target arithmetic, the cadences
   * of statistics, output and checkpoints, the progress line with its ETA, and resuming
   * from a checkpoint. A scene (TimeSteppedScene) provides only the body of its step and
   * what it reports, checks, writes and saves.
   *
   * The step is the scene's stable step, at most 'Maximum time step', and shortened to land
   * exactly on the next output time and on the end time (within 1e-12 of the run's length):
   * when between one and two steps remain, the remainder is taken as two equal steps, so
   * that no step is much shorter than its neighbours. A scene that allows any step (still
   * water) steps straight to the next of these targets.
   * Output is written at the start, at every output time and at the end; a statistics row
   * at the start, every 'Statistics interval' steps, at output times and at the end;
   * checkpoints every 'Checkpoint/Step interval' steps, every 'Wall time interval' minutes
   * (rank 0's clock decides for all ranks) and at the end if asked.
   */
  class RunControl
  {
  public:
    explicit RunControl(const SceneParameters &scene);

    /**
     * Sets up (or resumes) @p body and runs it to the end time with @p timer. Returns what
     * body.finish() returns; throws what the body throws (InputError, RunFailure).
     */
    bool
    run(TimeSteppedScene &body, dealii::TimerOutput &timer);

    /** The loop's own state, saved in checkpoints under "run/". */
    struct State
    {
      double       time = 0., next_output = 0.;
      unsigned int step = 0, output_index = 0;
    };

  private:
    /** The first output time after @p time on the current output interval. */
    double
    next_output_after(double time) const;

    /** The step from @p stable_dt: the maximum step and the next output or end time. */
    StepInfo
    plan_step(double stable_dt) const;

    bool
    checkpoint_due(const StepInfo &info) const;

    void
    write_checkpoint(TimeSteppedScene &body, Statistics &statistics);

    void
    resume(TimeSteppedScene &body, dealii::TimerOutput &timer);

    /** What is wrong with the run's entries (run/) of a checkpoint's @p record, empty when
     *  they can be resumed: a time at or after the start time, whole step and output
     *  counts, a next output time not before the time, an output interval not negative. */
    std::string
    check_record(const io::CheckpointRecord &record) const;

    std::vector<std::string>
    growing_files(const TimeSteppedScene &body) const;

    const SceneParameters                &scene;
    const double                          time_tolerance;
    State                                 state;
    std::chrono::steady_clock::time_point last_checkpoint;
  };
} // namespace slidewave

#endif
