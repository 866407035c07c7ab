#ifndef slidewave_core_memory_estimate_h
#define slidewave_core_memory_estimate_h

#include <string>
#include <vector>

namespace slidewave
{
  namespace core
  {
    /**
     * The memory a scene needs, estimated before anything large is allocated from the counts
     * that drive it (grid cells, material points, water cells, finite-element unknowns,
     * raster pixels) times the bytes each of them was measured to cost, plus what every MPI
     * rank costs before the scene (libraries, MPI, Trilinos). The bytes per unit are the peak
     * resident set sizes (VmHWM) of small and larger runs of release builds, fitted to a
     * line; doc/stability.md gives the runs and the method.
     *
     * A scene whose estimate exceeds the available memory (available()) is refused before it
     * allocates (check()); `--validate` prints the estimate (describe()).
     */
    class MemoryEstimate
    {
    public:
      /** @name Measured bytes per unit (doc/stability.md, "Memory estimate") */
      /** @{ */
      /** Every rank before the scene: libraries, MPI, Trilinos, p4est. */
      static constexpr double bytes_per_rank = 200e6;
      /** A cell of the background grid of the material points (triangulation, p4est, Q1
       *  dofs, nodal vectors). */
      static constexpr double bytes_per_grid_cell = 1850.;
      /** A cell of the depth-averaged grid (its grid plus the terrain and map arrays). */
      static constexpr double bytes_per_depth_averaged_cell = 3150.;
      /** A material point (properties, particle handler, output). */
      static constexpr double bytes_per_point = 770.;
      /** A cell of the 1D water mesh. */
      static constexpr double bytes_per_water_cell = 190.;
      /** An unknown of the free surface flow (flow and phase field: vectors, matrices,
       *  preconditioners), besides its grid's cells. */
      static constexpr double bytes_per_dof = 1550.;
      /** A pixel of a raster read (mask, window, elevation grid). */
      static constexpr double bytes_per_pixel = 24.;
      /** @} */

      /**
       * Adds @p count items (@p what, e.g. "grid cells") of @p bytes_each bytes, their number
       * set by the parameter @p parameter (its full path) with the value @p value.
       */
      void
      add(const std::string &what,
          double             count,
          double             bytes_each,
          const std::string &parameter,
          const std::string &value);

      /** The estimate [bytes]: the items plus bytes_per_rank for each rank. */
      double
      bytes() const;

      /** One line: the estimate and the counts that drive it. */
      std::string
      describe() const;

      /**
       * Throws an InputError naming the largest item's parameter when bytes() exceeds
       * available(): the estimate, the counts, the memory available and what to change.
       * Collective (available() is).
       */
      void
      check() const;

      /**
       * The memory available to the run [bytes]: MemAvailable of /proc/meminfo, summed
       * over the nodes of MPI_COMM_WORLD (read by one rank of each node); the environment
       * variable SLIDEWAVE_AVAILABLE_MEMORY (bytes) replaces it on every node (the test
       * suite sets it, so that messages do not depend on the machine; a user may set it to
       * leave room for others). +infinity when neither can be read. Collective when MPI
       * is initialized.
       */
      static double
      available();

      /** Where available() comes from, for messages. */
      static std::string
      available_source();

      /**
       * Refuses a raster of @p width x @p height pixels (as its header declares them, before
       * a pixel is read) whose reading would need more than this node's available memory:
       * an InputError naming @p parameter and @p file. Not collective.
       */
      static void
      check_raster(const std::string &parameter,
                   const std::string &file,
                   double             width,
                   double             height);

      /** @p bytes in the unit that suits them ("1.8 GB", "650 MB"). */
      static std::string
      format_bytes(double bytes);

    private:
      struct Item
      {
        std::string what;
        double      count, bytes_each;
        std::string parameter, value;
      };
      std::vector<Item> items;
    };
  } // namespace core
} // namespace slidewave

#endif
