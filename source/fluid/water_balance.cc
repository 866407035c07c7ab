#include <algorithm>
#include <cmath>
#include <cstdio>
#include <slidewave/core/input_error.h>
#include <slidewave/fluid/water_balance.h>

namespace slidewave
{
  namespace fluid
  {
    WaterBalance::WaterBalance(const FreeSurfaceParameters &parameters)
      : parameters(parameters)
    {
    }



    void
    WaterBalance::start(const double volume)
    {
      initial = volume;
      largest = 0.;
    }



    double
    WaterBalance::reference_volume() const
    {
      // An empty tank filled through an inflow side: its area.
      return initial > 0. ? initial :
                            (parameters.upper_right[0] - parameters.lower_left[0])
                              * (parameters.upper_right[1] - parameters.lower_left[1]);
    }



    double
    WaterBalance::drift(const double volume, const double outflow) const
    {
      // What is there, plus what left, minus what was there.
      return (volume + outflow - initial) / reference_volume();
    }



    void
    WaterBalance::check(const std::string &where, const double volume, const double outflow)
    {
      const double magnitude = std::abs(drift(volume, outflow));
      if (parameters.max_volume_drift > 0. && magnitude > parameters.max_volume_drift)
        throw RunFailure(where + "the water volume drifted by " + to_string(100. * magnitude)
                         + " % of " + to_string(reference_volume())
                         + " m^2 from its initial value and what the sides let in and out, "
                           "beyond 'Free surface flow/Guards/Maximum volume drift' = "
                         + to_string(100. * parameters.max_volume_drift) + " %");
      largest = std::max(largest, magnitude);
    }



    void
    WaterBalance::print_summary(const double outflow) const
    {
      std::printf("Water volume: largest drift %.3e of the initial %.6g m^2\n", largest, initial);
      if (std::abs(outflow) > 1e-6 * reference_volume())
        std::printf("Water through the sides: %.6g m^2 out (negative: in)\n", outflow);
    }



    void
    WaterBalance::save(io::CheckpointRecord &record) const
    {
      record.put("fluid/initial_volume", initial);
      record.put("fluid/max_drift", largest);
    }



    void
    WaterBalance::load(const io::CheckpointRecord &record)
    {
      initial = record.get("fluid/initial_volume");
      largest = record.get("fluid/max_drift");
    }
  } // namespace fluid
} // namespace slidewave
