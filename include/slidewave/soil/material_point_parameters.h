#ifndef slidewave_soil_material_point_parameters_h
#define slidewave_soil_material_point_parameters_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <memory>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/engine/velocity_transfer.h>
#include <slidewave/grid/grid_boundary.h>
#include <slidewave/grid/rigid_solid.h>
#include <slidewave/grid/rigid_wall.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/materials/material.h>
#include <slidewave/particles/material_region.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace soil
  {
    enum class UpdateScheme
    {
      usl, ///< update stress last (paper 000, Algorithm 1)
      musl ///< modified USL: strains from velocities re-mapped from the particles
    };

    /**
     * The largest stable alpha of Eq. 23 (paper 000): with lumped mass, the highest mode of
     * a 2D grid of square bilinear cells is sqrt(2) times faster than that of a line of
     * cells, so the explicit step is stable for dt <= h / (sqrt(2) max_p (c_p + |v_p|)).
     * Measured (doc/stability.md): GIMP runs complete at 0.7071 and blow up at 0.9.
     */
    constexpr double max_time_step_multiplier = 0.70710678118654752;
    /** The default 'Time step multiplier', whose step the 'FLIP fraction' is the blend of
     *  (a step of another length blends FLIP^(dt / dt_ref), ParticleEngine::Settings). */
    constexpr double reference_time_step_multiplier = 0.5;
    /** The default 'FLIP fraction' (the only one 'Velocity transfer = apic' accepts). */
    constexpr double default_flip_fraction = 0.99;

    /** The velocity conditions of the sides of the grid. */
    using GridBoundary = grid::GridBoundary;

    /** How the material starts stressed (subsection "Initial stress"). */
    enum class InitialStress
    {
      none,            ///< stress free
      geostatic,       ///< sigma_v from the weight of the material above, sigma_h = K0 sigma_v
      gravity_loading, ///< gravity applied with heavy damping until at rest, then released
      uniform          ///< the same given stress in every point
    };

    /**
     * Numerical and physical parameters of the material points, the background grid and its
     * boundaries (subsection "Material points").
     */
    struct MaterialPointParameters
    {
      /** Material subsections a scene may declare ("Material 1" ... ). */
      static constexpr unsigned int max_materials = 4;

      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Reads and checks everything; only the materials that some region refers to are
       * read.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** Adds the grid's cells and (a bound on) the points the regions will hold to
       *  @p estimate; @p path names the subsection in its messages. */
      void
      add_to_memory_estimate(core::MemoryEstimate &estimate, const std::string &path) const;

      dealii::Point<2>    lower_left, upper_right;
      double              cell_size               = 0.01;
      unsigned int        particles_per_direction = 2;
      grid::ShapeFunction shape_function          = grid::ShapeFunction::q1;
      UpdateScheme        update_scheme           = UpdateScheme::usl;
      double              flip_fraction           = default_flip_fraction;
      /** 'Velocity transfer': the FLIP blend or APIC (engine::VelocityTransfer). */
      engine::VelocityTransfer velocity_transfer    = engine::VelocityTransfer::flip;
      double                   time_step_multiplier = 0.5;
      double                   fixed_time_step      = 0.;
      bool                     b_bar                = true;
      /** 'B-bar point volumes = own': with B-bar each small-strain point's volume follows
       *  its own tr L dt while its stress takes the cell's mean dilatation (false: the
       *  volume takes the mean too). */
      bool own_volumes     = false;
      bool detailed_timing = false;
      bool step_timeline   = false;
      /** 'Particle relocation = full sort': deal.II's sort every step. */
      bool                 full_sort_every_step = false;
      dealii::Tensor<1, 2> gravity;
      double               damping = 0.;
      /** Boundary conditions on the left, right, bottom and top sides (ids 0-3). */
      std::array<GridBoundary, 4> boundaries{
        {GridBoundary::roller, GridBoundary::roller, GridBoundary::fixed, GridBoundary::free}};

      /** The rigid walls: the segments of the subsections "Rigid wall N" of Type 'roller'
       *  or 'fixed', in their order (grid::parse_rigid_body_parameters()). */
      std::vector<grid::RigidWall> walls;
      /** The rigid solids: the polygons of those of Type 'solid', in their order. */
      std::vector<grid::RigidSolid> solids;

      /** Subsection "Adaptive grid". */
      struct Adaptivity
      {
        bool         enabled      = false;
        unsigned int levels       = 2;
        unsigned int buffer_cells = 2;
        unsigned int interval     = 50;
        /** Subsection "Load balancing" (also without adaptivity). */
        unsigned int particle_weight     = 1000000;
        double       imbalance_threshold = 1.1;
      } adaptivity;
      unsigned int balance_interval = 50;

      InitialStress initial_stress = InitialStress::none;
      /** K0 = sigma_h / sigma_v; negative: from each material (1 - sin phi, or nu/(1-nu)). */
      double lateral_stress_ratio    = -1.;
      double gravity_loading_time    = 0.;
      double gravity_loading_damping = 0.7;
      /** 'uniform': sigma_xx, sigma_yy, sigma_xy, sigma_zz [Pa]. */
      std::array<double, 4> uniform_stress{{0., 0., 0., 0.}};

      /**
       * Kinematic mode ('Prescribed velocity'): the nodal velocities are v(x, y, t) of
       * this function (two components) instead of the solution of the momentum balance;
       * the points move and their stresses are updated from it as usual. Null: off.
       */
      std::shared_ptr<dealii::FunctionParser<2>> prescribed_velocity;

      std::vector<materials::MaterialParameters> materials;
      std::vector<particles::MaterialRegion>     regions;

      /**
       * Whether the material points carry point forces (property::point_force_x/y): set
       * by scenes that load the soil surface (the coupled scenes), not a user parameter.
       */
      bool point_forces = false;
    };
  } // namespace soil
} // namespace slidewave

#endif
