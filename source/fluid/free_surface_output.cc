#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>
#include <filesystem>
#include <slidewave/core/input_error.h>
#include <slidewave/fluid/free_surface_diagnostics.h>
#include <slidewave/fluid/free_surface_output.h>
#include <slidewave/io/particle_output.h>

namespace slidewave
{
  namespace fluid
  {
    namespace
    {
      bool
      is_writer()
      {
        return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }
    } // namespace



    FreeSurfaceOutput::FreeSurfaceOutput(std::string output_directory, std::vector<double> gauges)
      : directory(std::move(output_directory))
      , gauge_positions(std::move(gauges))
    {
    }



    void
    FreeSurfaceOutput::write(const FreeSurfaceSolver &solver,
                             const bool               surface,
                             const unsigned int       index,
                             const double             time)
    {
      using Interpretation = dealii::DataComponentInterpretation::DataComponentInterpretation;
      const auto &flow     = solver.flow_field();
      const auto &phase    = solver.phase_field();

      dealii::DataOut<2> data_out;
      data_out.attach_triangulation(solver.background_grid().triangulation());
      data_out.add_data_vector(flow.dof_handler(),
                               flow.values(0),
                               std::vector<std::string>{"velocity", "velocity", "pressure"},
                               std::vector<Interpretation>{
                                 dealii::DataComponentInterpretation::component_is_part_of_vector,
                                 dealii::DataComponentInterpretation::component_is_part_of_vector,
                                 dealii::DataComponentInterpretation::component_is_scalar});
      data_out.add_data_vector(phase.dof_handler(), phase.values(0), "phi");
      const auto           &tria = solver.background_grid().triangulation();
      dealii::Vector<float> subdomain(tria.n_active_cells());
      subdomain = static_cast<float>(tria.locally_owned_subdomain());
      data_out.add_data_vector(subdomain, "subdomain");
      data_out.set_flags(io::vtu_flags());
      data_out.build_patches();
      const std::string record
        = io::write_vtu(data_out, directory + "/free_surface/", "fields", index);
      files.emplace_back(time, "free_surface/" + record);
      if (is_writer())
        {
          std::ofstream pvd(directory + "/free_surface.pvd");
          dealii::DataOutBase::write_pvd_record(pvd, files);
          pvd.close();
          require_written(pvd, directory + "/free_surface.pvd");
        }

      if (!surface)
        return;
      const auto segments = diagnostics::surface_segments(phase);
      if (is_writer())
        {
          char name[64];
          std::snprintf(name, sizeof(name), "/free_surface/surface_%05u.csv", index);
          std::ofstream out(directory + name);
          out.precision(10);
          out << "# time = " << time << "\nx0,y0,x1,y1\n";
          for (const auto &s : segments)
            out << s[0] << ',' << s[1] << ',' << s[2] << ',' << s[3] << '\n';
          out.close();
          require_written(out, directory + name);
        }
    }



    void
    FreeSurfaceOutput::open_gauges(const bool append)
    {
      if (!is_writer() || gauge_positions.empty())
        return;
      gauges = std::make_unique<std::ofstream>(directory + "/" + gauge_file(),
                                               append ? std::ios::app : std::ios::out);
      require_written(*gauges, directory + "/" + gauge_file());
      gauges->precision(12);
      if (append)
        return;
      *gauges << "time";
      for (const double x : gauge_positions)
        *gauges << ",eta(x=" << x << ")";
      *gauges << '\n';
    }



    void
    FreeSurfaceOutput::record_gauges(const FreeSurfaceSolver &solver, const double time)
    {
      if (gauge_positions.empty())
        return;
      std::vector<double> eta;
      for (const double x : gauge_positions)
        eta.push_back(diagnostics::surface_elevation(solver.phase_field(), x));
      if (!gauges)
        return;
      *gauges << time;
      for (const double e : eta)
        *gauges << ',' << e;
      *gauges << '\n';
      gauges->flush();
      require_written(*gauges, directory + "/" + gauge_file());
    }
  } // namespace fluid
} // namespace slidewave
