#ifndef slidewave_io_solver_checkpoints_h
#define slidewave_io_solver_checkpoints_h

#include <slidewave/io/checkpoint.h>
#include <string>

namespace slidewave
{
  namespace io
  {
    /**
     * A material-point solver's state besides the points and the grid (which go to the
     * checkpoint's data files): its time, step counter and lost mass, under "<name>/"
     * (collective: the lost mass is summed over the ranks). For every solver whose
     * state() has the members time, lost_mass and n_steps (soil::MaterialPointSolver,
     * depth_averaged::DepthAveragedSolver).
     */
    template <class Solver>
    void
    save_state(CheckpointRecord &record, const std::string &name, const Solver &solver)
    {
      const auto state = solver.state();
      record.put(name + "/time", state.time);
      record.put(name + "/lost_mass", state.lost_mass);
      record.put(name + "/steps", state.n_steps);
    }

    /** What save_state() put under "<name>/", after the solver's load(). */
    template <class Solver>
    void
    restore_state(const CheckpointRecord &record, const std::string &name, Solver &solver)
    {
      typename Solver::State state;
      state.time      = record.get(name + "/time");
      state.lost_mass = record.get(name + "/lost_mass");
      state.n_steps   = record.get_unsigned(name + "/steps");
      solver.set_state(state);
    }
  } // namespace io
} // namespace slidewave

#endif
