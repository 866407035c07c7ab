#ifndef slidewave_depth_averaged_depth_averaged_parameters_h
#define slidewave_depth_averaged_depth_averaged_parameters_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <memory>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/grid/adaptive_grid_parameters.h>
#include <slidewave/grid/grid_boundary.h>
#include <slidewave/grid/load_balancing_parameters.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/particles/material_region.h>
#include <slidewave/terrain/raster_terrain.h>
#include <string>

namespace slidewave
{
  namespace depth_averaged
  {
    /** The default 'Courant number', whose step the 'FLIP fraction' is the blend of. */
    constexpr double reference_courant_number = 0.5;
    /** The pressure term of the momentum balance (paper 001, §4.1). */
    enum class HydrostaticTerm
    {
      standard,   ///< sigma^nabla = sigma - 1/2 rho g h 1 and b = -g grad Z (Eqs. 14–15)
      still_level ///< about a known still level: 1/2 g (h^2 - H^2) and -g (h - H) grad Z (Eq. 41)
    };

    /**
     * The gravity and basal normal stress of a column on a slope ('Slope correction';
     * doc/depth-averaged.md, "Slope correction").
     */
    enum class SlopeCorrection
    {
      none,      ///< paper 001's plan-view terms: full g in the slope term, the pressure and
                 ///< the friction (a block slides at g (tan theta - tan phi) horizontally)
      bed_normal ///< the normal gravity g cos^2 theta on a vertical thickness h (a block
                 ///< slides at the exact g cos^2 theta (tan theta - tan phi))
    };

    /** How a column's depth follows the flow ('Depth update'). */
    enum class DepthUpdate
    {
      strain,    ///< h_p / (1 + tr(delta eps_p)) every step (paper 001, Eq. 38)
      projection ///< from the columns' volumes on the nodes, then Eq. 38 for the step
    };

    /**
     * Subsection "Depth averaged": the flow of paper 001 on a plan-view grid over a terrain
     * Z(x, y): the grid and its sides, the material (density, Bingham viscosity and yield
     * stress), Voellmy's basal friction, the terrain, the released material, the numerical
     * options and load balancing. Everything is read and checked here; a bad value is an
     * InputError naming the parameter, the value and what is allowed.
     */
    struct DepthAveragedParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads the subsection (the handler inside it); @p path names it in errors. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** @name Grid (plan view) */
      dealii::Point<2> lower_left, upper_right;
      double           cell_size = 0.2;
      /** 'Extent = terrain raster': the corners are not given but fitted inside the terrain
       *  raster's footprint (by the scene, once the raster's path is resolved). */
      bool grid_from_raster = false;
      /** Subsection "Adaptive grid": a grid that follows the flow (issue 28). */
      grid::AdaptiveGridParameters adaptivity;
      /** Left, right, bottom, top (ids 0-3): roller = 'wall', free = 'open'. */
      std::array<grid::GridBoundary, 4> sides{{grid::GridBoundary::roller,
                                               grid::GridBoundary::roller,
                                               grid::GridBoundary::roller,
                                               grid::GridBoundary::roller}};

      /** @name Physics */
      double gravity      = 9.81;
      double density      = 1200.;
      double viscosity    = 0.;
      double yield_stress = 0.;
      /** Papanastasiou's m [s]; 0: the plain Bingham law. */
      double regularization = 100.;
      bool   friction       = false;
      /** [rad] */
      double friction_angle = 0.;
      /** xi [m/s^2]; 0: no turbulent term. */
      double turbulence           = 0.;
      double atmospheric_pressure = 0.;

      HydrostaticTerm hydrostatic_term = HydrostaticTerm::standard;
      /** The still level's elevation H + Z [m] (still_level). */
      double          still_level      = 0.;
      SlopeCorrection slope_correction = SlopeCorrection::bed_normal;

      /** @name Terrain */
      std::string elevation;
      /** 'Source = table': the CSV file x,y,z (resolved against the scene's directory by
       *  the scene); empty: the expression. */
      std::string elevation_table;
      /** 'Source = raster': the DEM read through GDAL (resolved by the scene) and how its
       *  coordinates are taken; empty: not a raster. */
      std::string            elevation_raster;
      terrain::RasterOptions raster_options;
      /** 'Terrain/Coordinates CRS' as WKT: the CRS of the model's coordinates when the
       *  terrain has none ("": none). */
      std::string coordinates_crs_wkt;
      /** The terrain raster, opened (and warped) once for the whole set-up and shared:
       *  by the scene when 'Extent = terrain raster' asks it for its footprint, else by
       *  the solver, which takes its CRS and elevations from it and lets it go; null until
       *  then, and for a terrain that is not a raster. */
      std::shared_ptr<const terrain::RasterSource> terrain_raster;
      /** Spacing of the elevation grid the expression is sampled on [m]. */
      double terrain_spacing = 0.;

      /** @name Released material */
      /** The area: a rectangle, a polygon or a vector file (read by Release). */
      particles::MaterialRegion release;
      /** Exactly one of them is set: the depth h(x, y), the surface h + Z, a raster of the
       *  depth (resolved by the scene) or the vector file's field holding each polygon's
       *  depth. */
      std::string  depth, surface, depth_raster, depth_attribute;
      unsigned int particles_per_direction = 4;
      /** 'Depth' is a thickness normal to the slope: h = T sqrt(1 + |grad Z|^2). */
      bool depth_normal_to_slope = false;

      /** @name Numerics */
      DepthUpdate         depth_update   = DepthUpdate::projection;
      grid::ShapeFunction shape_function = grid::ShapeFunction::gimp;
      /** 0: PIC (Eq. 33), 1: FLIP (Eq. 34), between: the blend of a step at the default
       *  'Courant number' (reference_courant_number); a step dt blends
       *  flip_fraction^(dt / dt_ref) (engine::ParticleEngine::Settings). */
      double flip_fraction = 0.8;
      /** A column wider than this many times its initial width splits (0: never). */
      double split_stretch = 1.5;
      /** C of Eq. 22, with the wave speed |v| + sqrt(g h). */
      double courant_number  = 0.5;
      double fixed_time_step = 0.;

      /** @name Load balancing */
      grid::LoadBalancingParameters balancing;
      bool                          detailed_timing = false;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
