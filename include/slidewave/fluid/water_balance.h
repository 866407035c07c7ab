#ifndef slidewave_fluid_water_balance_h
#define slidewave_fluid_water_balance_h

#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/io/checkpoint_record.h>
#include <string>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The water's volume balance of a free-surface flow: the water there now plus what
     * has left through the open and inflow sides (FreeSurfaceSolver::water_outflow),
     * against the water there at the start, relative to that start (or to the domain's
     * area when the tank starts empty). Its guard is 'Free surface flow/Guards/Maximum
     * volume drift'; the largest drift of the run is kept for the final report and the
     * checkpoint.
     *
     * In a porous solid the volume is the integral of n phi (the grains' pores hold the
     * rest), so water that the grains push through the open top of a tank counts as
     * outflow, not as drift.
     */
    class WaterBalance
    {
    public:
      explicit WaterBalance(const FreeSurfaceParameters &parameters);

      /** The start: @p volume is the water there [m^2]. */
      void
      start(double volume);

      /** (@p volume + @p outflow - the initial volume) / reference_volume(). */
      double
      drift(double volume, double outflow) const;

      /** Records the drift's magnitude as the largest so far; beyond the guard a
       *  RunFailure that begins with @p where. */
      void
      check(const std::string &where, double volume, double outflow);

      /** The run's end (the caller's writing rank): the largest drift and, when water
       *  crossed the sides, @p outflow, what left through them [m^2]. */
      void
      print_summary(double outflow) const;

      void
      save(io::CheckpointRecord &record) const;

      void
      load(const io::CheckpointRecord &record);

    private:
      /** The initial volume, or the domain's area when the tank starts empty [m^2]. */
      double
      reference_volume() const;

      const FreeSurfaceParameters &parameters;
      double                       initial = 0., largest = 0.;
    };
  } // namespace fluid
} // namespace slidewave

#endif
