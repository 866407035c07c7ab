#include <deal.II/base/utilities.h>
#include <exception>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/water/water_output.h>
#include <stdexcept>

namespace slidewave
{
  namespace water
  {
    void
    write_profile(const ShallowWater1D &water, const std::string &file_name, const double time)
    {
      std::ofstream out(file_name);
      out.precision(12);
      out << "# time = " << time << "\nx,h,u,hu,bed,eta\n";
      const WaterMesh &mesh = water.mesh();
      for (unsigned int i = 0; i < mesh.n_cells(); ++i)
        {
          const double h = water.depth()[i];
          const double b = water.bed()[i];
          out << mesh.center(i) << ',' << h << ',' << water.velocity(i) << ','
              << water.discharge()[i] << ',' << b << ',' << h + b << '\n';
        }
      out.close();
      require_written(out, file_name);
    }



    void
    GaugeRecorder::parse_positions(const std::string &parameter,
                                   const std::string &text,
                                   const double       left,
                                   const double       right)
    {
      gauge_positions.clear();
      for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
        {
          double x = 0.;
          try
            {
              std::size_t used = 0;
              x                = std::stod(item, &used);
              if (used != item.size())
                throw std::invalid_argument("");
            }
          catch (const std::exception &)
            {
              throw InputError(parameter, text, "a comma-separated list of positions");
            }
          if (x < left || x > right)
            throw InputError(parameter,
                             item,
                             "positions inside the water domain [" + to_string(left) + ", "
                               + to_string(right) + "]");
          gauge_positions.push_back(x);
        }
    }



    void
    GaugeRecorder::open(const std::string &file_name, const bool is_writer, const bool append)
    {
      if (!is_writer || gauge_positions.empty())
        return;
      file = std::make_unique<std::ofstream>(file_name, append ? std::ios::app : std::ios::out);
      name = file_name;
      require_written(*file, name);
      file->precision(12);
      if (append)
        return;
      *file << "time";
      for (const double x : gauge_positions)
        *file << ",eta(x=" << x << ")";
      *file << '\n';
    }



    void
    GaugeRecorder::record(const double time, const ShallowWater1D &water)
    {
      if (!file)
        return;
      *file << time;
      for (const double x : gauge_positions)
        *file << ',' << water.free_surface_at(x);
      *file << '\n';
      require_written(*file, name);
    }



    void
    GaugeRecorder::flush()
    {
      if (file)
        {
          file->flush();
          require_written(*file, name);
        }
    }
  } // namespace water
} // namespace slidewave
