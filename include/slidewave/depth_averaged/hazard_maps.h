#ifndef slidewave_depth_averaged_hazard_maps_h
#define slidewave_depth_averaged_hazard_maps_h

#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * Hazard maps of a depth-averaged run on the nodes of its grid (uniform cells, one
     * pixel per node; the thickness is the columns' volume on the node over its area, the
     * velocity the columns' mass-weighted mean at the node, DepthAveragedSolver::nodal_state): peak
     * flow thickness, peak flow velocity, peak dynamic pressure rho v^2 and peak static pressure
     * rho g h (AvaFrame's pft, pfv, ppr and r.avaflow's hflow_max, vflow_max), the time of arrival
     * (first time the thickness exceeds the threshold) and the final deposit thickness. Written as
     * GeoTIFF in the terrain's CRS (when the terrain is a raster) with the outlines of the
     * affected and deposit areas (GeoJSON) and a summary of areas, runout (crown to toe) and
     * travel angle.
     *
     * Each rank updates the nodes it owns into arrays over all nodes of the grid (so the
     * maps survive repartitioning); write() combines them (max, min, sum) and rank 0
     * writes the files. Memory: six doubles per node of the grid on every rank.
     */
    class HazardMaps
    {
    public:
      HazardMaps(const DepthAveragedParameters &parameters, double threshold);

      /** Updates the peaks and arrival times from the solver's state at @p time
       *  (collective: the nodal depth is an exchange). */
      void
      record(const DepthAveragedSolver &solver, double time);

      /** The maps and the summary into @p directory (collective; rank 0 writes);
       *  @p crs_wkt: the CRS of the files (empty: none). The runout and the travel angle
       *  go from the crown, the highest node reached at @p start_time (the release), to
       *  the toe, the affected node farthest from it; @p release_centre, the release's
       *  centre of mass, stands in for the crown if no node was reached at the start. */
      void
      write(const std::string         &directory,
            const DepthAveragedSolver &solver,
            const std::string         &crs_wkt,
            const dealii::Point<2>    &release_centre,
            double                     start_time) const;

      /** The maps so far into @p file, for a checkpoint (collective: combined over the
       *  ranks as write() does; rank 0 writes): the numbers of nodes along x and y, then
       *  the six arrays of doubles (peaks, arrival, last thickness), in this machine's byte
       *  order. */
      void
      save(const std::string &file) const;

      /** What save() wrote (collective, every rank reads): the maps of a resumed run go on
       *  from those of the run that wrote the checkpoint. Throws InputError when the file
       *  cannot be read or is not of this grid. */
      void
      load(const std::string &file);

      /** The maps' names, in the order of the files. */
      static const std::vector<std::string> &
      names();

    private:
      /** The six arrays combined over the ranks (max of the peaks, min of the arrival,
       *  sum of the last thickness; collective), in the order of names(). */
      std::vector<std::vector<double>>
      combined() const;

      unsigned int
      node_index(const dealii::Point<2> &x) const;

      const DepthAveragedParameters &prm;
      const double                   threshold;
      unsigned int                   nx, ny;
      /** Per node: peak thickness, peak speed, peak rho v^2, peak rho g h, arrival time
       *  (+inf: not reached), final thickness (of the last record). */
      std::vector<double> peak_depth, peak_speed, peak_dynamic, peak_static, arrival, last_depth;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
