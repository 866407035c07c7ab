#ifndef slidewave_io_particle_output_h
#define slidewave_io_particle_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/particles/particle_handler.h>
#include <slidewave/core/input_error.h>
#include <slidewave/particles/property_layout.h>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace io
  {
    /**
     * VTU flags of the material-point files (points and grid): zlib's fastest level. The
     * strongest level, deal.II's default, takes several times longer for files hardly
     * smaller (819,200 points: 11 s against 1.5 s per output, 24 MB either way).
     */
    inline dealii::DataOutBase::VtkFlags
    vtu_flags()
    {
      dealii::DataOutBase::VtkFlags flags;
      flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
      return flags;
    }

    /**
     * deal.II's write_vtu_with_pvtu_record() of @p data_out into @p folder (ending in '/'):
     * the files NAME_INDEX.* and their record, whose name it returns (collective). A write
     * deal.II reports as failed is an OutputFailure naming the files.
     */
    template <class DataOutType>
    std::string
    write_vtu(const DataOutType &data_out,
              const std::string &folder,
              const std::string &name,
              const unsigned int index)
    {
      try
        {
          return data_out.write_vtu_with_pvtu_record(folder, name, index, MPI_COMM_WORLD, 5);
        }
      catch (const dealii::ExceptionBase &)
        {
          throw OutputFailure(folder + name + "_" + dealii::Utilities::int_to_string(index, 5)
                                + ".*",
                              "deal.II could not write the VTU files");
        }
    }

    /**
     * The material points as a ParaView time series: OUTPUT/particles/particles_NNNNN.pvtu
     * (every property by the name of the model's PropertyLayout, vectors as vectors) and the
     * OUTPUT/particles.pvd record that lists them (collective).
     */
    class ParticleOutput
    {
    public:
      explicit ParticleOutput(std::string output_directory);

      void
      write(const dealii::Particles::ParticleHandler<2> &particles,
            const particles::PropertyLayout             &layout,
            unsigned int                                 index,
            double                                       time);

      /** (time, file) of every record so far (saved and restored by checkpoints). */
      std::vector<std::pair<double, std::string>> files;

    private:
      std::string directory;
    };



    /**
     * The background grid's nodal state as a ParaView time series (`Output grid = true`):
     * OUTPUT/grid/grid_NNNNN.pvtu (the nodal fields a scene gives, the owning rank per cell) and
     * the OUTPUT/grid.pvd record (collective).
     */
    class GridOutput
    {
    public:
      explicit GridOutput(std::string output_directory);

      /** A named nodal field on the grid (a ghosted vector of the scalar Q1 dofs). */
      using Field
        = std::pair<std::string, const dealii::LinearAlgebra::distributed::Vector<double> *>;

      /** Writes @p fields on the grid of @p dofs, and the owning rank per cell. */
      void
      write(const dealii::DoFHandler<2> &dofs,
            const std::vector<Field>    &fields,
            unsigned int                 index,
            double                       time);

      /** (time, file) of every record so far (saved and restored by checkpoints). */
      std::vector<std::pair<double, std::string>> files;

    private:
      std::string directory;
    };
  } // namespace io
} // namespace slidewave

#endif
