#ifndef slidewave_fluid_free_surface_output_h
#define slidewave_fluid_free_surface_output_h

#include <fstream>
#include <memory>
#include <slidewave/fluid/free_surface_solver.h>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * What the free-surface flow writes into OUTPUT (collective calls):
     * - free_surface/fields_NNNNN.pvtu with velocity, pressure, phi, density and the
     *   owning rank on the grid, listed by free_surface.pvd;
     * - free_surface/surface_NNNNN.csv: the phi = 0.5 contour as segments x0,y0,x1,y1;
     * - free_surface/gauges.csv: time, then the surface elevation at every gauge, every
     *   step (the shallow water's gauge format: scripts/plot_water.py reads both);
     * - free_surface/pressure_probes.csv: time, then the pressure at every probe, every
     *   step.
     */
    class FreeSurfaceOutput
    {
    public:
      FreeSurfaceOutput(std::string                   output_directory,
                        std::vector<double>           gauges,
                        std::vector<dealii::Point<2>> pressure_probes = {});

      /** Fields and surface of output number @p index at @p time. */
      void
      write(const FreeSurfaceSolver &solver, bool surface, unsigned int index, double time);

      /** Opens the gauge and probe files (rank 0; with @p append it continues resumed
       *  ones). */
      void
      open_gauges(bool append);

      /** One gauge row and one probe row (collective: reduced over the ranks). */
      void
      record_gauges(const FreeSurfaceSolver &solver, double time);

      /** The last probe row, one line on stdout (rank 0; nothing without probes):
       *  "Pressure probes at t = ... s: p(x=.. y=..) = ... Pa, ...". */
      void
      print_probes() const;

      /** The gauge file relative to the output directory (a checkpoint keeps it). */
      static std::string
      gauge_file()
      {
        return "free_surface/gauges.csv";
      }

      /** The pressure probes' file relative to the output directory. */
      static std::string
      probe_file()
      {
        return "free_surface/pressure_probes.csv";
      }

      /** The files that grow every step (relative to the output directory): the gauges'
       *  and the probes' where there are any. A checkpoint keeps them. */
      std::vector<std::string>
      growing_files() const;

      /** The gauges' and probes' positions for a checkpoint's signature (empty without
       *  any): a resumed run continues their files, so it must have the same columns. */
      std::string
      signature() const;

      /** (time, file) of every field record so far (kept by checkpoints). */
      std::vector<std::pair<double, std::string>> files;

    private:
      std::string                    directory;
      std::vector<double>            gauge_positions;
      std::vector<dealii::Point<2>>  probe_points;
      std::unique_ptr<std::ofstream> gauges, probes;
      std::vector<std::string>       gauge_columns, probe_columns;
      double                         last_time = 0.;
      std::vector<double>            last_pressures;
    };
  } // namespace fluid
} // namespace slidewave

#endif
