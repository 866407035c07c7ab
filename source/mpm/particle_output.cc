#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/particles/data_out.h>
#include <fstream>
#include <slidewave/mpm/particle_output.h>

namespace slidewave
{
  namespace mpm
  {
    ParticleOutput::ParticleOutput(std::string output_directory)
      : directory(std::move(output_directory))
    {
    }



    void
    ParticleOutput::write(const MaterialPointSolver &solver,
                          const unsigned int         index,
                          const double               time)
    {
      // Every property by the name its model's layout gives it, the components of a
      // vector (velocity, point force) under the vector's name.
      const auto &layout         = solver.property_layout();
      const auto  data_names     = layout.output_names();
      const auto  interpretation = layout.output_interpretation();

      dealii::Particles::DataOut<2> data_out;
      data_out.set_flags(vtu_flags());
      data_out.build_patches(solver.particles(), data_names, interpretation);
      const std::string record = data_out.write_vtu_with_pvtu_record(
        directory + "/particles/", "particles", index, MPI_COMM_WORLD, 5);
      files.emplace_back(time, "particles/" + record);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::ofstream pvd(directory + "/particles.pvd");
          dealii::DataOutBase::write_pvd_record(pvd, files);
        }
    }
  } // namespace mpm
} // namespace slidewave
