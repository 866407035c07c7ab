#ifndef slidewave_core_step_timeline_h
#define slidewave_core_step_timeline_h

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace slidewave
{
  namespace core
  {
    /**
     * Per step and per rank, the wall time of each part of a material-point step, with the
     * exchanges between ranks (where a rank waits for a slower one) apart from the rank's
     * own work ('Material points/Step timeline'). The timer summary gives sums over the
     * run; this shows how the ranks' times of a part differ from step to step. Meant for
     * profiling runs: it keeps a row of a few doubles per step.
     *
     * Usage: begin_step() when a step starts, then lap(part) at the end of each part: the
     * wall time since the previous lap (or the start of the step) is added to that part.
     */
    class StepTimeline
    {
    public:
      enum Part : unsigned int
      {
        grid_changes,         ///< adaptation or repartitioning, when due
        scatter,              ///< particles to grid, up to the exchange
        exchange_sums,        ///< nodal sums of the ghost nodes to their owners
        grid_update,          ///< nodal velocities, boundary conditions
        exchange_velocities,  ///< nodal velocities from the owners to the ghost nodes
        gather,               ///< grid to particles (with the stresses under USL)
        musl_remap,           ///< MUSL: re-map and stress update (with its own exchanges)
        relocation,           ///< points into their new cells
        relocation_reduction, ///< the ranks agree whether the patch relocation suffices
        full_sort,            ///< deal.II's sort, when due or needed
        n_parts
      };

      /** Column names of the CSV, in the order of Part. */
      static const std::array<const char *, n_parts> &
      part_names();

      void
      begin_step(unsigned int step);

      void
      lap(Part part);

      /** Rows recorded on this rank. */
      std::size_t
      n_steps() const
      {
        return rows.size();
      }

      /** What write() wrote (on rank 0; zeros elsewhere). */
      struct Written
      {
        std::size_t rows = 0;
        /** Rows whose times are all finite and non-negative, with some time in the scatter
         * and in the gather (every step has both). */
        std::size_t complete_rows = 0;
      };

      /**
       * Collective: writes every rank's rows to @p filename on rank 0 (columns step, rank,
       * then the parts in seconds).
       */
      Written
      write(const std::string &filename) const;

    private:
      struct Row
      {
        unsigned int                step = 0;
        std::array<double, n_parts> seconds{};
      };
      std::vector<Row> rows;
      double           last = 0.;
    };
  } // namespace core
} // namespace slidewave

#endif
