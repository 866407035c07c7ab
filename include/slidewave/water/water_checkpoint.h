#ifndef slidewave_water_water_checkpoint_h
#define slidewave_water_water_checkpoint_h

#include <slidewave/io/checkpoint.h>
#include <slidewave/water/shallow_water_1d.h>
#include <string>

namespace slidewave
{
  namespace water
  {
    /** The water's whole state under "<name>/": depth, discharge and bed per cell and the
     *  volume that entered through the ends. */
    void
    save_state(io::CheckpointRecord &record, const std::string &name, const ShallowWater1D &water);

    /** What save_state() put under "<name>/", bit for bit. */
    void
    restore_state(const io::CheckpointRecord &record,
                  const std::string          &name,
                  ShallowWater1D             &water);
  } // namespace water
} // namespace slidewave

#endif
