#include <slidewave/water/water_checkpoint.h>

namespace slidewave
{
  namespace water
  {
    void
    save_state(io::CheckpointRecord &record, const std::string &name, const ShallowWater1D &water)
    {
      record.put(name + "/depth", water.depth());
      record.put(name + "/discharge", water.discharge());
      record.put(name + "/bed", water.bed());
      record.put(name + "/boundary_inflow", water.net_boundary_inflow());
    }



    void
    restore_state(const io::CheckpointRecord &record,
                  const std::string          &name,
                  ShallowWater1D             &water)
    {
      water.restore(record.get_vector(name + "/depth"),
                    record.get_vector(name + "/discharge"),
                    record.get_vector(name + "/bed"),
                    record.get(name + "/boundary_inflow"));
    }
  } // namespace water
} // namespace slidewave
