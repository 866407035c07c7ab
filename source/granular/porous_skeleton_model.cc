#include <deal.II/base/mpi.h>
#include <limits>
#include <slidewave/engine/particle_engine.templates.h>
#include <slidewave/granular/porous_skeleton_model.h>
#include <slidewave/soil/particle_properties.h>

namespace slidewave
{
  namespace granular
  {
    PorousSkeletonModel::PorousSkeletonModel(const soil::MaterialPointParameters &soil_parameters,
                                             const GranularWaterParameters       &parameters,
                                             const double                         fluid_density,
                                             const double                         fluid_viscosity)
      : soil::SoilModel(soil_parameters, parameters.grain_density, parameters.suspension_porosity)
      , parameters(parameters)
      , grain_density(parameters.grain_density)
      , viscosity(fluid_viscosity)
      , law(fluid_density, fluid_viscosity, parameters.d50)
      , porous_layout(soil::SoilModel::layout())
      , speed_index(porous_layout.size())
    {
      if (parameters.forchheimer)
        porous_layout.add_scalar("relative_speed");
    }



    double
    PorousSkeletonModel::coupling_time_scale(const particles::PointCloud &cloud) const
    {
      double smallest = std::numeric_limits<double>::infinity();
      for (const auto &particle : cloud.particles())
        {
          const auto   p     = particle.get_properties();
          const double solid = p[soil::property::mass] / grain_density;
          const double n     = porosity(solid, p[soil::property::volume]);
          const double C     = drag_coefficient(n, parameters.forchheimer ? p[speed_index] : 0.);
          if (C > 0.)
            smallest = std::min(smallest, grain_density * (1. - n) * n * n / C);
        }
      return dealii::Utilities::MPI::min(smallest, MPI_COMM_WORLD);
    }
  } // namespace granular

  template class engine::TransferKernels<granular::PorousSkeletonModel>;
  template class engine::ParticleEngine<granular::PorousSkeletonModel>;
} // namespace slidewave
