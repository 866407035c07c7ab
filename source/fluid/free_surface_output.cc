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
#include <sstream>

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



    FreeSurfaceOutput::FreeSurfaceOutput(std::string                   output_directory,
                                         std::vector<double>           gauges,
                                         std::vector<dealii::Point<2>> pressure_probes)
      : directory(std::move(output_directory))
      , gauge_positions(std::move(gauges))
      , probe_points(std::move(pressure_probes))
    {
      // The files' headers name every column by its position, with the files' 12 digits.
      const auto column = [](const std::string &name, const std::vector<double> &position) {
        std::ostringstream out;
        out.precision(12);
        out << name << "(x=" << position[0];
        if (position.size() > 1)
          out << " y=" << position[1];
        out << ')';
        return out.str();
      };
      for (const double x : gauge_positions)
        gauge_columns.push_back(column("eta", {x}));
      for (const auto &p : probe_points)
        probe_columns.push_back(column("p", {p[0], p[1]}));
    }



    std::string
    FreeSurfaceOutput::signature() const
    {
      std::ostringstream out;
      out.precision(12);
      if (!gauge_positions.empty())
        {
          out << "; gauges";
          for (const double x : gauge_positions)
            out << ' ' << x;
        }
      if (!probe_points.empty())
        {
          out << "; pressure probes";
          for (const auto &p : probe_points)
            out << " (" << p << ')';
        }
      return out.str();
    }



    std::vector<std::string>
    FreeSurfaceOutput::growing_files() const
    {
      std::vector<std::string> files;
      if (!gauge_positions.empty())
        files.push_back(gauge_file());
      if (!probe_points.empty())
        files.push_back(probe_file());
      return files;
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
      if (!is_writer())
        return;
      const auto open = [&](const std::string &name, const std::vector<std::string> &columns) {
        auto file = std::make_unique<std::ofstream>(directory + "/" + name,
                                                    append ? std::ios::app : std::ios::out);
        require_written(*file, directory + "/" + name);
        file->precision(12);
        if (!append)
          {
            *file << "time";
            for (const auto &column : columns)
              *file << ',' << column;
            *file << '\n';
          }
        return file;
      };
      if (!gauge_positions.empty())
        gauges = open(gauge_file(), gauge_columns);
      if (!probe_points.empty())
        probes = open(probe_file(), probe_columns);
    }



    void
    FreeSurfaceOutput::record_gauges(const FreeSurfaceSolver &solver, const double time)
    {
      std::vector<double> eta, p;
      for (const double x : gauge_positions)
        eta.push_back(diagnostics::surface_elevation(solver.phase_field(), x));
      for (const auto &point : probe_points)
        p.push_back(diagnostics::pressure_at(solver.flow_field(), point));
      const auto row
        = [&](std::ofstream *file, const std::vector<double> &values, const std::string &name) {
            if (file == nullptr || values.empty())
              return;
            *file << time;
            for (const double v : values)
              *file << ',' << v;
            *file << '\n';
            file->flush();
            require_written(*file, directory + "/" + name);
          };
      row(gauges.get(), eta, gauge_file());
      row(probes.get(), p, probe_file());
      last_time      = time;
      last_pressures = p;
    }



    void
    FreeSurfaceOutput::print_probes() const
    {
      if (!is_writer() || last_pressures.empty())
        return;
      std::printf("Pressure probes at t = %.6e s:", last_time);
      for (unsigned int k = 0; k < last_pressures.size(); ++k)
        std::printf("%s %s = %.6e Pa",
                    k == 0 ? "" : ",",
                    probe_columns[k].c_str(),
                    last_pressures[k]);
      std::printf("\n");
    }
  } // namespace fluid
} // namespace slidewave
