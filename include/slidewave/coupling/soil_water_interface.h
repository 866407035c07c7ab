#ifndef slidewave_coupling_soil_water_interface_h
#define slidewave_coupling_soil_water_interface_h

#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>
#include <limits>
#include <slidewave/coupling/monotone_cubic.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/particles/property_layout.h>
#include <slidewave/water/shallow_water_1d.h>
#include <slidewave/water/shallow_water_parameters.h>
#include <vector>

namespace slidewave
{
  namespace coupling
  {
    /** How the soil makes the bed of a column (subsection "Coupling", 'Soil surface'). */
    enum class SoilSurface
    {
      /** The top of the highest point domain in the column, max_p (y_p + l_p). */
      top,
      /** The mean over the column of the upper envelope of the point domains (sampled at
       *  samples_per_column points across the column; the grid's floor where no domain
       *  is): the top where the soil fills the column, and continuous as a face moves
       *  through a column. */
      envelope
    };



    /** Which water pressure loads the soil (subsection "Coupling", 'Water pressure on
     *  soil'). */
    enum class WaterPressure
    {
      /** The full hydrostatic pressure of the water, rho_w g (eta - z): total-stress
       *  loading, the still water's weight on the soil's top and its thrust on the faces.
       *  Applied as two parts that add up to it: the pressure of the still level eta_s,
       *  rho_w g (eta_s - z), whose integral over the wetted boundary of the soil below
       *  eta_s is the buoyancy of that soil (a body force rho_w g V upwards on the points
       *  below eta_s, consistent with the stress divergence as gravity is), and the
       *  pressure in excess of it on the boundary (as the excess form, relative to eta_s).
       *  The soil's stress then excludes the still water's pressure. */
      hydrostatic,
      /** Paper 000, Eq. 10: the pressure in excess of that of the initial water level
       *  eta_0 = h_0 + B_0 of each water cell, rho_w g (eta - eta_0) on the bed: still
       *  water loads nothing, a wave's crest pushes and its trough pulls. */
      excess_over_initial_level
    };



    /**
     * The constants of the water that its loads on the soil depend on (paper 000, Eq. 10),
     * given to SoilWaterInterface once at construction: the interface reads the water's
     * state, never its solver's parameters.
     */
    struct WaterConstants
    {
      /** rho_w [kg/m^3] (subsection "Coupling", 'Water density'). */
      double density;
      /** g [m/s^2] (the water's 'Gravity'). */
      double gravity;
      /** Manning's n of the bed shear [s/m^(1/3)]. */
      double manning_coefficient;
      /** The depth at and below which a water cell is dry and loads nothing [m]. */
      double dry_depth;

      /** The constants of water of density @p density [kg/m^3] that @p parameters
       *  describe (gravity, Manning's n, dry depth). */
      static WaterConstants
      of(const double density, const water::ShallowWaterParameters &parameters)
      {
        return {density, parameters.gravity, parameters.manning_coefficient, parameters.dry_depth};
      }
    };



    /**
     * What passes between the soil (material points) and the water (1D finite volumes)
     * across the seabed (paper 000, Eq. 10 and Algorithm 1):
     *
     * - soil to water: the soil surface in each column of the background grid (the top
     *   of the highest point domain in it, or the mean of the domains' upper envelope
     *   across it: SoilSurface); the bed of the water cells is the higher of it and the
     *   fixed terrain. When the water cells are the grid columns the
     *   column values are the bed; otherwise the bed is reconstructed at the water cell
     *   centres by monotone cubic interpolation through the column centres (no overshoot
     *   at a steep face or a corner).
     * - water to soil: per water cell, the weight of the water column on the bed and the
     *   Manning bed shear along it, and the hydrostatic thrust on the rising side of every
     *   step of the bed (exact for a stepped bed); under WaterPressure::excess_over_initial_level
     *   the weight and the thrust of the pressure in excess of the initial level's, which
     *   is rho_w g (eta - eta_0) below both levels; moved to the soil columns in proportion
     *   to the overlap (conservative), the weight and shear in proportion to the part of
     *   the column's width that is soil. In each column the weight and shear are shared by
     *   the material points within half a point spacing of the surface, the thrust by the
     *   points in the wet band of the face in proportion to the (excess) water pressure at
     *   their height, as point forces; a point acts on (and takes loads from) every column its
     *   domain overlaps, in proportion to the overlap. Dry cells load nothing; what falls on a
     * column without soil rests on the rigid floor.
     *
     * The water mesh and the columns are fixed at construction; per step the class
     * allocates nothing. Of the soil it knows only its points: their properties by the
     * indices of the soil's PropertyLayout, found once at construction (the half-sizes of
     * the points' domains and their volume, read; the point forces, written).
     */
    class SoilWaterInterface
    {
    public:
      /**
       * @p columns: the interfaces of the soil columns (increasing; the water mesh's own
       * interfaces when the water cells are the grid columns). @p terrain_at_columns and
       * @p terrain_at_cells: the fixed bed at the column and at the water cell centres.
       * @p soil_layout: the properties of the soil's points; it must name
       * "domain_half_x", "domain_half_y" and "volume", and "point_force_x",
       * "point_force_y" if apply_water_loads() is called.
       */
      SoilWaterInterface(std::vector<double>              columns,
                         const water::WaterMesh          &water_mesh,
                         std::vector<double>              terrain_at_columns,
                         std::vector<double>              terrain_at_cells,
                         const WaterConstants            &water_constants,
                         const particles::PropertyLayout &soil_layout,
                         SoilSurface                      surface,
                         double                           grid_floor,
                         WaterPressure                    pressure = WaterPressure::hydrostatic);

      /** Takes the water's present state as the reference of the loads: the free surface
       *  h + B per water cell as the initial level eta_0 of the excess pressure
       *  (WaterPressure::excess_over_initial_level), or the still level eta_s, the lowest
       *  free surface of the wet cells, in every cell wet now (WaterPressure::hydrostatic);
       *  -infinity in the cells dry now. */
      void
      set_initial_level(const water::ShallowWater1D &water);

      /** The reference level per water cell (eta_0, or eta_s where wet at the start). */
      const std::vector<double> &
      initial_level() const
      {
        return reference_level;
      }

      /** Sets the initial level eta_0 (a run resumed from a checkpoint). */
      void
      restore_initial_level(const std::vector<double> &level);

      /** The soil surface per column from the material points @p soil_points
       *  (collective). */
      void
      update_surface(const dealii::Particles::ParticleHandler<2> &soil_points);

      /** The bed per water cell from the last surface. */
      const std::vector<double> &
      bed();

      /**
       * Sets the point forces of all the soil's local points @p soil_points from the
       * water's state (zero away from the surface, the faces and the still water); @p dt
       * is the step the water just took (the bed shear never takes more momentum than the
       * water column has in one step). The points are visited in the grid's order
       * (particles::PointCloud::for_each_particle()): the same sums in a resumed run.
       * Collective.
       */
      void
      apply_water_loads(particles::PointCloud       &soil_points,
                        const water::ShallowWater1D &water,
                        double                       dt);

      /** The total load the water puts on the soil (the last apply_water_loads). */
      dealii::Tensor<1, 2>
      load_on_soil() const
      {
        return total_load;
      }

      /** Sets what load_on_soil() reports (a run resumed from a checkpoint: the point
       *  forces themselves are restored with the material points). */
      void
      restore_load_on_soil(const dealii::Tensor<1, 2> &load)
      {
        total_load = load;
      }

    private:
      using Point = dealii::Particles::ParticleAccessor<2>;

      /** Step 1 of apply_water_loads(): per water cell, the weight on the bed of the water
       *  (or of its excess over the reference level) and the Manning bed shear (paper 000,
       *  Eq. 10), in cell_load_x, cell_load_y. */
      void
      compute_cell_loads(const water::ShallowWater1D &water, double dt);

      /** Step 2: per water cell, the thrust of the water against the step of the bed on
       *  its rising side and the wet band of that face (cell_thrust, cell_band_*). */
      void
      compute_face_thrusts(const water::ShallowWater1D &water);

      /** Step 3: the loads of the water cells moved to the columns in proportion to the
       *  overlap (conservative), the weight and shear to the part that is soil. */
      void
      move_loads_to_columns();

      /** Step 4: how many points bear each envelope sample's load and the face weights of
       *  the points in each column's wet band (collective); the thrust of a face too low
       *  to hold a point goes to the column's surface points. */
      void
      count_bearing_points(particles::PointCloud &soil_points);

      /** Step 5: writes the point force of every local point and sums total_load, the
       *  loads of the columns with soil and the buoyancy (collective). */
      void
      write_point_forces(particles::PointCloud &soil_points);

      /** The buoyancy of @p point [N/m]: rho_w g times the part of its volume below the
       *  still level (WaterPressure::hydrostatic; otherwise 0). */
      double
      buoyancy(const Point &point) const;

      /** The hydrostatic thrust [N/m] of water at @p level on a face from @p bottom to
       *  @p top. */
      double
      thrust_of(double level, double bottom, double top) const;

      /** The share of a face's thrust that @p point in @p column takes, before
       *  normalization: the (excess) water pressure head at its height within the wet
       *  band, 0 outside it. */
      double
      face_weight(const Point &point, unsigned int column) const;

      /** Calls f(sample) for every envelope sample of column @p c that @p point forms
       *  (its top within half its height of the envelope there). */
      template <typename Function>
      void
      for_each_envelope_sample_of(const Point &point, unsigned int c, const Function &f) const;

      unsigned int
      column_of(double x) const;

      /** Calls f(column, fraction) for every column the domain [x - l, x + l] overlaps,
       *  with the fraction of the domain over it. */
      template <typename Function>
      void
      for_each_column_of(double x, double l, const Function &f) const;
      /** Calls f(sample) for every envelope sample of column c under [x - l, x + l]. */
      template <typename Function>
      void
      for_each_sample_of(double x, double l, unsigned int c, const Function &f) const;

      /** The soil's bed per column: the top or the envelope's mean. */
      const std::vector<double> &
      soil_bed() const
      {
        return surface_definition == SoilSurface::top ? surface_height : soil_height;
      }

      std::vector<double> columns, column_centers, cell_centers;
      /** The width of the columns if they are all equal, else 0. */
      double              uniform_width = 0.;
      std::vector<double> terrain_at_columns, terrain_at_cells;
      WaterConstants      water_constants;
      /** Where the interface reads and writes a soil point's properties: their indices
       *  in its property array, from the soil's layout (the point forces'
       *  numbers::invalid_unsigned_int when the soil carries none). */
      struct PropertyIndices
      {
        unsigned int volume, domain_half_x, domain_half_y, point_force_x, point_force_y;
      } soil_property;
      SoilSurface   surface_definition;
      double        floor;
      WaterPressure pressure;
      /** eta_0 per water cell (WaterPressure::excess_over_initial_level), or eta_s where
       *  the cell was wet at the start (WaterPressure::hydrostatic); -infinity elsewhere. */
      std::vector<double> reference_level;
      /** The level below which the points are buoyant (WaterPressure::hydrostatic): the
       *  still level eta_s, the highest reference level, under every column (a flat
       *  phreatic surface); -infinity before any water was set. */
      double buoyant_level = -std::numeric_limits<double>::infinity();
      /** Points forming the envelope at each sample (samples_per_column per column), and
       *  the covered samples per column: the shares of a column's weight and shear. */
      std::vector<double> sample_count, covered_samples;
      /** Sets buoyant_level from reference_level. */
      void
      set_buoyant_level();
      /** The columns are the water cells: no reconstruction, no transfer. */
      bool same_cells;

      /** Overlap of water cell i with columns: (column, fraction of the cell) in
       *  overlap[overlap_start[i] .. overlap_start[i+1]). */
      std::vector<unsigned int> overlap_start, overlap_column;
      std::vector<double>       overlap_fraction;

      /** Samples across a column of the envelope of the point domains. */
      static constexpr unsigned int samples_per_column = 8;

      std::vector<double> surface_height, soil_height, envelope, samples, bed_elevation;
      /** The part of each column's width that is soil (1 or 0 with SoilSurface::top). */
      std::vector<double> coverage;
      std::vector<double> column_load_x, column_load_y, cell_load_x, cell_load_y;
      /** Thrust on the faces of the bed and the wet band [bottom, water level] of the
       *  face, per water cell and per column. */
      std::vector<double> cell_thrust, cell_band_bottom, cell_band_level;
      /** The initial level of the band's water (-infinity under hydrostatic pressure). */
      std::vector<double>  cell_band_reference, band_reference;
      std::vector<double>  column_thrust, band_bottom, band_level, face_weights;
      MonotoneCubic        reconstruction;
      dealii::Tensor<1, 2> total_load;
    };
  } // namespace coupling
} // namespace slidewave

#endif
