#ifndef slidewave_core_time_stepped_scene_h
#define slidewave_core_time_stepped_scene_h

#include <deal.II/base/timer.h>
#include <slidewave/core/output_locations.h>
#include <slidewave/core/statistics.h>
#include <slidewave/io/checkpoint.h>
#include <string>
#include <vector>

namespace slidewave
{
  /** Where the run stands at the end of a step (or at the start: step 0, dt 0). */
  struct StepInfo
  {
    unsigned int step = 0;
    /** The time at the start of the step and at its end (after the step, time). */
    double old_time = 0., time = 0., dt = 0.;
    /** The step ended on an output time, at the end of the run; a statistics row is due
     *  (every 'Statistics interval' steps, at output times and at the end). */
    bool is_output_time = false, at_end = false, reports = false;
  };



  /**
   * What a scene gives the run control (RunControl): the body of its step and the hooks
   * around it. The run control owns the time, the step counter, the output times, the
   * statistics file, the progress line and the checkpoints; a scene owns its solvers and
   * says what to compute, check, write and save. The calls are per step, never per point.
   *
   * One step: stable_time_step(), then (the run control clamps the step to the next output
   * time and the end) advance(), after_step(), write_output() at output times and at the
   * end, add_statistics() when a row is due, and a checkpoint when one is due.
   */
  class TimeSteppedScene
  {
  public:
    virtual ~TimeSteppedScene() = default;

    /** The prefix of the scene's timer sections and of its console lines ("mpm"). */
    virtual std::string
    timer_prefix() const = 0;

    /** The folders (in the output directory) the scene writes into: the run control
     *  creates them and checks that they can be written before the run starts. */
    virtual std::vector<core::OutputFolder>
    output_folders() const
    {
      return {};
    }

    /** Builds the solvers and the initial state at @p start_time (collective). */
    virtual void
    set_up(double start_time, dealii::TimerOutput &timer)
      = 0;

    /** Checks what can only be checked once the state exists (after set_up() or
     *  resume()), e.g. a fixed time step against the stability limit. */
    virtual void
    check_set_up() const
    {
    }

    /** The line printed on rank 0 once the scene is set up. */
    virtual std::string
    description() const = 0;

    /** Things to record at the start of a fresh run, after the first output (initial
     *  energies, the gauges' first row). */
    virtual void
    start(const StepInfo &)
    {
    }

    /** The largest stable step now (collective); +infinity allows any step. */
    virtual double
    stable_time_step()
      = 0;

    /** The body of the step: from info.old_time to info.time. */
    virtual void
    advance(const StepInfo &info)
      = 0;

    /** After the step: the guards (throw RunFailure), loads for the next step, running
     *  maxima of the verification, gauges. */
    virtual void
    after_step(const StepInfo &)
    {
    }

    /** Writes output number @p index at @p time (the scene decides what, e.g. nothing in
     *  test mode). */
    virtual void
    write_output(unsigned int index, double time)
      = 0;

    virtual void
    add_statistics(Statistics &statistics, const StepInfo &info) const = 0;

    /** After the last step: reports, verification; returns false when a verification
     *  tolerance was exceeded. */
    virtual bool
    finish(const StepInfo &info)
      = 0;

    /** @name Checkpoints */
    /** @{ */

    /** What a checkpoint must share with the scene that resumes it (physics, grid,
     *  materials...), one line. */
    virtual std::string
    checkpoint_signature() const = 0;

    /** Output files (relative to the output directory) that grow during the run, besides
     *  statistics.csv: the checkpoint keeps a copy and a resumed run continues them. */
    virtual std::vector<std::string>
    growing_files() const
    {
      return {};
    }

    /** Puts the scene's state into @p record (collective; rank 0's record is written). */
    virtual void
    save(io::CheckpointRecord &record)
      = 0;

    /** Writes the scene's large data under @p prefix (collective). */
    virtual void
    save_data(const std::string &)
    {
    }

    /** Instead of set_up(): the state of @p record and the data under @p prefix. */
    virtual void
    resume(const io::CheckpointRecord &record,
           const std::string          &prefix,
           dealii::TimerOutput        &timer)
      = 0;
    /** @} */
  };
} // namespace slidewave

#endif
