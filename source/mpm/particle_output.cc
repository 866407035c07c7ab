#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/particles/data_out.h>
#include <fstream>
#include <slidewave/mpm/particle_output.h>
#include <slidewave/mpm/particle_properties.h>

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
      using Interpretation = dealii::DataComponentInterpretation::DataComponentInterpretation;
      const auto              &names = property_names();
      std::vector<std::string> data_names(names.begin(), names.end());
      data_names[property::velocity_x] = "velocity";
      data_names[property::velocity_y] = "velocity";
      if (solver.has_point_forces())
        {
          data_names.emplace_back("point_force");
          data_names.emplace_back("point_force");
        }
      std::vector<Interpretation> interpretation(
        data_names.size(), dealii::DataComponentInterpretation::component_is_scalar);
      for (unsigned int i = 0; i < data_names.size(); ++i)
        if (data_names[i] == "velocity" || data_names[i] == "point_force")
          interpretation[i] = dealii::DataComponentInterpretation::component_is_part_of_vector;

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
