#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <gdal.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/hazard_maps.h>
#include <slidewave/depth_averaged/map_files.h>
#include <slidewave/terrain/elevation_grid.h>
#include <slidewave/terrain/vector_polygons.h>
#include <utility>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      /** The values of a pixel of the maps, in the order of HazardMaps::names(). */
      enum MapValue : unsigned int
      {
        peak_depth,
        peak_speed,
        peak_dynamic,
        peak_static,
        arrival,
        last_depth,
        n_map_values
      };

      bool
      is_rank_zero()
      {
        return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }

      /** The raster of the maps: every pixel 0, the arrival time +inf (not reached). */
      TiledRaster
      empty_maps(const unsigned int nx, const unsigned int ny)
      {
        std::vector<double> defaults(n_map_values, 0.);
        defaults[arrival] = std::numeric_limits<double>::infinity();
        return TiledRaster(nx + 1, ny + 1, defaults);
      }



      /** The pixels the flow reached and the deposit's, their areas, and the runout from the
       *  crown to the toe with its elevation drop (what summary.csv reports). */
      struct Runout
      {
        std::vector<char> affected, deposit;
        double            affected_area = 0., deposit_area = 0., runout = 0., drop = 0.;
        dealii::Point<2>  crown, toe;
        /** The largest value of each peak map. */
        double largest[4] = {0., 0., 0., 0.};
      };



      /** Measures the Runout on the @p maps of the grid of @p nx x @p ny cells of size @p c
       *  from @p lower_left. */
      Runout
      measure_runout(const TiledRaster            &maps,
                     const terrain::ElevationGrid &terrain,
                     const dealii::Point<2>       &lower_left,
                     const double                  c,
                     const unsigned int            nx,
                     const unsigned int            ny,
                     const double                  threshold,
                     const dealii::Point<2>       &release_centre,
                     const double                  start_time)
      {
        // Areas, and the runout as a landslide's travel angle is measured: from the crown
        // (the highest pixel of the release, reached at the start) to the toe (the affected
        // pixel farthest from it), H / L (the Fahrboeschung). Pixels of tiles never written
        // were never reached.
        Runout r;
        r.affected.assign(static_cast<std::size_t>(nx + 1) * (ny + 1), 0);
        r.deposit.assign(r.affected.size(), 0);
        const auto node = [&](const unsigned int i, const unsigned int j) {
          return dealii::Point<2>(lower_left[0] + i * c, lower_left[1] + j * c);
        };
        r.crown = r.toe        = release_centre;
        double crown_elevation = -std::numeric_limits<double>::infinity();
        maps.for_each_allocated_pixel(
          [&](const unsigned int i, const unsigned int j, const double *v) {
            const std::size_t k = static_cast<std::size_t>(j) * (nx + 1) + i;
            // A pixel's area: the node's quarter of each cell around it.
            const double a
              = c * c * (i == 0 || i == nx ? 0.5 : 1.) * (j == 0 || j == ny ? 0.5 : 1.);
            r.affected[k] = v[peak_depth] > threshold;
            r.deposit[k]  = v[last_depth] > threshold;
            r.affected_area += r.affected[k] ? a : 0.;
            r.deposit_area += r.deposit[k] ? a : 0.;
            for (unsigned int m = 0; m < 4; ++m)
              r.largest[m] = std::max(r.largest[m], v[m]);
            if (r.affected[k] && v[arrival] <= start_time
                && terrain.value(node(i, j)) > crown_elevation)
              {
                crown_elevation = terrain.value(node(i, j));
                r.crown         = node(i, j);
              }
          });
        maps.for_each_allocated_pixel(
          [&](const unsigned int i, const unsigned int j, const double *) {
            if (r.affected[static_cast<std::size_t>(j) * (nx + 1) + i]
                && node(i, j).distance(r.crown) > r.runout)
              {
                r.runout = node(i, j).distance(r.crown);
                r.toe    = node(i, j);
              }
          });
        r.drop = terrain.value(r.crown) - terrain.value(r.toe);
        return r;
      }



      /** The release as the model took it (a vector file's polygons reprojected), for
       *  plots and GIS: release_area.geojson in @p directory. */
      void
      write_release_area(const std::string         &directory,
                         const DepthAveragedSolver &solver,
                         const std::string         &crs_wkt)
      {
        std::vector<terrain::VectorPolygon> release;
        for (const auto &area : solver.release_area().regions())
          release.push_back({area.polygon, area.holes});
        if (!terrain::write_polygons(directory + "/release_area.geojson", release, crs_wkt))
          std::fprintf(stderr,
                       "slidewave: could not write %s/release_area.geojson\n",
                       directory.c_str());
      }



      /** summary.csv in @p directory: the threshold, the areas, the runout and the largest
       *  value of each peak map. */
      void
      write_summary(const std::string &directory, const double threshold, const Runout &r)
      {
        std::ofstream summary(directory + "/summary.csv");
        summary.precision(10);
        summary << "quantity,value,unit\n"
                << "threshold," << threshold << ",m\n"
                << "affected_area," << r.affected_area << ",m^2\n"
                << "deposit_area," << r.deposit_area << ",m^2\n"
                << "crown_x," << r.crown[0] << ",m\n"
                << "crown_y," << r.crown[1] << ",m\n"
                << "toe_x," << r.toe[0] << ",m\n"
                << "toe_y," << r.toe[1] << ",m\n"
                << "runout," << r.runout << ",m\n"
                << "elevation_drop," << r.drop << ",m\n"
                << "travel_angle,"
                << (r.runout > 0. ? std::atan2(r.drop, r.runout) * 180. / M_PI : 0.)
                << ",degrees\n";
        const char *units[] = {"m", "m/s", "Pa", "Pa"};
        for (unsigned int m = 0; m < 4; ++m)
          summary << "max_" << HazardMaps::names()[m] << "," << r.largest[m] << "," << units[m]
                  << "\n";
        summary.close();
        require_written(summary, directory + "/summary.csv");
      }
    } // namespace



    HazardMaps::HazardMaps(const DepthAveragedParameters &parameters, const double threshold)
      : prm(parameters)
      , threshold(threshold)
      , nx(static_cast<unsigned int>(std::lround(
          (parameters.upper_right[0] - parameters.lower_left[0]) / parameters.cell_size)))
      , ny(static_cast<unsigned int>(std::lround(
          (parameters.upper_right[1] - parameters.lower_left[1]) / parameters.cell_size)))
      , projection(parameters.lower_left, parameters.cell_size, nx, ny)
      , maps(empty_maps(nx, ny))
    {
    }



    void
    HazardMaps::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Enable",
                        "false",
                        Bool(),
                        "Write hazard maps at the end of the run into OUTPUT/maps: GeoTIFFs "
                        "of one pixel per node of the grid of 'Cell size' (in the terrain "
                        "raster's CRS when the terrain is a raster; the thickness and "
                        "velocity projected from the columns' own areas, doc/terrain.md) "
                        "of the peak flow thickness, peak flow "
                        "velocity, peak dynamic pressure rho v^2, peak static pressure "
                        "rho g h, the time of arrival and the deposit thickness at the end; "
                        "the outlines of the affected and the deposit areas as GeoJSON; "
                        "summary.csv with their areas, the runout from the release's centre "
                        "of mass, the elevation drop and the travel angle.");
      prm.declare_entry("Thickness threshold",
                        "0.05",
                        Double(0.),
                        "A node is reached (affected, part of the deposit) where the flow "
                        "is thicker than this [m].");
      prm.declare_entry("Interval",
                        "5",
                        Integer(1),
                        "Steps between updates of the peaks and arrival times (and the "
                        "last step). Each update costs a fifth of a step or less (a pass "
                        "over the columns, the covered pixels gathered on rank 0): 1 for "
                        "the sharpest maps.");
    }



    const std::vector<std::string> &
    HazardMaps::names()
    {
      static const std::vector<std::string> list{"peak_flow_thickness",
                                                 "peak_flow_velocity",
                                                 "peak_pressure_dynamic",
                                                 "peak_pressure_static",
                                                 "arrival_time",
                                                 "deposit_thickness"};
      return list;
    }



    void
    HazardMaps::record(const DepthAveragedSolver &solver, const double time)
    {
      const auto &pixels = projection.project(solver.point_cloud());
      if (!is_rank_zero())
        return;
      const double rho = prm.density, g = prm.gravity;
      // The last thickness is the flow's now: zero where it was and has left.
      for (const std::uint64_t k : last_covered)
        maps.at(k % (nx + 1), k / (nx + 1))[last_depth] = 0.;
      last_covered.clear();
      for (const auto &pixel : pixels)
        {
          double      *v = maps.at(pixel.index % (nx + 1), pixel.index / (nx + 1));
          const double h = pixel.depth;
          v[last_depth]  = h;
          last_covered.push_back(pixel.index);
          if (!(h > threshold))
            continue;
          const double speed_squared
            = pixel.velocity_x * pixel.velocity_x + pixel.velocity_y * pixel.velocity_y;
          v[peak_depth]   = std::max(v[peak_depth], h);
          v[peak_speed]   = std::max(v[peak_speed], std::sqrt(speed_squared));
          v[peak_dynamic] = std::max(v[peak_dynamic], rho * speed_squared);
          v[peak_static]  = std::max(v[peak_static], rho * g * h);
          v[arrival]      = std::min(v[arrival], time);
        }
    }



    void
    HazardMaps::save(const std::string &file) const
    {
      if (!is_rank_zero())
        return;
      std::ofstream      out(file, std::ios::binary);
      const std::int64_t nodes[2] = {nx + 1, ny + 1};
      out.write(reinterpret_cast<const char *>(nodes), sizeof(nodes));
      maps.save(out);
      out.close();
      require_written(out, file);
    }



    void
    HazardMaps::load(const std::string &file)
    {
      std::ifstream in(file, std::ios::binary);
      std::int64_t  nodes[2] = {0, 0};
      in.read(reinterpret_cast<char *>(nodes), sizeof(nodes));
      if (!in || nodes[0] != nx + 1 || nodes[1] != ny + 1)
        throw InputError("Checkpoint/Resume",
                         "true",
                         "a readable checkpoint ('" + file + "' is not of " + std::to_string(nx + 1)
                           + " x " + std::to_string(ny + 1) + " nodes)");
      if (!maps.load(in) || in.peek() != std::char_traits<char>::eof())
        throw InputError("Checkpoint/Resume",
                         "true",
                         "a readable checkpoint ('" + file
                           + "' does not hold the tiles of six "
                             "maps of "
                           + std::to_string(nx + 1) + " x " + std::to_string(ny + 1) + " nodes)");
      // Rank 0 holds the maps.
      last_covered.clear();
      if (!is_rank_zero())
        maps = empty_maps(nx, ny);
      else
        maps.for_each_allocated_pixel(
          [&](const unsigned int i, const unsigned int j, const double *v) {
            if (v[last_depth] != 0.)
              last_covered.push_back(static_cast<std::uint64_t>(j) * (nx + 1) + i);
          });
    }



    std::string
    HazardMaps::write(const std::string         &directory,
                      const DepthAveragedSolver &solver,
                      const std::string         &crs_wkt,
                      const dealii::Point<2>    &release_centre,
                      const double               start_time) const
    {
      if (!is_rank_zero())
        return std::string();
      // One pixel per node: the pixels' centres are the nodes.
      const double c = prm.cell_size;
      const double transform[6]
        = {prm.lower_left[0] - 0.5 * c, c, 0., prm.upper_right[1] + 0.5 * c, 0., -c};
      GDALAllRegister();
      for (unsigned int m = 0; m < n_map_values; ++m)
        map_files::write_geotiff(
          directory + "/" + names()[m] + ".tif",
          [&](const unsigned int j, double *row) {
            maps.fill_row(m, j, row);
            for (unsigned int i = 0; i <= nx; ++i)
              if (m == arrival && !std::isfinite(row[i]))
                row[i] = map_files::no_data;
              else if (m == last_depth && !(row[i] > threshold))
                row[i] = 0.;
          },
          nx + 1,
          ny + 1,
          transform,
          crs_wkt);

      // The outlines and the release for GIS, the areas and the runout in the summary.
      const Runout r = measure_runout(maps,
                                      solver.model().terrain(),
                                      prm.lower_left,
                                      c,
                                      nx,
                                      ny,
                                      threshold,
                                      release_centre,
                                      start_time);
      map_files::write_outline(
        directory + "/affected_area.geojson", r.affected, nx + 1, ny + 1, transform, crs_wkt);
      map_files::write_outline(
        directory + "/deposit_area.geojson", r.deposit, nx + 1, ny + 1, transform, crs_wkt);
      write_release_area(directory, solver, crs_wkt);
      write_summary(directory, threshold, r);
      char line[400];
      std::snprintf(line,
                    sizeof(line),
                    "affected_area=%.8e deposit_area=%.8e runout=%.8e elevation_drop=%.8e "
                    "max_peak_flow_thickness=%.8e max_peak_flow_velocity=%.8e",
                    r.affected_area,
                    r.deposit_area,
                    r.runout,
                    r.drop,
                    r.largest[0],
                    r.largest[1]);
      return line;
    }
  } // namespace depth_averaged
} // namespace slidewave
