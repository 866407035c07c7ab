#ifndef slidewave_io_solver_checkpoints_h
#define slidewave_io_solver_checkpoints_h

#include <slidewave/io/checkpoint.h>
#include <slidewave/mpm/material_point_solver.h>
#include <slidewave/water/shallow_water_1d.h>
#include <string>

namespace slidewave
{
  namespace io
  {
    /**
     * The material points' state besides the points and the grid (which go to the
     * checkpoint's data files): the solver's time, step counter and lost mass, under
     * "<name>/" (collective: the lost mass is summed over the ranks).
     */
    void
    save_state(CheckpointRecord               &record,
               const std::string              &name,
               const mpm::MaterialPointSolver &soil);

    /** What save_state() put under "<name>/", after MaterialPointSolver::load(). */
    void
    restore_state(const CheckpointRecord   &record,
                  const std::string        &name,
                  mpm::MaterialPointSolver &soil);

    /** The water's whole state under "<name>/": depth, discharge and bed per cell and the
     *  volume that entered through the ends. */
    void
    save_state(CheckpointRecord            &record,
               const std::string           &name,
               const water::ShallowWater1D &water);

    /** What save_state() put under "<name>/", bit for bit. */
    void
    restore_state(const CheckpointRecord &record,
                  const std::string      &name,
                  water::ShallowWater1D  &water);
  } // namespace io
} // namespace slidewave

#endif
