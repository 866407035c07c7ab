#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <slidewave/coupling/soil_water_interface.h>

namespace slidewave
{
  namespace coupling
  {
    namespace
    {
      /** The index of the property @p name in @p layout, or numbers::invalid_unsigned_int
       *  when the points do not carry it. */
      unsigned int
      index_if_any(const particles::PropertyLayout &layout, const std::string &name)
      {
        return layout.has(name) ? layout.index(name) : dealii::numbers::invalid_unsigned_int;
      }
    } // namespace



    SoilWaterInterface::SoilWaterInterface(std::vector<double>              column_interfaces,
                                           const water::WaterMesh          &water_mesh,
                                           std::vector<double>              terrain_columns,
                                           std::vector<double>              terrain_cells,
                                           const WaterConstants            &constants,
                                           const particles::PropertyLayout &soil_layout,
                                           const SoilSurface                surface_kind,
                                           const double                     grid_floor,
                                           const WaterPressure              water_pressure)
      : columns(std::move(column_interfaces))
      , terrain_at_columns(std::move(terrain_columns))
      , terrain_at_cells(std::move(terrain_cells))
      , water_constants(constants)
      // The properties by their names once here, by index in every step.
      , soil_property{soil_layout.index("volume"),
                      soil_layout.index("domain_half_x"),
                      soil_layout.index("domain_half_y"),
                      index_if_any(soil_layout, "point_force_x"),
                      index_if_any(soil_layout, "point_force_y")}
      , surface_definition(surface_kind)
      , floor(grid_floor)
      , pressure(water_pressure)
      , same_cells(columns == water_mesh.interfaces())
    {
      const unsigned int n_columns = columns.size() - 1;
      const unsigned int n_cells   = water_mesh.n_cells();
      // Uniform columns are found by division, others by bisection.
      uniform_width = (columns.back() - columns.front()) / n_columns;
      for (unsigned int c = 0; c < n_columns; ++c)
        if (std::abs(columns[c + 1] - columns[c] - uniform_width) > 1e-9 * uniform_width)
          uniform_width = 0.;
      for (unsigned int c = 0; c < n_columns; ++c)
        column_centers.push_back(0.5 * (columns[c] + columns[c + 1]));
      for (unsigned int i = 0; i < n_cells; ++i)
        cell_centers.push_back(water_mesh.center(i));

      // Which part of each water cell lies over which column.
      overlap_start.push_back(0);
      for (unsigned int i = 0; i < n_cells; ++i)
        {
          const double a = water_mesh.interfaces()[i], b = water_mesh.interfaces()[i + 1];
          for (unsigned int c = 0; c < n_columns; ++c)
            {
              const double overlap = std::min(b, columns[c + 1]) - std::max(a, columns[c]);
              if (overlap > 1e-12 * (b - a))
                {
                  overlap_column.push_back(c);
                  overlap_fraction.push_back(overlap / (b - a));
                }
            }
          overlap_start.push_back(overlap_column.size());
        }

      surface_height.assign(n_columns, -std::numeric_limits<double>::infinity());
      samples.resize(n_columns);
      coverage.resize(n_columns);
      if (surface_definition == SoilSurface::envelope)
        soil_height.resize(n_columns);
      bed_elevation.resize(n_cells);
      column_load_x.resize(n_columns);
      column_load_y.resize(n_columns);
      cell_load_x.resize(n_cells);
      cell_load_y.resize(n_cells);
      cell_thrust.resize(n_cells);
      cell_band_bottom.resize(n_cells);
      cell_band_level.resize(n_cells);
      cell_band_reference.resize(n_cells);
      column_thrust.resize(n_columns);
      band_bottom.resize(n_columns);
      band_level.resize(n_columns);
      band_reference.resize(n_columns);
      face_weights.resize(n_columns);
      envelope.resize(n_columns * samples_per_column);
      sample_count.resize(n_columns * samples_per_column);
      covered_samples.resize(n_columns);
      // No reference until set_initial_level: the full pressure acts on the boundary.
      reference_level.assign(n_cells, -std::numeric_limits<double>::infinity());
    }



    void
    SoilWaterInterface::set_initial_level(const water::ShallowWater1D &water)
    {
      // A cell dry at the start had no water pressure: its level is -infinity, and any
      // water that comes later loads the bed with its full pressure.
      constexpr double no_level = -std::numeric_limits<double>::infinity();
      const auto       wet
        = [&](const unsigned int i) { return water.depth()[i] > water_constants.dry_depth; };
      // Hydrostatic: one still level eta_s for all wet cells (a flat reference, so that the
      // buoyancy of the points below it is exactly the integral of its pressure over the
      // soil's boundary), the lowest free surface of the wet cells.
      double still_level = std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < water.n_cells(); ++i)
        if (wet(i))
          still_level = std::min(still_level, water.depth()[i] + water.bed()[i]);
      reference_level.resize(water.n_cells());
      for (unsigned int i = 0; i < water.n_cells(); ++i)
        reference_level[i] = !wet(i) ? no_level :
                             pressure == WaterPressure::hydrostatic ?
                                       still_level :
                                       water.depth()[i] + water.bed()[i];
      set_buoyant_level();
    }



    void
    SoilWaterInterface::set_buoyant_level()
    {
      // The pore water is taken in hydrostatic equilibrium with the still water: one flat
      // phreatic level eta_s under every column (also where the soil stands above the
      // water, or its top was dry at the start), so every point below eta_s is buoyant.
      buoyant_level = -std::numeric_limits<double>::infinity();
      for (const double level : reference_level)
        buoyant_level = std::max(buoyant_level, level);
    }



    void
    SoilWaterInterface::restore_initial_level(const std::vector<double> &level)
    {
      AssertThrow(level.size() == bed_elevation.size(),
                  dealii::ExcMessage("The initial water level of the checkpoint has "
                                     + std::to_string(level.size()) + " values for "
                                     + std::to_string(bed_elevation.size()) + " water cells."));
      reference_level = level;
      set_buoyant_level();
    }



    unsigned int
    SoilWaterInterface::column_of(const double x) const
    {
      if (uniform_width > 0.)
        return static_cast<unsigned int>(
          std::clamp(std::floor((x - columns.front()) / uniform_width),
                     0.,
                     static_cast<double>(columns.size() - 2)));
      const auto k = std::upper_bound(columns.begin(), columns.end(), x) - columns.begin();
      return static_cast<unsigned int>(
        std::clamp<long>(k - 1, 0, static_cast<long>(columns.size()) - 2));
    }



    template <typename Function>
    inline void
    SoilWaterInterface::for_each_column_of(const double x, const double l, const Function &f) const
    {
      // A point acts on every column its domain [x - l, x + l] overlaps, in proportion to
      // the overlap (a domain without width: the column it is in).
      if (!(l > 0.))
        {
          f(column_of(x), 1.);
          return;
        }
      for (unsigned int c = column_of(x - l); c + 1 < columns.size() && columns[c] < x + l; ++c)
        {
          const double overlap = std::min(x + l, columns[c + 1]) - std::max(x - l, columns[c]);
          if (overlap > 0.)
            f(c, overlap / (2. * l));
        }
    }



    template <typename Function>
    inline void
    SoilWaterInterface::for_each_sample_of(const double       x,
                                           const double       l,
                                           const unsigned int c,
                                           const Function    &f) const
    {
      // The samples (centres of samples_per_column equal parts) of column c under the
      // domain [x - l, x + l].
      const double w     = (columns[c + 1] - columns[c]) / samples_per_column;
      const int    first = std::max(0, static_cast<int>(std::ceil((x - l - columns[c]) / w - 0.5)));
      const int    last  = std::min(static_cast<int>(samples_per_column) - 1,
                                static_cast<int>(std::floor((x + l - columns[c]) / w - 0.5)));
      for (int k = first; k <= last; ++k)
        f(c * samples_per_column + k);
    }



    void
    SoilWaterInterface::update_surface(const dealii::Particles::ParticleHandler<2> &soil_points)
    {
      std::fill(surface_height.begin(),
                surface_height.end(),
                -std::numeric_limits<double>::infinity());
      std::fill(envelope.begin(), envelope.end(), -std::numeric_limits<double>::infinity());
      for (const auto &particle : soil_points)
        {
          const auto   x   = particle.get_location();
          const auto   p   = particle.get_properties();
          const double top = x[1] + p[soil_property.domain_half_y];
          const double l   = p[soil_property.domain_half_x];
          for_each_column_of(x[0], l, [&](const unsigned int c, const double) {
            surface_height[c] = std::max(surface_height[c], top);
            // The samples of the column under the point's domain.
            for_each_sample_of(x[0], l, c, [&](const unsigned int s) {
              envelope[s] = std::max(envelope[s], top);
            });
          });
        }
      dealii::Utilities::MPI::max(surface_height, MPI_COMM_WORLD, surface_height);
      dealii::Utilities::MPI::max(envelope, MPI_COMM_WORLD, envelope);
      if (surface_definition == SoilSurface::envelope)
        {
          // The mean of the envelope over the column, the floor where there is no soil.
          for (unsigned int c = 0; c < soil_height.size(); ++c)
            {
              double       sum     = 0.;
              unsigned int covered = 0;
              for (unsigned int k = 0; k < samples_per_column; ++k)
                {
                  const double e = envelope[c * samples_per_column + k];
                  sum += std::max(e, floor);
                  covered += e > -std::numeric_limits<double>::infinity();
                }
              soil_height[c] = sum / samples_per_column;
              coverage[c]    = static_cast<double>(covered) / samples_per_column;
            }
        }
      else
        for (unsigned int c = 0; c < coverage.size(); ++c)
          coverage[c] = surface_height[c] > -std::numeric_limits<double>::infinity() ? 1. : 0.;
    }



    const std::vector<double> &
    SoilWaterInterface::bed()
    {
      if (same_cells)
        for (unsigned int i = 0; i < bed_elevation.size(); ++i)
          bed_elevation[i] = std::max(soil_bed()[i], terrain_at_cells[i]);
      else
        {
          for (unsigned int c = 0; c < samples.size(); ++c)
            samples[c] = std::max(soil_bed()[c], terrain_at_columns[c]);
          reconstruction.reinit(column_centers, samples);
          for (unsigned int i = 0; i < bed_elevation.size(); ++i)
            {
              const double x   = cell_centers[i];
              bed_elevation[i] = x < columns.front() || x > columns.back() ?
                                   terrain_at_cells[i] :
                                   std::max(reconstruction.value(x), terrain_at_cells[i]);
            }
        }
      return bed_elevation;
    }



    double
    SoilWaterInterface::buoyancy(const Point &point) const
    {
      if (pressure != WaterPressure::hydrostatic)
        return 0.;
      const auto   p      = point.get_properties();
      const double l_y    = p[soil_property.domain_half_y];
      const double bottom = point.get_location()[1] - l_y;
      return water_constants.density * water_constants.gravity * p[soil_property.volume]
             * std::clamp((buoyant_level - bottom) / (2. * l_y), 0., 1.);
    }



    double
    SoilWaterInterface::thrust_of(const double level, const double bottom, const double top) const
    {
      const double below = std::max(level - bottom, 0.), above = std::max(level - top, 0.);
      return 0.5 * water_constants.density * water_constants.gravity
             * (below * below - above * above);
    }



    double
    SoilWaterInterface::face_weight(const Point &point, const unsigned int column) const
    {
      // The excess of the water's pressure head over the reference's at the point's height,
      // in the wet band of the face.
      const double y = point.get_location()[1];
      return column_thrust[column] != 0. && y >= band_bottom[column] ? std::abs(
               std::max(band_level[column] - y, 0.) - std::max(band_reference[column] - y, 0.)) :
                                                                       0.;
    }



    template <typename Function>
    inline void
    SoilWaterInterface::for_each_envelope_sample_of(const Point       &point,
                                                    const unsigned int c,
                                                    const Function    &f) const
    {
      // The surface where it is, not the column's highest point: a point of the
      // neighbouring column whose domain reaches into a lower column would otherwise take
      // that column's whole load.
      const double l_y = point.get_properties()[soil_property.domain_half_y];
      const double top = point.get_location()[1] + l_y;
      for_each_sample_of(point.get_location()[0],
                         point.get_properties()[soil_property.domain_half_x],
                         c,
                         [&](const unsigned int s) {
                           if (envelope[s] > -std::numeric_limits<double>::infinity()
                               && top >= envelope[s] - l_y)
                             f(s);
                         });
    }



    void
    SoilWaterInterface::apply_water_loads(particles::PointCloud       &soil_points,
                                          const water::ShallowWater1D &water,
                                          const double                 dt)
    {
      AssertThrow(soil_property.point_force_x != dealii::numbers::invalid_unsigned_int
                    && soil_property.point_force_y != dealii::numbers::invalid_unsigned_int,
                  dealii::ExcMessage("The soil's points carry no point forces to load."));
      Assert(reference_level.size() == water.n_cells(), dealii::ExcInternalError());
      // Under the excess form (paper 000, Eq. 10) the pressure on the bed is that above the
      // initial level eta_0 of the cell, rho_w g (eta - eta_0); the still water's weight
      // and thrust are not loads. Under hydrostatic pressure the same relative to the still
      // level eta_s, whose pressure is the buoyancy of the points below it.
      compute_cell_loads(water, dt);
      compute_face_thrusts(water);
      move_loads_to_columns();
      count_bearing_points(soil_points);
      write_point_forces(soil_points);
    }



    void
    SoilWaterInterface::compute_cell_loads(const water::ShallowWater1D &water, const double dt)
    {
      const auto        &mesh = water.mesh();
      const auto        &h    = water.depth();
      const auto        &B    = water.bed();
      const double       g    = water_constants.gravity;
      const double       n_m  = water_constants.manning_coefficient;
      const double       dry  = water_constants.dry_depth;
      const double       rho  = water_constants.density;
      const unsigned int n    = mesh.n_cells();
      for (unsigned int i = 0; i < n; ++i)
        {
          cell_load_x[i] = 0.;
          cell_load_y[i] = 0.;
          if (h[i] <= dry)
            continue;
          const double dx = mesh.width(i);
          const double u  = water.velocity(i);
          // Manning (Eq. 10), at most the momentum of the column over one step.
          double tau = rho * g * n_m * n_m * u * std::abs(u) / std::cbrt(h[i]);
          if (dt > 0.)
            tau = std::clamp(tau, -rho * h[i] * std::abs(u) / dt, rho * h[i] * std::abs(u) / dt);
          const unsigned int l = i > 0 ? i - 1 : i, r = i + 1 < n ? i + 1 : i;
          const double       slope = r > l ? (B[r] - B[l]) / (mesh.center(r) - mesh.center(l)) : 0.;
          // The excess pressure on the bed, p(B) - p_0(B) with p_0(z) = rho g (eta_0 - z)+:
          // rho g (eta - eta_0) where the bed is below the initial level (eta computed as
          // eta_0 was, so that still water gives an exact zero), the full rho g h where it
          // is above it (there was no water pressure there at the start).
          const double head = B[i] < reference_level[i] ? h[i] + B[i] - reference_level[i] : h[i];
          cell_load_x[i]    = tau * dx;
          cell_load_y[i]    = -rho * g * head * dx + tau * slope * dx;
        }
    }



    void
    SoilWaterInterface::compute_face_thrusts(const water::ShallowWater1D &water)
    {
      // The thrust of the water against each step of the bed, on the higher side: the
      // hydrostatic pressure of the lower cell's water integrated over the step's height,
      // borne by the soil in the wet band of the face, [B_low, eta_low]. Under the excess
      // form, the thrust of the present level less that of the initial level on the same
      // face (rho_w g (eta - eta_0) times the face's height where both levels are above it).
      constexpr double   no_level = -std::numeric_limits<double>::infinity();
      const auto        &h        = water.depth();
      const auto        &B        = water.bed();
      const unsigned int n        = water.mesh().n_cells();
      std::fill(cell_thrust.begin(), cell_thrust.end(), 0.);
      std::fill(cell_band_bottom.begin(),
                cell_band_bottom.end(),
                std::numeric_limits<double>::infinity());
      std::fill(cell_band_level.begin(), cell_band_level.end(), no_level);
      std::fill(cell_band_reference.begin(), cell_band_reference.end(), no_level);
      for (unsigned int i = 0; i + 1 < n; ++i)
        {
          const bool         rises = B[i + 1] > B[i];
          const unsigned int low = rises ? i : i + 1, high = rises ? i + 1 : i;
          if (h[low] <= water_constants.dry_depth)
            continue;
          const double eta = h[low] + B[low];
          // (Both thrusts from the levels, so that still water, whose eta is computed as
          // the reference level was, gives exactly zero.)
          const double thrust
            = thrust_of(eta, B[low], B[high]) - thrust_of(reference_level[low], B[low], B[high]);
          cell_thrust[high] += rises ? thrust : -thrust;
          cell_band_bottom[high]    = std::min(cell_band_bottom[high], B[low]);
          cell_band_level[high]     = std::max(cell_band_level[high], eta);
          cell_band_reference[high] = std::max(cell_band_reference[high], reference_level[low]);
        }
    }



    void
    SoilWaterInterface::move_loads_to_columns()
    {
      constexpr double no_level = -std::numeric_limits<double>::infinity();
      std::fill(column_load_x.begin(), column_load_x.end(), 0.);
      std::fill(column_load_y.begin(), column_load_y.end(), 0.);
      std::fill(column_thrust.begin(), column_thrust.end(), 0.);
      std::fill(band_bottom.begin(), band_bottom.end(), std::numeric_limits<double>::infinity());
      std::fill(band_level.begin(), band_level.end(), no_level);
      std::fill(band_reference.begin(), band_reference.end(), no_level);
      for (unsigned int i = 0; i + 1 < overlap_start.size(); ++i)
        for (unsigned int e = overlap_start[i]; e < overlap_start[i + 1]; ++e)
          {
            // Weight and shear on the part of the column that is soil.
            const unsigned int c = overlap_column[e];
            column_load_x[c] += coverage[c] * overlap_fraction[e] * cell_load_x[i];
            column_load_y[c] += coverage[c] * overlap_fraction[e] * cell_load_y[i];
            if (cell_thrust[i] != 0.)
              {
                column_thrust[c] += overlap_fraction[e] * cell_thrust[i];
                band_bottom[c]    = std::min(band_bottom[c], cell_band_bottom[i]);
                band_level[c]     = std::max(band_level[c], cell_band_level[i]);
                band_reference[c] = std::max(band_reference[c], cell_band_reference[i]);
              }
          }
    }



    void
    SoilWaterInterface::count_bearing_points(particles::PointCloud &soil_points)
    {
      // The weight and shear of a column are shared equally by its samples that soil
      // covers, and the load of a sample by the points that form the envelope there (their
      // top within half a point spacing of it). The points in the wet band of a face share
      // its thrust in proportion to the (excess) water pressure at their height, in
      // proportion to the part of the point's domain over the column.
      std::fill(sample_count.begin(), sample_count.end(), 0.);
      std::fill(face_weights.begin(), face_weights.end(), 0.);
      soil_points.for_each_particle([&](const auto &particle) {
        for_each_column_of(particle.get_location()[0],
                           particle.get_properties()[soil_property.domain_half_x],
                           [&](const unsigned int c, const double fraction) {
                             for_each_envelope_sample_of(particle, c, [&](const unsigned int s) {
                               sample_count[s] += 1.;
                             });
                             face_weights[c] += fraction * face_weight(particle, c);
                           });
      });
      dealii::Utilities::MPI::sum(sample_count, MPI_COMM_WORLD, sample_count);
      dealii::Utilities::MPI::sum(face_weights, MPI_COMM_WORLD, face_weights);
      std::fill(covered_samples.begin(), covered_samples.end(), 0.);
      for (unsigned int s = 0; s < sample_count.size(); ++s)
        if (sample_count[s] > 0.)
          covered_samples[s / samples_per_column] += 1.;
      // A face too low to hold a point: its thrust goes to the surface points.
      for (unsigned int c = 0; c < covered_samples.size(); ++c)
        if (column_thrust[c] != 0. && !(face_weights[c] > 0.))
          {
            column_load_x[c] += column_thrust[c];
            column_thrust[c] = 0.;
          }
    }



    void
    SoilWaterInterface::write_point_forces(particles::PointCloud &soil_points)
    {
      double total_buoyancy = 0.;
      soil_points.for_each_particle([&](auto &particle) {
        dealii::Tensor<1, 2> force({0., buoyancy(particle)});
        total_buoyancy += force[1];
        for_each_column_of(particle.get_location()[0],
                           particle.get_properties()[soil_property.domain_half_x],
                           [&](const unsigned int c, const double fraction) {
                             for_each_envelope_sample_of(particle, c, [&](const unsigned int s) {
                               const double share = 1. / (covered_samples[c] * sample_count[s]);
                               force[0] += column_load_x[c] * share;
                               force[1] += column_load_y[c] * share;
                             });
                             const double face = fraction * face_weight(particle, c);
                             if (face > 0.)
                               force[0] += column_thrust[c] * face / face_weights[c];
                           });
        auto p                         = particle.get_properties();
        p[soil_property.point_force_x] = force[0];
        p[soil_property.point_force_y] = force[1];
      });

      // What the soil carries: the loads of the columns with soil, and the buoyancy.
      total_load
        = dealii::Tensor<1, 2>({0., dealii::Utilities::MPI::sum(total_buoyancy, MPI_COMM_WORLD)});
      for (unsigned int c = 0; c < covered_samples.size(); ++c)
        if (covered_samples[c] > 0.)
          total_load
            += dealii::Tensor<1, 2>({column_load_x[c] + column_thrust[c], column_load_y[c]});
    }
  } // namespace coupling
} // namespace slidewave
