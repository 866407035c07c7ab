#ifndef slidewave_grid_load_balancing_parameters_h
#define slidewave_grid_load_balancing_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace slidewave
{
  namespace grid
  {
    /**
     * How the cells and their points are shared among the MPI ranks: the entries of a
     * "Load balancing" subsection (the weight of a point against a cell's 1000, the
     * imbalance that triggers a repartition, how often it is checked).
     */
    struct LoadBalancingParameters
    {
      /** The points' default weight, against a cell's 1000. */
      static constexpr unsigned int default_particle_weight = 1000000;

      /** Declares the entries (the handler inside the "Load balancing" subsection);
       *  @p particle_weight_note ends the help of 'Particle weight' (what a physics adds). */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &particle_weight_note = "");

      void
      parse_parameters(dealii::ParameterHandler &prm);

      unsigned int particle_weight     = default_particle_weight;
      double       imbalance_threshold = 1.1;
      unsigned int interval            = 50;
    };
  } // namespace grid
} // namespace slidewave

#endif
