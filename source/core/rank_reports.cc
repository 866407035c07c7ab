#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <slidewave/core/rank_reports.h>

namespace slidewave
{
  namespace rank_reports
  {
    std::string
    first_nonempty(const std::string &local)
    {
      const unsigned int my_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const unsigned int first   = dealii::Utilities::MPI::min(
        local.empty() ? dealii::numbers::invalid_unsigned_int : my_rank, MPI_COMM_WORLD);
      if (first == dealii::numbers::invalid_unsigned_int)
        return "";
      return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, local, first);
    }



    std::string
    of_largest(const double local_value, const std::string &local)
    {
      const unsigned int my_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const double       global  = dealii::Utilities::MPI::max(local_value, MPI_COMM_WORLD);
      const unsigned int owner   = dealii::Utilities::MPI::min(
        local_value == global ? my_rank : dealii::numbers::invalid_unsigned_int, MPI_COMM_WORLD);
      return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, local, owner);
    }
  } // namespace rank_reports
} // namespace slidewave
