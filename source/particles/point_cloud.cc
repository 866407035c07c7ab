#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <limits>
#include <slidewave/grid/tree_order.h>
#include <slidewave/particles/point_cloud.h>
#include <sstream>

namespace slidewave
{
  namespace particles
  {
    PointCloud::PointCloud(grid::BackgroundGrid                    &grid,
                           const PropertyLayout                    &layout,
                           const unsigned int                       mass_index,
                           const std::array<grid::GridBoundary, 4> &sides,
                           const unsigned int                       particle_weight)
      : grid(grid)
      , properties(layout)
      , mass(mass_index)
      , sides(sides)
      , hold_depth(grid.cell_size())
      , particle_weight(particle_weight)
    {
      const double infinity = std::numeric_limits<double>::infinity();
      for (unsigned int d = 0; d < 2; ++d)
        {
          closed_low[d]
            = sides[2 * d] == grid::GridBoundary::free ? -infinity : grid.lower_left()[d];
          closed_high[d]
            = sides[2 * d + 1] == grid::GridBoundary::free ? infinity : grid.upper_right()[d];
        }
    }



    void
    PointCloud::expect_points(const std::vector<particles::MaterialRegion> &regions,
                              const unsigned int                            n)
    {
      expected_regions       = &regions;
      expected_per_direction = n;
    }



    unsigned int
    PointCloud::points_in(const CellIterator &cell, const unsigned int n) const
    {
      unsigned int count = 0;
      if (expected_regions != nullptr)
        for_each_point_to_create(cell, n, *expected_regions, [&count](const auto &...) {
          ++count;
        });
      else
        count = handler.n_particles_in_cell(cell);
      return count;
    }



    unsigned long long
    PointCloud::cell_weight(const CellIterator &cell, const CellStatus status) const
    {
      // The cell's points: those it holds or, before they exist, those the regions will
      // put there with 'per_direction' of them per direction.
      const unsigned int per_direction = expected_per_direction;
      unsigned int       n             = 0;
      switch (status)
        {
          case dealii::Triangulation<2>::CELL_PERSIST:
            n = points_in(cell, per_direction);
            break;
          case dealii::Triangulation<2>::CELL_REFINE:
            // The children's lattices together are the parent's at twice the density.
            n = points_in(cell, 2 * per_direction);
            break;
          case dealii::Triangulation<2>::CELL_COARSEN:
            for (const auto &child : cell->child_iterators())
              n += points_in(child, per_direction);
            break;
          default:
            break;
        }
      return static_cast<unsigned long long>(particle_weight) * n;
    }



    void
    PointCloud::add_refinement_indicators(std::vector<bool> &keep_fine) const
    {
      // Cells holding material: from the regions (at set-up: any point of the finest
      // lattice of points in the cell lies in a region) or from the points.
      std::vector<std::pair<dealii::Point<2>, dealii::Point<2>>> boxes;
      bool                                                       all_boxed = true;
      if (expected_regions != nullptr)
        {
          for (const auto &region : *expected_regions)
            {
              if (region.polygon.empty())
                all_boxed = false;
              else
                boxes.push_back(region.bounding_box());
            }
        }
      for (const auto &cell : grid.triangulation().active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          bool has_material = false;
          if (expected_regions != nullptr)
            {
              const dealii::Point<2> origin = cell->vertex(0);
              const double           h      = cell->vertex(1)[0] - origin[0];
              // A cell away from every region's bounding box holds none of its points (the
              // lattice test below costs (per_direction x 2^levels)^2 point-in-polygon
              // tests per coarse cell: most of the set-up on a regional DEM).
              const bool near_a_region
                = !all_boxed || std::any_of(boxes.begin(), boxes.end(), [&](const auto &box) {
                    return origin[0] <= box.second[0] && origin[0] + h >= box.first[0]
                           && origin[1] <= box.second[1] && origin[1] + h >= box.first[1];
                  });
              if (!near_a_region)
                continue;
              const unsigned int m = expected_per_direction
                                     * static_cast<unsigned int>(std::round(h / grid.cell_size()));
              for (unsigned int j = 0; j < m && !has_material; ++j)
                for (unsigned int i = 0; i < m && !has_material; ++i)
                  {
                    const dealii::Point<2> x(origin[0] + (i + 0.5) * h / m,
                                             origin[1] + (j + 0.5) * h / m);
                    for (const auto &region : *expected_regions)
                      has_material = has_material || region.contains(x);
                  }
            }
          else
            has_material = handler.n_particles_in_cell(cell) > 0;
          if (has_material)
            keep_fine[cell->active_cell_index()] = true;
        }
    }



    void
    PointCloud::initialize()
    {
      // The cells are axis-aligned rectangles: the Cartesian mapping finds a point's
      // reference coordinates directly (MappingQ1 would build an inverse approximation per
      // cell at every sort, a fifth of the step).
      static const dealii::MappingCartesian<2> mapping;
      handler.initialize(grid.triangulation(), mapping, properties.size());
      grid_outdated  = true;
      cells_outdated = true;
      handler.signals.particle_lost.connect(
        [this](const dealii::Particles::ParticleIterator<2> &particle,
               const typename dealii::Triangulation<2>::active_cell_iterator &) {
          lost_mass += particle->get_properties()[mass];
          const dealii::Point<2> x = particle->get_location();
          if (!wall_crossing.empty())
            return;
          std::ostringstream out;
          if (!std::isfinite(x[0]) || !std::isfinite(x[1]))
            {
              // (no side: every comparison with a NaN is false)
              out << "material point " << particle->get_id() << " left the domain at (" << x
                  << "), a position that is not finite";
              wall_crossing = out.str();
              return;
            }
          const unsigned int side = x[0] < grid.lower_left()[0]  ? 0 :
                                    x[0] > grid.upper_right()[0] ? 1 :
                                    x[1] < grid.lower_left()[1]  ? 2 :
                                                                   3;
          if (sides[side] != grid::GridBoundary::free)
            {
              static const char *const names[4] = {"left", "right", "bottom", "top"};
              out << "material point " << particle->get_id() << " left the domain at (" << x
                  << ") through the " << names[side] << " side, which is "
                  << (sides[side] == grid::GridBoundary::fixed ? "fixed" : "a roller")
                  << ", more than a cell past it (points may leave only through a free side; "
                     "a closed one holds a point that crosses it by less: the step carried "
                     "this one farther than a stable run can; lower 'Time step multiplier' "
                     "or stiffen the material)";
              wall_crossing = out.str();
            }
        });
    }



    void
    PointCloud::create(const unsigned int                            n,
                       const std::vector<particles::MaterialRegion> &regions,
                       const PropertyFill                           &fill)
    {
      std::vector<double> values(handler.n_properties_per_particle(), 0.);
      for (const auto &cell : grid.triangulation().active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const double hx = cell->vertex(1)[0] - cell->vertex(0)[0];
          const double hy = cell->vertex(2)[1] - cell->vertex(0)[1];
          for_each_point_to_create(cell,
                                   n,
                                   regions,
                                   [&](const dealii::Point<2> &position,
                                       const dealii::Point<2> &reference,
                                       const unsigned int      region_index,
                                       const unsigned int      lattice_index) {
                                     std::fill(values.begin(), values.end(), 0.);
                                     if (!fill(values, position, region_index, hx, hy))
                                       return;
                                     // Identifiers that do not depend on the partition: the
                                     // global index of the cell and the position in it.
                                     const dealii::types::particle_index id
                                       = cell->global_active_cell_index() * n * n + lattice_index;
                                     handler.insert_particle(position,
                                                             reference,
                                                             id,
                                                             cell,
                                                             dealii::make_array_view(values));
                                   });
        }
      handler.update_cached_numbers();
      cells_outdated   = true;
      expected_regions = nullptr;
    }



    bool
    PointCloud::relocate_within_patches(const std::vector<dealii::Point<2>> &new_positions,
                                        const grid::CellPatches             &patches,
                                        core::StepTimeline                  *timeline)
    {
      // The reference coordinates exactly as deal.II's MappingCartesian computes them,
      // and its test for a point inside the unit cell, so that this path and the full
      // sort put every point in the same cell at the same reference coordinates.
      const auto locate
        = [](const grid::PatchCell &c, const dealii::Point<2> &x, dealii::Point<2> &reference) {
            reference[0] = (x[0] - c.x0) / c.hx;
            reference[1] = (x[1] - c.y0) / c.hy;
            return reference[0] >= 0. && reference[0] <= 1. && reference[1] >= 0.
                   && reference[1] <= 1.;
          };
      moving_particles.clear();
      moving_data.clear();
      bool             leaves_patch = false;
      dealii::Point<2> reference;
      for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        const unsigned int own        = patches.start(cell_index);
        const unsigned int end        = patches.start(cell_index + 1);
        for (auto particle = particles_in_cell.begin(); particle != particles_in_cell.end();
             ++particle)
          {
            const dealii::Point<2> &x = new_positions[particle->get_local_index()];
            particle->set_location(x);
            if (locate(patches.own(cell_index), x, reference))
              {
                particle->set_reference_location(reference);
                continue;
              }
            unsigned int target = end;
            for (unsigned int c = own + 1; c < end; ++c)
              if (locate(patches.entry(c), x, reference))
                {
                  target = c;
                  break;
                }
            if (target == end || !patches.cell(target)->is_locally_owned())
              {
                leaves_patch = true; // out of the domain, to another rank, beyond the patch
                continue;
              }
            // A copy of what the point carries, to insert it in its new cell (inserting can
            // grow the property pool and move the memory the point's properties are in).
            moving_particles.push_back(
              {particle, patches.cell(target), particle->get_id(), x, reference});
            const auto values = particle->get_properties();
            moving_data.insert(moving_data.end(), values.begin(), values.end());
          }
      });
      // Collective: one reduction decides for all ranks.
      const unsigned int local[2]  = {leaves_patch ? 1u : 0u, moving_particles.empty() ? 0u : 1u};
      unsigned int       global[2] = {0, 0};
      if (timeline)
        timeline->lap(core::StepTimeline::relocation);
      dealii::Utilities::MPI::max(dealii::ArrayView<const unsigned int>(local, 2),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<unsigned int>(global, 2));
      if (timeline)
        timeline->lap(core::StepTimeline::relocation_reduction);
      if (global[0] != 0)
        return false; // the full sort takes over (the locations are set)
      if (global[1] == 0)
        return true;
      move_to_new_cells();
      return true;
    }



    void
    PointCloud::move_to_new_cells()
    {
      // As deal.II's sort does it, so that the points end up in the same order within
      // their cells: the moving points are appended to their new cells first, then
      // removed from their old ones back to front (the points were collected cell by cell
      // in increasing order within each cell; a removal moves a cell's last point into
      // the gap, so the iterators of the points still to be removed stay valid).
      // The cached cells holding points (for_each_cell_with_particles()) change only when a
      // cell receives its first point or loses its last.
      const unsigned int n_properties = handler.n_properties_per_particle();
      for (unsigned int k = 0; k < moving_particles.size(); ++k)
        {
          const MovingParticle &moving = moving_particles[k];
          if (handler.n_particles_in_cell(moving.cell) == 0)
            cells_outdated = true;
          handler.insert_particle(
            moving.location,
            moving.reference,
            moving.id,
            moving.cell,
            dealii::ArrayView<const double>(moving_data.data() + k * n_properties, n_properties));
        }
      for (auto moving = moving_particles.rbegin(); moving != moving_particles.rend(); ++moving)
        {
          const auto cell = moving->particle->get_surrounding_cell();
          handler.remove_particle(moving->particle);
          if (handler.n_particles_in_cell(cell) == 0)
            cells_outdated = true;
        }
      handler.update_cached_numbers();
    }



    std::vector<unsigned int>
    PointCloud::add_points(const std::vector<NewPoint> &new_points,
                           const std::vector<double>   &values)
    {
      std::vector<unsigned int> local_indices;
      if (dealii::Utilities::MPI::sum(static_cast<unsigned int>(new_points.size()), MPI_COMM_WORLD)
          == 0)
        return local_indices;
      // The identifiers: from deal.II's next free one on (the largest in use on any rank
      // plus one, at its last count), in the order of the parents' identifiers over all
      // ranks (the same on any number of ranks).
      const dealii::types::particle_index        first = handler.get_next_free_particle_index();
      std::vector<dealii::types::particle_index> parents;
      parents.reserve(new_points.size());
      for (const NewPoint &point : new_points)
        parents.push_back(point.parent_id);
      std::vector<dealii::types::particle_index> all_parents;
      for (const auto &rank_parents : dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, parents))
        all_parents.insert(all_parents.end(), rank_parents.begin(), rank_parents.end());
      std::sort(all_parents.begin(), all_parents.end());
      AssertThrow(static_cast<double>(first) + all_parents.size() < static_cast<double>(
                    std::numeric_limits<dealii::types::particle_index>::max()),
                  dealii::ExcMessage("The points' identifiers are exhausted."));

      const unsigned int n_properties = handler.n_properties_per_particle();
      local_indices.reserve(new_points.size());
      for (unsigned int k = 0; k < new_points.size(); ++k)
        {
          const NewPoint &point = new_points[k];
          const auto      place
            = std::lower_bound(all_parents.begin(), all_parents.end(), point.parent_id)
              - all_parents.begin();
          if (handler.n_particles_in_cell(point.cell) == 0)
            cells_outdated = true; // (a new point goes to its parent's cell)
          const auto inserted = handler.insert_particle(
            point.location,
            point.reference,
            first + place,
            point.cell,
            dealii::ArrayView<const double>(values.data() + k * n_properties, n_properties));
          local_indices.push_back(inserted->get_local_index());
        }
      handler.update_cached_numbers();
      return local_indices;
    }



    void
    PointCloud::sort()
    {
      handler.sort_particles_into_subdomains_and_cells();
      cells_outdated = true;
    }



    void
    PointCloud::prepare_for_grid_change()
    {
      handler.prepare_for_coarsening_and_refinement();
    }



    void
    PointCloud::grid_changed()
    {
      handler.unpack_after_coarsening_and_refinement();
      grid_outdated  = true;
      cells_outdated = true;
    }



    void
    PointCloud::prepare_for_checkpoint()
    {
      handler.prepare_for_serialization();
    }



    void
    PointCloud::checkpoint_loaded()
    {
      handler.deserialize();
      grid_outdated  = true;
      cells_outdated = true;
    }



    void
    PointCloud::find_cells_with_points() const
    {
      const unsigned int n_cells = grid.triangulation().n_active_cells();
      if (grid_outdated || tree_position.size() != n_cells)
        {
          tree_position.assign(n_cells, dealii::numbers::invalid_unsigned_int);
          unsigned int place = 0;
          grid::for_each_owned_cell_in_tree_order(grid.dof_handler(), [&](const auto &cell) {
            tree_position[cell->active_cell_index()] = place++;
          });
          grid_outdated = false;
        }
      // The handler's cells, one step each (the points of a cell are contiguous).
      cells_with_points.clear();
      for (auto particle = handler.begin(); particle != handler.end();)
        {
          const auto cell = particle->get_surrounding_cell();
          cells_with_points.push_back(cell);
          particle = handler.particles_in_cell(cell).end();
        }
      std::sort(cells_with_points.begin(),
                cells_with_points.end(),
                [this](const auto &a, const auto &b) {
                  return tree_position[a->active_cell_index()]
                         < tree_position[b->active_cell_index()];
                });
      Assert(cells_with_points.empty()
               || tree_position[cells_with_points.back()->active_cell_index()]
                    != dealii::numbers::invalid_unsigned_int,
             dealii::ExcInternalError());
      cells_outdated = false;
    }
  } // namespace particles
} // namespace slidewave
