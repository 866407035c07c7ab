#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <mpi.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/memory_estimate.h>
#include <sstream>

namespace slidewave
{
  namespace core
  {
    namespace
    {
      /** SLIDEWAVE_AVAILABLE_MEMORY [bytes], or 0 when unset or not a positive number. */
      double
      memory_from_environment()
      {
        const char *text = std::getenv("SLIDEWAVE_AVAILABLE_MEMORY");
        if (text == nullptr)
          return 0.;
        char        *end   = nullptr;
        const double bytes = std::strtod(text, &end);
        return (end != text && bytes > 0.) ? bytes : 0.;
      }

      /** This node's available memory [bytes]: the environment's, else MemAvailable. */
      double
      node_available()
      {
        if (const double bytes = memory_from_environment(); bytes > 0.)
          return bytes;
        std::ifstream meminfo("/proc/meminfo");
        std::string   key, unit;
        double        value = 0.;
        while (meminfo >> key >> value >> unit)
          if (key == "MemAvailable:")
            return value * 1024.;
        return std::numeric_limits<double>::infinity();
      }

      bool
      mpi_is_running()
      {
        int initialized = 0, finalized = 0;
        MPI_Initialized(&initialized);
        MPI_Finalized(&finalized);
        return initialized != 0 && finalized == 0;
      }

      unsigned int
      n_ranks()
      {
        int size = 1;
        if (mpi_is_running())
          MPI_Comm_size(MPI_COMM_WORLD, &size);
        return size;
      }

      std::string
      count_text(const double count)
      {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), count < 1e6 ? "%.0f" : "%.3g", count);
        return buffer;
      }
    } // namespace



    void
    MemoryEstimate::add(const std::string &what,
                        const double       count,
                        const double       bytes_each,
                        const std::string &parameter,
                        const std::string &value)
    {
      if (count > 0.)
        items.push_back({what, count, bytes_each, parameter, value});
    }



    double
    MemoryEstimate::bytes() const
    {
      double total = bytes_per_rank * n_ranks();
      for (const auto &item : items)
        total += item.count * item.bytes_each;
      return total;
    }



    std::string
    MemoryEstimate::format_bytes(const double bytes)
    {
      char buffer[32];
      if (bytes >= 1e12)
        std::snprintf(buffer, sizeof(buffer), "%.3g TB", bytes / 1e12);
      else if (bytes >= 1e9)
        std::snprintf(buffer, sizeof(buffer), "%.3g GB", bytes / 1e9);
      else
        std::snprintf(buffer, sizeof(buffer), "%.3g MB", bytes / 1e6);
      return buffer;
    }



    std::string
    MemoryEstimate::describe() const
    {
      std::ostringstream text;
      text << "an estimated " << format_bytes(bytes()) << " (";
      for (const auto &item : items)
        text << count_text(item.count) << ' ' << item.what << " x " << item.bytes_each << " B, ";
      const unsigned int ranks = n_ranks();
      text << ranks << (ranks == 1 ? " rank" : " ranks") << " x " << format_bytes(bytes_per_rank)
           << ")";
      return text.str();
    }



    double
    MemoryEstimate::available()
    {
      if (!mpi_is_running())
        return node_available();
      // One rank of each node reads that node's memory; the nodes' memory adds up.
      MPI_Comm node;
      MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      int node_rank = 0;
      MPI_Comm_rank(node, &node_rank);
      MPI_Comm_free(&node);
      const double mine  = node_rank == 0 ? node_available() : 0.;
      double       total = 0.;
      MPI_Allreduce(&mine, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
      return total;
    }



    std::string
    MemoryEstimate::available_source()
    {
      return memory_from_environment() > 0. ? "SLIDEWAVE_AVAILABLE_MEMORY" :
                                              "MemAvailable in /proc/meminfo";
    }



    void
    MemoryEstimate::check() const
    {
      const double available_bytes = available();
      const double needed          = bytes();
      if (!(needed > available_bytes) || items.empty())
        return;
      const auto largest
        = std::max_element(items.begin(), items.end(), [](const Item &a, const Item &b) {
            return a.count * a.bytes_each < b.count * b.bytes_each;
          });
      throw InputError(largest->parameter,
                       largest->value,
                       "a scene that fits in the memory available: it needs " + describe() + " and "
                         + format_bytes(available_bytes) + " are available (" + available_source()
                         + "); make the grid coarser or smaller, use fewer points per cell, "
                           "or run on more nodes (the bytes per unit are in "
                           "doc/stability.md)");
    }



    void
    MemoryEstimate::check_raster(const std::string &parameter,
                                 const std::string &file,
                                 const double       width,
                                 const double       height)
    {
      const double needed          = width * height * bytes_per_pixel;
      const double available_bytes = node_available();
      if (!(needed > available_bytes))
        return;
      throw InputError(parameter,
                       file,
                       "a raster that fits in the memory available: it declares "
                         + count_text(width) + " x " + count_text(height) + " = "
                         + count_text(width * height) + " pixels, an estimated "
                         + format_bytes(needed) + " to read (" + to_string(bytes_per_pixel)
                         + " B per pixel), and " + format_bytes(available_bytes)
                         + " are available (" + available_source()
                         + "); crop it to the area of interest or resample it to larger "
                           "pixels (e.g. gdal_translate -projwin or -tr)");
    }
  } // namespace core
} // namespace slidewave
