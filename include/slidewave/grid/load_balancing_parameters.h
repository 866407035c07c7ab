#ifndef slidewave_grid_load_balancing_parameters_h
#define slidewave_grid_load_balancing_parameters_h

#include <deal.II/base/parameter_handler.h>

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
      /** Declares the entries (the handler inside the "Load balancing" subsection). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm);

      unsigned int particle_weight     = 1000000;
      double       imbalance_threshold = 1.1;
      unsigned int interval            = 50;
    };
  } // namespace grid
} // namespace slidewave

#endif
