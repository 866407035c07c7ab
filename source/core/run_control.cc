#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/output_locations.h>
#include <slidewave/core/progress_reporter.h>
#include <slidewave/core/run_control.h>

namespace slidewave
{
  namespace
  {
    bool
    is_writer()
    {
      return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }
  } // namespace



  RunControl::RunControl(const SceneParameters &scene)
    : scene(scene)
    , time_tolerance(1e-12 * (scene.end_time - scene.start_time))
  {
    state.time        = scene.start_time;
    state.next_output = next_output_after(scene.start_time);
  }



  double
  RunControl::next_output_after(const double time) const
  {
    if (!(scene.output_interval > 0.))
      return scene.end_time;
    return scene.start_time
           + (std::floor((time - scene.start_time) / scene.output_interval + 1e-9) + 1.)
               * scene.output_interval;
  }



  StepInfo
  RunControl::plan_step(const double stable_dt) const
  {
    StepInfo info;
    info.old_time = state.time;
    double dt     = stable_dt;
    if (scene.maximum_time_step > 0.)
      dt = std::min(dt, scene.maximum_time_step);
    const double target = std::min(state.next_output, scene.end_time);
    if (!std::isfinite(dt))
      dt = target - state.time;
    const bool reaches_target = state.time + dt >= target - time_tolerance;
    if (reaches_target)
      dt = target - state.time;
    else if (state.time + 2. * dt > target - time_tolerance)
      // Between one and two steps to go: two equal steps, not a full one and a short one.
      // The granular water's pore pressure moves with the step's length: a step ten times
      // shorter than its neighbours showed in the fields written at that output time
      // (doc/free-surface-flow.md, "Pressure probes").
      dt = 0.5 * (target - state.time);
    info.dt             = dt;
    info.time           = reaches_target ? target : state.time + dt;
    info.step           = state.step + 1;
    info.is_output_time = reaches_target && target == state.next_output;
    info.at_end         = info.time >= scene.end_time - time_tolerance;
    info.reports = info.is_output_time || info.at_end || info.step % scene.statistics_interval == 0;
    return info;
  }



  bool
  RunControl::checkpoint_due(const StepInfo &info) const
  {
    bool due = (scene.checkpoint_steps > 0 && info.step % scene.checkpoint_steps == 0)
               || (info.at_end && scene.checkpoint_at_end);
    if (scene.checkpoint_minutes > 0.)
      {
        const double minutes
          = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint)
              .count()
            / 60.;
        due = due
              || dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD,
                                                   minutes >= scene.checkpoint_minutes,
                                                   0);
      }
    return due;
  }



  std::vector<std::string>
  RunControl::growing_files(const TimeSteppedScene &body) const
  {
    auto files = body.growing_files();
    files.insert(files.begin(), "statistics.csv");
    return files;
  }



  void
  RunControl::write_checkpoint(TimeSteppedScene &body, Statistics &statistics)
  {
    statistics.flush();
    io::CheckpointRecord record;
    record.put("run/time", state.time);
    record.put("run/step", state.step);
    record.put("run/output_index", state.output_index);
    record.put("run/next_output", state.next_output);
    record.put("run/output_interval", scene.output_interval);
    body.save(record);
    io::CheckpointDirectory(scene.output_directory)
      .write(body.checkpoint_signature(),
             record,
             growing_files(body),
             [&body](const std::string &prefix) { body.save_data(prefix); });
    last_checkpoint = std::chrono::steady_clock::now();
  }



  std::string
  RunControl::check_record(const io::CheckpointRecord &record) const
  {
    // Every number of a record is finite (CheckpointRecord::read); get_unsigned() refuses
    // what is not a whole number an unsigned int holds.
    const double time     = record.get("run/time");
    const double next     = record.get("run/next_output");
    const double interval = record.get("run/output_interval");
    record.get_unsigned("run/step");
    record.get_unsigned("run/output_index");
    const std::string in_record = "'record.txt' is damaged: ";
    if (time < scene.start_time)
      return in_record + "'run/time' is " + to_string(time) + " s, before the start time "
             + to_string(scene.start_time) + " s";
    if (next < time)
      return in_record + "'run/next_output' is " + to_string(next) + " s, before 'run/time' "
             + to_string(time) + " s";
    if (interval < 0.)
      return in_record + "'run/output_interval' is " + to_string(interval) + " s";
    return "";
  }



  void
  RunControl::resume(TimeSteppedScene &body, dealii::TimerOutput &timer)
  {
    io::CheckpointRecord record;
    const std::string    prefix
      = io::CheckpointDirectory(scene.output_directory)
          .read(body.checkpoint_signature(),
                record,
                growing_files(body),
                [this](const io::CheckpointRecord &r) { return check_record(r); });
    state.time         = record.get("run/time");
    state.step         = record.get_unsigned("run/step");
    state.output_index = record.get_unsigned("run/output_index");
    state.next_output  = record.get("run/next_output");
    // A changed output interval restarts the output times from the resumed time.
    if (record.get("run/output_interval") != scene.output_interval)
      state.next_output = next_output_after(state.time);
    if (!(scene.end_time > state.time))
      throw InputError("Time/End time",
                       to_string(scene.end_time),
                       "a time after the checkpoint's t = " + to_string(state.time) + " s");
    body.resume(record, prefix, timer);
  }



  bool
  RunControl::run(TimeSteppedScene &body, dealii::TimerOutput &timer)
  {
    using dealii::TimerOutput;
    const bool         test_mode = scene.test_mode;
    const std::string &prefix    = body.timer_prefix();
    std::ostream      *console   = is_writer() && !test_mode ? &std::cout : nullptr;

    // Every folder checked before the first step; all ranks refuse together.
    core::prepare_output_locations(scene.output_directory, body.output_folders());

    if (scene.resume)
      resume(body, timer);
    else
      body.set_up(scene.start_time, timer);
    body.check_set_up();
    if (console)
      *console << body.description()
               << (scene.resume ? "; resumed at t = " + to_string(state.time) + " s" : "")
               << std::endl;

    Statistics statistics;
    statistics.open(scene.output_directory + "/statistics.csv",
                    is_writer(),
                    is_writer() && test_mode ? &std::cout : nullptr,
                    scene.resume);
    ProgressReporter progress(console, state.time, scene.end_time);

    StepInfo info;
    info.step     = state.step;
    info.old_time = info.time = state.time;
    if (!scene.resume)
      {
        body.write_output(state.output_index++, state.time);
        body.start(info);
        body.add_statistics(statistics, info);
        statistics.end_row();
      }

    last_checkpoint = std::chrono::steady_clock::now();
    while (state.time < scene.end_time - time_tolerance)
      {
        info = plan_step(body.stable_time_step());
        body.advance(info);
        state.time = info.time;
        state.step = info.step;
        body.after_step(info);

        if (info.is_output_time || info.at_end)
          {
            body.write_output(state.output_index++, state.time);
            if (info.is_output_time)
              state.next_output = scene.output_interval > 0. ?
                                    state.next_output + scene.output_interval :
                                    scene.end_time;
          }
        if (info.reports)
          {
            TimerOutput::Scope scope(timer, prefix + ": statistics");
            body.add_statistics(statistics, info);
            statistics.end_row();
          }
        progress.report(state.step, state.time, info.dt, info.at_end);

        if (checkpoint_due(info))
          {
            TimerOutput::Scope scope(timer, prefix + ": checkpoint");
            write_checkpoint(body, statistics);
          }
      }
    statistics.flush();
    return body.finish(info);
  }
} // namespace slidewave
