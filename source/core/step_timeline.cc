#include <cmath>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <mpi.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/step_timeline.h>
#include <stdexcept>

namespace slidewave
{
  namespace core
  {
    const std::array<const char *, StepTimeline::n_parts> &
    StepTimeline::part_names()
    {
      static const std::array<const char *, n_parts> names{{"grid_changes",
                                                            "scatter",
                                                            "exchange_sums",
                                                            "grid_update",
                                                            "exchange_velocities",
                                                            "gather",
                                                            "musl_remap",
                                                            "relocation",
                                                            "relocation_reduction",
                                                            "full_sort"}};
      return names;
    }



    void
    StepTimeline::begin_step(const unsigned int step)
    {
      rows.emplace_back();
      rows.back().step = step;
      last             = MPI_Wtime();
    }



    void
    StepTimeline::lap(const Part part)
    {
      const double now = MPI_Wtime();
      if (!rows.empty())
        rows.back().seconds[part] += now - last;
      last = now;
    }



    StepTimeline::Written
    StepTimeline::write(const std::string &filename) const
    {
      // One flat array per rank: step, then the parts, per row.
      constexpr unsigned int width = 1 + n_parts;
      std::vector<double>    local;
      local.reserve(rows.size() * width);
      for (const Row &row : rows)
        {
          local.push_back(row.step);
          local.insert(local.end(), row.seconds.begin(), row.seconds.end());
        }
      const auto all = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, local, 0);
      Written    written;
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return written;
      std::ofstream out(filename);
      require_written(out, filename);
      out << "step,rank";
      for (const char *name : part_names())
        out << ',' << name;
      out << '\n' << std::setprecision(6);
      for (unsigned int rank = 0; rank < all.size(); ++rank)
        for (std::size_t r = 0; r + width <= all[rank].size(); r += width)
          {
            const double *seconds = all[rank].data() + r + 1;
            bool          valid   = seconds[scatter] > 0. && seconds[gather] > 0.;
            out << static_cast<unsigned int>(all[rank][r]) << ',' << rank;
            for (unsigned int k = 0; k < n_parts; ++k)
              {
                out << ',' << seconds[k];
                valid = valid && std::isfinite(seconds[k]) && seconds[k] >= 0.;
              }
            out << '\n';
            ++written.rows;
            written.complete_rows += valid ? 1 : 0;
          }
      if (!out)
        throw std::runtime_error("cannot write the step timeline to " + filename);
      return written;
    }
  } // namespace core
} // namespace slidewave
