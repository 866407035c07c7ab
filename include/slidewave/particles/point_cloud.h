#ifndef slidewave_particles_point_cloud_h
#define slidewave_particles_point_cloud_h

#include <algorithm>
#include <array>
#include <deal.II/base/point.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <slidewave/core/step_timeline.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/cell_patches.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/grid/velocity_constraints.h>
#include <slidewave/particles/material_region.h>
#include <slidewave/particles/property_layout.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace particles
  {
    /**
     * The material points of a model on the background grid: deal.II's ParticleHandler
     * with the model's PropertyLayout, the creation of points on a lattice in the cells
     * where regions hold material, the cheap relocation of points that moved less than a
     * cell (within the patch of their cell), the mass lost through free sides and the
     * detection of points that crossed a side that is not free, and the points'
     * checkpoint data. A GridFollower: the points travel with their cells through
     * refinement, coarsening and repartitioning.
     */
    class PointCloud : public grid::GridFollower
    {
    public:
      using ParticleHandler = dealii::Particles::ParticleHandler<2>;

      /**
       * Points on @p grid carrying the properties of @p layout; @p mass_index is the
       * property that counts as lost mass, @p sides the conditions of the grid's sides
       * (a point may leave only through a free one).
       */
      PointCloud(grid::BackgroundGrid                    &grid,
                 const PropertyLayout                    &layout,
                 unsigned int                             mass_index,
                 const std::array<grid::GridBoundary, 4> &sides,
                 unsigned int                             particle_weight);

      /**
       * Until create() is called, the cells weigh (cell_weight) and need fine
       * (add_refinement_indicators) the points that @p regions will put there with @p n
       * per direction: the grid is then refined and partitioned at set-up so that each
       * rank creates the points it keeps. @p regions must outlive create().
       */
      void
      expect_points(const std::vector<particles::MaterialRegion> &regions, unsigned int n);

      /** The particle handler on the grid (its cells must exist) and the lost-point
       *  signal. */
      void
      initialize();

      /** Calls f(position, reference, region index, lattice index in the cell) for the
       * points that create() puts in @p cell with @p n per direction: at the centres of
       * n x n sub-cells that lie in a region (the first that holds it). */
      template <typename Function>
      void
      for_each_point_to_create(const grid::BackgroundGrid::CellIterator     &cell,
                               unsigned int                                  n,
                               const std::vector<particles::MaterialRegion> &regions,
                               const Function                               &f) const;

      /** What create() asks of the model for each point: its properties (zeroed before)
       *  from its position, region index and the cell's size; false: no point there (no
       *  material, e.g. a depth of zero). */
      using PropertyFill = std::function<bool(std::vector<double>    &properties,
                                              const dealii::Point<2> &position,
                                              unsigned int            region_index,
                                              double                  hx,
                                              double                  hy)>;

      /** Fills the owned cells with n x n points per cell where they lie in a region;
       *  identifiers from the global cell index and the lattice position. Ends the
       *  expectation of expect_points(). */
      void
      create(unsigned int                                  n,
             const std::vector<particles::MaterialRegion> &regions,
             const PropertyFill                           &fill);

      /**
       * Calls @p f(cell, particles) for every locally owned cell that holds points, in the
       * order of the grid's tree (grid::for_each_owned_cell_in_tree_order()), not in the
       * particle handler's order of cells: deal.II's handler appends a cell that receives
       * its first points to its list, while a handler loaded from a checkpoint holds its
       * cells in the grid's order, so that sums over the points taken in the handler's
       * order would differ by round-off in a resumed run. The cells are a cached list,
       * found again (in proportion to the cells holding points, not to the grid) after
       * anything changed the handler's cells: empty cells cost nothing. Every loop whose
       * order matters (a sum, the first point found) goes through here or
       * for_each_particle(); the handler's cells must change only through this class.
       */
      template <typename Function>
      void
      for_each_cell_with_particles(const Function &f) const
      {
        if (cells_outdated)
          find_cells_with_points();
        for (const auto &cell : cells_with_points)
          f(cell, handler.particles_in_cell(cell));
      }

      /** Calls @p f(particle) for every locally owned point, cell by cell in the order of
       *  for_each_cell_with_particles(). */
      template <typename Function>
      void
      for_each_particle(const Function &f) const
      {
        for_each_cell_with_particles([&f](const auto &, const auto &particles_in_cell) {
          for (auto &particle : particles_in_cell)
            f(particle);
        });
      }

      /**
       * Puts every point at its new position (@p new_positions, by local index) in its
       * cell, looking only in the patch of its old cell, and moves the points that changed
       * cell (collective). Returns false, having set the locations only, when some point
       * on some rank left its rank's cells or its patch: then the full sort must run.
       */
      bool
      relocate_within_patches(const std::vector<dealii::Point<2>> &new_positions,
                              const grid::CellPatches             &patches,
                              core::StepTimeline                  *timeline);

      /** A point to add next to an existing one (a split): the cell and the location it
       *  is inserted at (its parent's; the next relocation moves it to where it goes) and
       *  the parent's identifier. */
      struct NewPoint
      {
        grid::BackgroundGrid::ActiveCellIterator cell;
        dealii::Point<2>                         location, reference;
        dealii::types::particle_index            parent_id;
      };

      /**
       * Inserts @p new_points, point k with the properties @p values[k n_p ... (k + 1) n_p),
       * and returns their local indices (their memory slots) in the same order. Their
       * identifiers do not depend on the partition: deal.II's next free identifier (the
       * largest on any rank plus one), plus the place of the parent's identifier among all
       * the parents of this call (a parent adds at most one point per call). Collective; nothing
       * happens, and nothing is communicated beyond one sum, when no rank adds a point.
       */
      std::vector<unsigned int>
      add_points(const std::vector<NewPoint> &new_points, const std::vector<double> &values);

      /** deal.II's full sort of the points into the cells and ranks. */
      void
      sort();

      /** The cells' order in the tree is found again (set-up, resume). */
      void
      grid_ready() override
      {
        grid_outdated  = true;
        cells_outdated = true;
      }

      /** The points travel with their cells: attached before the change. */
      void
      prepare_for_grid_change() override;

      /** The points taken back on their new cells. */
      void
      grid_changed() override;

      /** Attaches the points to the cells before the grid is saved. */
      void
      prepare_for_checkpoint() override;

      /** The particle handler on the coarse grid, before the cells are read. */
      void
      before_checkpoint_load() override
      {
        initialize();
      }

      /** Takes the points back from the cells after the grid was loaded. */
      void
      checkpoint_loaded() override;

      /** Cells holding points (or, before create(), points to come) must be fine. */
      void
      add_refinement_indicators(std::vector<bool> &keep_fine) const override;

      /** 'Particle weight' per point the cell holds (before create(): will hold); for a
       *  cell to be refined, its children's points, for one to be coarsened, its
       *  children's. */
      unsigned long long
      cell_weight(const CellIterator &cell, CellStatus status) const override;

      ParticleHandler &
      particles()
      {
        return handler;
      }

      const ParticleHandler &
      particles() const
      {
        return handler;
      }

      const PropertyLayout &
      layout() const
      {
        return properties;
      }

      /**
       * Holds a point that the step carries less than a cell across a closed side (fixed
       * or roller) of the grid: @p x, its new position, is put back on that side and the
       * point's velocity (@p v_x, @p v_y) loses its outward normal component. GIMP gives a
       * point within half its size of a wall the velocity of interior nodes (its domain
       * reaches past the wall's nodes, where no node holds it back), so a point resting on
       * a floor creeps through it by round-off amounts, and a column's centre sliding
       * along a wall crosses it. A point farther out has gone farther than a step of a
       * stable run carries it: it is not held, leaves the grid and stops the run
       * (wall_crossing). Only free sides let points out. Inline: four comparisons per
       * point of the gather.
       */
      void
      hold_at_closed_sides(dealii::Point<2> &x, double &v_x, double &v_y) const
      {
        for (unsigned int d = 0; d < 2; ++d)
          {
            double &v = d == 0 ? v_x : v_y;
            if (x[d] < closed_low[d] && x[d] > closed_low[d] - hold_depth)
              {
                x[d] = closed_low[d];
                v    = std::max(v, 0.);
              }
            else if (x[d] > closed_high[d] && x[d] < closed_high[d] + hold_depth)
              {
                x[d] = closed_high[d];
                v    = std::min(v, 0.);
              }
          }
      }

      /** Mass lost by this rank through the free sides. */
      double lost_mass = 0.;
      /** The first point of this rank lost through a side that is not free (more than a
       *  cell past it, or at a position that is not finite): a failed step. */
      std::string wall_crossing;

    private:
      grid::BackgroundGrid                   &grid;
      const PropertyLayout                   &properties;
      const unsigned int                      mass;
      const std::array<grid::GridBoundary, 4> sides;
      /** The closed sides' coordinates (x, y), infinite where a side is free, and how far
       *  past them a point is held (the coarse cell size). */
      dealii::Point<2>   closed_low, closed_high;
      double             hold_depth;
      const unsigned int particle_weight;
      ParticleHandler    handler;
      /** Set-up, until create(): the regions and the points per direction to come. */
      const std::vector<particles::MaterialRegion> *expected_regions       = nullptr;
      unsigned int                                  expected_per_direction = 0;

      /** The points create() puts in @p cell with @p n per direction (expect_points()),
       *  or the points the cell holds. */
      unsigned int
      points_in(const CellIterator &cell, unsigned int n) const;

      /** A point that changed cell within its patch (relocate_within_patches). */
      struct MovingParticle
      {
        ParticleHandler::particle_iterator       particle;
        grid::BackgroundGrid::ActiveCellIterator cell;
        dealii::types::particle_index            id;
        dealii::Point<2>                         location, reference;
      };
      /** Scratch of relocate_within_patches(), kept between steps (no allocation once
       *  grown): the moving points and their properties, one row each. */
      std::vector<MovingParticle> moving_particles;
      std::vector<double>         moving_data;

      /** The locally owned cells holding points, in the order of the grid's tree
       *  (for_each_cell_with_particles()), and whether the handler's cells may have changed
       *  since they were found. */
      mutable std::vector<grid::BackgroundGrid::ActiveCellIterator> cells_with_points;
      mutable bool                                                  cells_outdated = true;
      /** Each locally owned active cell's place in the tree order, by active cell index,
       *  and whether the grid changed since it was found. */
      mutable std::vector<unsigned int> tree_position;
      mutable bool                      grid_outdated = true;

      /** Finds cells_with_points: the handler's cells (one step per cell), sorted by their
       *  place in the tree (found first, in proportion to the grid, if it changed). */
      void
      find_cells_with_points() const;

      /** The end of relocate_within_patches() when some point on some rank changed cell:
       *  inserts this rank's moving points in their new cells, then removes them from their
       *  old ones, and updates the handler's counts. */
      void
      move_to_new_cells();
    };



    template <typename Function>
    void
    PointCloud::for_each_point_to_create(const grid::BackgroundGrid::CellIterator     &cell,
                                         const unsigned int                            n,
                                         const std::vector<particles::MaterialRegion> &regions,
                                         const Function                               &f) const
    {
      const dealii::Point<2> origin = cell->vertex(0);
      const double           hx     = cell->vertex(1)[0] - origin[0];
      const double           hy     = cell->vertex(2)[1] - origin[1];
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          {
            const dealii::Point<2> reference((i + 0.5) / n, (j + 0.5) / n);
            const dealii::Point<2> position(origin[0] + reference[0] * hx,
                                            origin[1] + reference[1] * hy);
            for (unsigned int r = 0; r < regions.size(); ++r)
              if (regions[r].contains(position))
                {
                  f(position, reference, r, j * n + i);
                  break;
                }
          }
    }
  } // namespace particles
} // namespace slidewave

#endif
