#include <algorithm>
#include <cmath>
#include <cpl_error.h>
#include <cstdint>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <gdal.h>
#include <gdal_alg.h>
#include <limits>
#include <ogr_api.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/hazard_maps.h>
#include <slidewave/terrain/elevation_grid.h>
#include <slidewave/terrain/gdal_diagnostics.h>
#include <slidewave/terrain/vector_polygons.h>
#include <utility>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      constexpr double no_data = -9999.;

      /** Throws an OutputFailure naming @p path when GDAL reported a failure since
       *  CPLErrorReset() (a dataset not created, a write or the flush at GDALClose failed),
       *  quoting what GDAL said. */
      void
      require_gdal_success(const std::string &path, const terrain::GdalDiagnostics &diagnostics)
      {
        if (CPLGetLastErrorType() >= CE_Failure)
          throw OutputFailure(
            path,
            "GDAL: " + (diagnostics.text().empty() ? std::string("failed") : diagnostics.text()));
      }

      /** Writes @p values (node (i, j) at [j * (nx + 1) + i], y growing) as a GeoTIFF of
       *  one pixel per node, rows from north to south. */
      void
      write_geotiff(const std::string         &path,
                    const std::vector<double> &values,
                    const unsigned int         nx,
                    const unsigned int         ny,
                    const double              *transform,
                    const std::string         &crs_wkt)
      {
        const int                      w = nx + 1, h = ny + 1;
        const terrain::GdalDiagnostics diagnostics;
        CPLErrorReset();
        GDALDatasetH data
          = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Float64, nullptr);
        if (data == nullptr)
          throw OutputFailure(path, "GDAL could not create it" + diagnostics.note());
        GDALSetGeoTransform(data, const_cast<double *>(transform));
        if (!crs_wkt.empty())
          GDALSetProjection(data, crs_wkt.c_str());
        std::vector<double> rows(values.size());
        for (int j = 0; j < h; ++j)
          std::copy(values.begin() + static_cast<std::size_t>(j) * w,
                    values.begin() + static_cast<std::size_t>(j + 1) * w,
                    rows.begin() + static_cast<std::size_t>(h - 1 - j) * w);
        GDALRasterBandH band = GDALGetRasterBand(data, 1);
        GDALSetRasterNoDataValue(band, no_data);
        const CPLErr written
          = GDALRasterIO(band, GF_Write, 0, 0, w, h, rows.data(), w, h, GDT_Float64, 0, 0);
        // The pixels reach the file at GDALClose (GDAL 3.6's returns nothing: its errors are
        // GDAL's last error).
        GDALClose(data);
        if (written != CE_None)
          throw OutputFailure(path, "GDAL could not write its pixels" + diagnostics.note());
        require_gdal_success(path, diagnostics);
      }

      /** The outline of the nodes where @p inside is true, as GeoJSON polygons (GDAL's
       *  polygonize on the node raster). */
      void
      write_outline(const std::string       &path,
                    const std::vector<char> &inside,
                    const unsigned int       nx,
                    const unsigned int       ny,
                    const double            *transform,
                    const std::string       &crs_wkt)
      {
        const int    w = nx + 1, h = ny + 1;
        GDALDatasetH mask = GDALCreate(GDALGetDriverByName("MEM"), "", w, h, 1, GDT_Byte, nullptr);
        GDALSetGeoTransform(mask, const_cast<double *>(transform));
        std::vector<unsigned char> rows(static_cast<std::size_t>(w) * h);
        for (int j = 0; j < h; ++j)
          for (int i = 0; i < w; ++i)
            rows[static_cast<std::size_t>(h - 1 - j) * w + i]
              = inside[static_cast<std::size_t>(j) * w + i] ? 1 : 0;
        GDALRasterBandH band = GDALGetRasterBand(mask, 1);
        if (GDALRasterIO(band, GF_Write, 0, 0, w, h, rows.data(), w, h, GDT_Byte, 0, 0) != CE_None)
          return;
        const terrain::GdalDiagnostics diagnostics;
        CPLErrorReset();
        GDALDatasetH vector
          = GDALCreate(GDALGetDriverByName("GeoJSON"), path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
        if (vector == nullptr)
          {
            GDALClose(mask);
            throw OutputFailure(path, "GDAL could not create it" + diagnostics.note());
          }
        OGRSpatialReferenceH crs
          = crs_wkt.empty() ? nullptr : OSRNewSpatialReference(crs_wkt.c_str());
        OGRLayerH     layer = GDALDatasetCreateLayer(vector, "outline", crs, wkbPolygon, nullptr);
        OGRFieldDefnH field = OGR_Fld_Create("value", OFTInteger);
        OGR_L_CreateField(layer, field, TRUE);
        OGR_Fld_Destroy(field);
        GDALPolygonize(band, band, layer, 0, nullptr, nullptr, nullptr);
        if (crs != nullptr)
          OSRDestroySpatialReference(crs);
        GDALClose(vector);
        GDALClose(mask);
        require_gdal_success(path, diagnostics);
      }



      /** The nodes the flow reached and the deposit's, their areas, and the runout from the
       *  crown to the toe with its elevation drop (what summary.csv reports). */
      struct Runout
      {
        std::vector<char> affected, deposit;
        double            affected_area, deposit_area, runout, drop;
        dealii::Point<2>  crown, toe;
      };



      /** Measures the Runout on the reduced @p maps (thickness first, arrival fifth, deposit
       *  sixth) of the grid of @p nx x @p ny cells of size @p c from @p lower_left. */
      Runout
      measure_runout(const std::vector<std::vector<double>> &maps,
                     const terrain::ElevationGrid           &terrain,
                     const dealii::Point<2>                 &lower_left,
                     const double                            c,
                     const unsigned int                      nx,
                     const unsigned int                      ny,
                     const double                            threshold,
                     const dealii::Point<2>                 &release_centre,
                     const double                            start_time)
      {
        // Areas, and the runout as a landslide's travel angle is measured: from the crown
        // (the highest node of the release, reached at the start) to the toe (the affected
        // node farthest from it), H / L (the Fahrboeschung).
        std::vector<char> affected(maps[0].size()), deposit(maps[0].size());
        double            affected_area = 0., deposit_area = 0., runout = 0., drop = 0.;
        const auto        node = [&](const unsigned int i, const unsigned int j) {
          return dealii::Point<2>(lower_left[0] + i * c, lower_left[1] + j * c);
        };
        dealii::Point<2> crown = release_centre, toe = release_centre;
        double           crown_elevation = -std::numeric_limits<double>::infinity();
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            {
              const std::size_t k = static_cast<std::size_t>(j) * (nx + 1) + i;
              // A node's share of the area: a quarter of each cell around it.
              const double a
                = c * c * (i == 0 || i == nx ? 0.5 : 1.) * (j == 0 || j == ny ? 0.5 : 1.);
              affected[k] = maps[0][k] > threshold;
              deposit[k]  = maps[5][k] > threshold;
              affected_area += affected[k] ? a : 0.;
              deposit_area += deposit[k] ? a : 0.;
              if (affected[k] && maps[4][k] <= start_time
                  && terrain.value(node(i, j)) > crown_elevation)
                {
                  crown_elevation = terrain.value(node(i, j));
                  crown           = node(i, j);
                }
            }
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            if (affected[static_cast<std::size_t>(j) * (nx + 1) + i]
                && node(i, j).distance(crown) > runout)
              {
                runout = node(i, j).distance(crown);
                toe    = node(i, j);
              }
        drop = terrain.value(crown) - terrain.value(toe);
        return {std::move(affected),
                std::move(deposit),
                affected_area,
                deposit_area,
                runout,
                drop,
                crown,
                toe};
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
      write_summary(const std::string                      &directory,
                    const double                            threshold,
                    const Runout                           &r,
                    const std::vector<std::vector<double>> &maps)
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
          summary << "max_" << HazardMaps::names()[m] << ","
                  << *std::max_element(maps[m].begin(), maps[m].end()) << "," << units[m] << "\n";
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
    {
      const std::size_t n = static_cast<std::size_t>(nx + 1) * (ny + 1);
      peak_depth.assign(n, 0.);
      peak_speed.assign(n, 0.);
      peak_dynamic.assign(n, 0.);
      peak_static.assign(n, 0.);
      arrival.assign(n, std::numeric_limits<double>::infinity());
      last_depth.assign(n, 0.);
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



    unsigned int
    HazardMaps::node_index(const dealii::Point<2> &x) const
    {
      const long i = std::lround((x[0] - prm.lower_left[0]) / prm.cell_size);
      const long j = std::lround((x[1] - prm.lower_left[1]) / prm.cell_size);
      return static_cast<unsigned int>(j * (nx + 1) + i);
    }



    void
    HazardMaps::record(const DepthAveragedSolver &solver, const double time)
    {
      const auto   state = solver.nodal_state();
      const auto  &depth = state.depth;
      const auto  &vx = state.velocity[0], &vy = state.velocity[1];
      const double rho = prm.density, g = prm.gravity;
      std::fill(last_depth.begin(), last_depth.end(), 0.);
      for (const auto &cell : solver.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto i = cell->vertex_dof_index(v, 0);
              if (!depth.in_local_range(i))
                continue;
              const unsigned int k = node_index(cell->vertex(v));
              const double       h = depth[i];
              last_depth[k]        = h;
              if (!(h > threshold))
                continue;
              const double speed_squared = vx[i] * vx[i] + vy[i] * vy[i];
              peak_depth[k]              = std::max(peak_depth[k], h);
              peak_speed[k]              = std::max(peak_speed[k], std::sqrt(speed_squared));
              peak_dynamic[k]            = std::max(peak_dynamic[k], rho * speed_squared);
              peak_static[k]             = std::max(peak_static[k], rho * g * h);
              arrival[k]                 = std::min(arrival[k], time);
            }
    }



    std::vector<std::vector<double>>
    HazardMaps::combined() const
    {
      // Every node is owned by one rank: maxima, minima and sums over the ranks give the
      // maps.
      std::vector<std::vector<double>> maps{
        peak_depth, peak_speed, peak_dynamic, peak_static, arrival, last_depth};
      for (unsigned int m = 0; m < 4; ++m)
        dealii::Utilities::MPI::max(maps[m], MPI_COMM_WORLD, maps[m]);
      dealii::Utilities::MPI::min(maps[4], MPI_COMM_WORLD, maps[4]);
      dealii::Utilities::MPI::sum(maps[5], MPI_COMM_WORLD, maps[5]);
      return maps;
    }



    void
    HazardMaps::save(const std::string &file) const
    {
      const auto maps = combined();
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      std::ofstream      out(file, std::ios::binary);
      const std::int64_t nodes[2] = {nx + 1, ny + 1};
      out.write(reinterpret_cast<const char *>(nodes), sizeof(nodes));
      for (const auto &map : maps)
        out.write(reinterpret_cast<const char *>(map.data()),
                  static_cast<std::streamsize>(map.size() * sizeof(double)));
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
      for (auto *map :
           {&peak_depth, &peak_speed, &peak_dynamic, &peak_static, &arrival, &last_depth})
        in.read(reinterpret_cast<char *>(map->data()),
                static_cast<std::streamsize>(map->size() * sizeof(double)));
      if (!in || in.peek() != std::char_traits<char>::eof())
        throw InputError("Checkpoint/Resume",
                         "true",
                         "a readable checkpoint ('" + file + "' does not hold six maps of "
                           + std::to_string(nx + 1) + " x " + std::to_string(ny + 1) + " nodes)");
      // The last thickness is combined by a sum: one rank holds it.
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        std::fill(last_depth.begin(), last_depth.end(), 0.);
    }



    void
    HazardMaps::write(const std::string         &directory,
                      const DepthAveragedSolver &solver,
                      const std::string         &crs_wkt,
                      const dealii::Point<2>    &release_centre,
                      const double               start_time) const
    {
      std::vector<std::vector<double>> maps = combined();
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      for (auto &t : maps[4])
        if (!std::isfinite(t))
          t = no_data;
      for (auto &h : maps[5])
        if (!(h > threshold))
          h = 0.;

      // One pixel per node: the pixels' centres are the nodes.
      const double c = prm.cell_size;
      const double transform[6]
        = {prm.lower_left[0] - 0.5 * c, c, 0., prm.upper_right[1] + 0.5 * c, 0., -c};
      GDALAllRegister();
      for (unsigned int m = 0; m < maps.size(); ++m)
        write_geotiff(directory + "/" + names()[m] + ".tif", maps[m], nx, ny, transform, crs_wkt);

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
      write_outline(directory + "/affected_area.geojson", r.affected, nx, ny, transform, crs_wkt);
      write_outline(directory + "/deposit_area.geojson", r.deposit, nx, ny, transform, crs_wkt);
      write_release_area(directory, solver, crs_wkt);
      write_summary(directory, threshold, r, maps);
    }
  } // namespace depth_averaged
} // namespace slidewave
