#ifndef slidewave_depth_averaged_hazard_maps_h
#define slidewave_depth_averaged_hazard_maps_h

#include <cstdint>
#include <deal.II/base/parameter_handler.h>
#include <slidewave/depth_averaged/column_projection.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/depth_averaged/tiled_raster.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * Hazard maps of a depth-averaged run on a fixed raster of pixels centred on the nodes
     * of the finest grid ('Grid/Cell size', one pixel per node whatever the grid's
     * refinement; the thickness and the velocity projected straight from the columns,
     * ColumnProjection): peak flow thickness, peak flow velocity, peak dynamic pressure
     * rho v^2 and peak static pressure rho g h (AvaFrame's pft, pfv, ppr and r.avaflow's
     * hflow_max, vflow_max), the time of arrival (first time the thickness exceeds the
     * threshold) and the final deposit thickness. Written as GeoTIFF in the terrain's CRS
     * (when the terrain is a raster) with the outlines of the affected and deposit areas
     * (GeoJSON) and a summary of areas, runout (crown to toe) and travel angle.
     *
     * Rank 0 holds the maps, in tiles allocated where the flow goes (TiledRaster); each
     * record gathers there the sums of the pixels the columns cover now, nothing of the
     * grid. Memory: six doubles per pixel of the tiles the flow touched, on rank 0.
     */
    class HazardMaps
    {
    public:
      HazardMaps(const DepthAveragedParameters &parameters, double threshold);

      /** Declares the entries of the subsection "Hazard maps" (the handler inside it):
       *  whether and how the maps are written at the end. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Updates the peaks and arrival times from the columns of @p solver at @p time
       *  (collective: the covered pixels' sums are gathered on rank 0). */
      void
      record(const DepthAveragedSolver &solver, double time);

      /** The maps and the summary into @p directory (rank 0 writes);
       *  @p crs_wkt: the CRS of the files (empty: none). The runout and the travel angle
       *  go from the crown, the highest node reached at @p start_time (the release), to
       *  the toe, the affected node farthest from it; @p release_centre, the release's
       *  centre of mass, stands in for the crown if no node was reached at the start.
       *  Returns the summary's figures on one line (rank 0; "" elsewhere). */
      std::string
      write(const std::string         &directory,
            const DepthAveragedSolver &solver,
            const std::string         &crs_wkt,
            const dealii::Point<2>    &release_centre,
            double                     start_time) const;

      /** The maps so far into @p file, for a checkpoint (rank 0 writes): the numbers of
       *  nodes along x and y, then the tiles of the six values per pixel (peaks, arrival,
       *  last thickness; TiledRaster::save), in this machine's byte order. */
      void
      save(const std::string &file) const;

      /** What save() wrote (every rank reads and checks it, rank 0 keeps it): the maps of a resumed
       * run go on from those of the run that wrote the checkpoint. Throws InputError when the file
       *  cannot be read or is not of this grid. */
      void
      load(const std::string &file);

      /** The maps' names, in the order of the files. */
      static const std::vector<std::string> &
      names();

    private:
      const DepthAveragedParameters &prm;
      const double                   threshold;
      unsigned int                   nx, ny;
      ColumnProjection               projection;
      /** Per pixel (rank 0): peak thickness, peak speed, peak rho v^2, peak rho g h,
       *  arrival time (+inf: not reached), thickness at the last record. */
      TiledRaster maps;
      /** The pixels the last record covered (their last thickness is not zero). */
      std::vector<std::uint64_t> last_covered;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
