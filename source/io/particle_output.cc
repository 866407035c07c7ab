#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/particles/data_out.h>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/io/particle_output.h>

namespace slidewave
{
  namespace io
  {
    ParticleOutput::ParticleOutput(std::string output_directory)
      : directory(std::move(output_directory))
    {
    }



    void
    ParticleOutput::write(const dealii::Particles::ParticleHandler<2> &particles,
                          const particles::PropertyLayout             &layout,
                          const unsigned int                           index,
                          const double                                 time)
    {
      // Every property by the name its model's layout gives it, the components of a
      // vector (velocity, point force) under the vector's name.
      const auto data_names     = layout.output_names();
      const auto interpretation = layout.output_interpretation();

      dealii::Particles::DataOut<2> data_out;
      data_out.set_flags(vtu_flags());
      data_out.build_patches(particles, data_names, interpretation);
      const std::string record = write_vtu(data_out, directory + "/particles/", "particles", index);
      files.emplace_back(time, "particles/" + record);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::ofstream pvd(directory + "/particles.pvd");
          dealii::DataOutBase::write_pvd_record(pvd, files);
          pvd.close();
          require_written(pvd, directory + "/particles.pvd");
        }
    }


    GridOutput::GridOutput(std::string output_directory)
      : directory(std::move(output_directory))
    {
    }



    void
    GridOutput::write(const dealii::DoFHandler<2> &dofs,
                      const std::vector<Field>    &fields,
                      const unsigned int           index,
                      const double                 time)
    {
      dealii::DataOut<2> data_out;
      data_out.attach_dof_handler(dofs);
      for (const auto &[name, vector] : fields)
        data_out.add_data_vector(*vector, name);
      const auto           &tria = dofs.get_triangulation();
      dealii::Vector<float> subdomain(tria.n_active_cells());
      subdomain = static_cast<float>(tria.locally_owned_subdomain());
      data_out.add_data_vector(subdomain, "subdomain");
      data_out.set_flags(vtu_flags());
      data_out.build_patches();
      const std::string record = write_vtu(data_out, directory + "/grid/", "grid", index);
      files.emplace_back(time, "grid/" + record);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::ofstream pvd(directory + "/grid.pvd");
          dealii::DataOutBase::write_pvd_record(pvd, files);
          pvd.close();
          require_written(pvd, directory + "/grid.pvd");
        }
    }
  } // namespace io
} // namespace slidewave
