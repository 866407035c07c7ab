#ifndef slidewave_io_particle_output_h
#define slidewave_io_particle_output_h

#include <deal.II/base/data_out_base.h>
#include <slidewave/mpm/material_point_solver.h>
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
     * The material points as a ParaView time series: OUTPUT/particles/particles_NNNNN.pvtu
     * (every property by the name of the model's PropertyLayout, vectors as vectors) and the
     * OUTPUT/particles.pvd record that lists them (collective).
     */
    class ParticleOutput
    {
    public:
      explicit ParticleOutput(std::string output_directory);

      void
      write(const mpm::MaterialPointSolver &solver, unsigned int index, double time);

      /** (time, file) of every record so far (saved and restored by checkpoints). */
      std::vector<std::pair<double, std::string>> files;

    private:
      std::string directory;
    };



    /**
     * The background grid's nodal state as a ParaView time series (`Output grid = true`):
     * OUTPUT/grid/grid_NNNNN.pvtu (nodal mass and velocity, the owning rank per cell) and
     * the OUTPUT/grid.pvd record (collective).
     */
    class GridOutput
    {
    public:
      explicit GridOutput(std::string output_directory);

      void
      write(const mpm::MaterialPointSolver &solver, unsigned int index, double time);

      /** (time, file) of every record so far (saved and restored by checkpoints). */
      std::vector<std::pair<double, std::string>> files;

    private:
      std::string directory;
    };
  } // namespace io
} // namespace slidewave

#endif
