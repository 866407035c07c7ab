#include <slidewave/grid/load_balancing_parameters.h>
#include <string>

namespace slidewave
{
  namespace grid
  {
    void
    LoadBalancingParameters::declare_parameters(dealii::ParameterHandler &prm,
                                                const std::string        &particle_weight_note)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Particle weight",
                        std::to_string(default_particle_weight),
                        Integer(0),
                        "Cost of a material point relative to a cell's 1000 when the grid "
                        "is partitioned among MPI ranks (the work of a rank is 1000 per "
                        "cell plus this per point; a cell's weight is capped at 2^31 - 1, "
                        "p4est's limit). A step's grid work is over the nodes the points "
                        "talk to, so an empty cell costs next to nothing: the default makes "
                        "1000 empty cells weigh as much as a point (doc/mpm.md, "
                        "Throughput)."
                          + particle_weight_note);
      prm.declare_entry("Imbalance threshold",
                        "1.1",
                        Double(0.),
                        "Repartition when the most loaded rank has more than this times "
                        "the mean work (0: never, except when an adaptive grid changes).");
      prm.declare_entry("Interval", "50", Integer(1), "Steps between checks of the imbalance.");
    }



    void
    LoadBalancingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      particle_weight     = prm.get_integer("Particle weight");
      imbalance_threshold = prm.get_double("Imbalance threshold");
      interval            = prm.get_integer("Interval");
    }
  } // namespace grid
} // namespace slidewave
