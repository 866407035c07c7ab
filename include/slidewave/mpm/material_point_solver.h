#ifndef slidewave_mpm_material_point_solver_h
#define slidewave_mpm_material_point_solver_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <memory>
#include <set>
#include <slidewave/materials/material.h>
#include <slidewave/mpm/material_region.h>
#include <slidewave/mpm/rigid_wall.h>
#include <slidewave/mpm/shape_functions.h>
#include <slidewave/mpm/step_timeline.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace mpm
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

    enum class GridBoundary
    {
      free,   ///< nothing imposed
      roller, ///< normal velocity zero (free slip)
      fixed   ///< both velocity components zero (no slip)
    };

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
    struct SolverParameters
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

      dealii::Point<2> lower_left, upper_right;
      double           cell_size               = 0.01;
      unsigned int     particles_per_direction = 2;
      ShapeFunction    shape_function          = ShapeFunction::q1;
      UpdateScheme     update_scheme           = UpdateScheme::usl;
      double           flip_fraction           = 0.99;
      double           time_step_multiplier    = 0.5;
      double           fixed_time_step         = 0.;
      bool             b_bar                   = true;
      bool             detailed_timing         = false;
      bool             step_timeline           = false;
      /** 'Particle relocation = full sort': deal.II's sort every step. */
      bool                 full_sort_every_step = false;
      dealii::Tensor<1, 2> gravity;
      double               damping = 0.;
      /** Boundary conditions on the left, right, bottom and top sides (ids 0-3). */
      std::array<GridBoundary, 4> boundaries{
        {GridBoundary::roller, GridBoundary::roller, GridBoundary::fixed, GridBoundary::free}};

      std::vector<RigidWall> walls;

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
      std::vector<MaterialRegion>                regions;

      /**
       * Whether the material points carry point forces (property::point_force_x/y): set
       * by scenes that load the soil surface (the coupled scenes), not a user parameter.
       */
      bool point_forces = false;
    };



    /**
     * The explicit material point method of paper 000 (§3.1, Eqs. 13–23) in 2D plane
     * strain: material points in deal.II's ParticleHandler on a background grid of Q1 cells
     * (a parallel::distributed::Triangulation), lumped nodal mass, and per step
     *
     *   1. particle to grid: nodal mass, momentum, internal and external forces
     *      (Eqs. 14–17);
     *   2. grid update: accelerations and velocities (Eqs. 18–19), boundary conditions;
     *   3. grid to particle: velocities (PIC/FLIP blend) and positions (Eqs. 20–21);
     *   4. stresses from the updated nodal velocities (USL), or from velocities mapped back
     *      from the particles (MUSL), with the Jaumann rate (Eqs. 5–6) and, optionally, the
     *      B-bar treatment of the volumetric strain against locking.
     *
     * Nodal quantities live in deal.II distributed vectors (one per component) on a scalar
     * Q1 DoFHandler; shape functions are evaluated by hand on the axis-aligned cells.
     * The class allocates nothing per particle per step.
     */
    class MaterialPointSolver
    {
    public:
      explicit MaterialPointSolver(const SolverParameters &parameters);

      /**
       * Creates the grid, fills the regions with material points and sets up their
       * initial stress (at time @p start_time; gravity loading runs before it).
       * @p apply_loads, if given, is called once the points exist and before the initial
       * stress is set up: it sets the point forces (surface loads), which the geostatic
       * stress then carries and gravity loading holds.
       */
      void
      setup(double start_time = 0., const std::function<void()> &apply_loads = {});

      bool
      has_point_forces() const
      {
        return prm.point_forces;
      }

      /**
       * Sets the point force of every local material point to @p force(particle) [N/m];
       * they act in every following step until set again (needs
       * SolverParameters::point_forces).
       */
      void
      set_point_forces(
        const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
          &force);

      /** The sum of the point forces over all points (collective). */
      dealii::Tensor<1, 2>
      total_point_force() const;

      /**
       * Writes the grid and the material points (all properties) under @p prefix
       * (collective; deal.II's triangulation files plus attached particle data).
       */
      void
      save(const std::string &prefix);

      /**
       * Instead of setup(): rebuilds the grid and the material points written by save(),
       * on any number of ranks (collective).
       */
      void
      load(const std::string &prefix);

      /** What else determines the future of a run: time, lost mass, step counter. */
      struct State
      {
        double       time = 0., lost_mass = 0.;
        unsigned int n_steps = 0;
      };

      State
      state() const;

      void
      set_state(const State &state);

      /** h / max_p (c_p + |v_p|): Eq. 23 with alpha = 1 (collective); the stable step is
       *  max_time_step_multiplier times this. */
      double
      stability_limit() const;

      /** The time step of Eq. 23 (or the fixed one). */
      double
      stable_time_step() const;

      /**
       * Times the parts of each step in @p timer_output when 'Detailed timing' is on
       * (otherwise nothing); the timer must outlive the solver's steps.
       */
      void
      set_timer(dealii::TimerOutput &timer_output);

      /** One step of length @p dt. */
      void
      advance(double dt);

      /**
       * Checks the particles for non-finite values and non-positive volumes; returns a
       * description of the first bad one, or "" when all is well (collective).
       */
      std::string
      find_invalid_particle() const;

      /** Integral quantities, reduced over all ranks (collective). */
      struct Integrals
      {
        double       mass = 0., momentum_x = 0., momentum_y = 0., kinetic_energy = 0.;
        double       max_speed = 0., runout = 0., max_height = 0.;
        double       lost_mass   = 0.;
        unsigned int n_particles = 0;
      };

      Integrals
      integrals() const;

      /**
       * Energies per unit thickness [J/m], reduced over all ranks (collective): kinetic,
       * elastic (p^2/(2K) + s:s/(4G) per unit volume) and the work done by gravity since
       * the start, sum m g.(x - x_0).
       */
      struct EnergyBudget
      {
        double kinetic = 0., elastic = 0., gravity_work = 0.;
      };

      EnergyBudget
      energy_budget() const;

      /** "material point ID at (x y) with speed S m/s" for the fastest point (collective). */
      std::string
      describe_fastest_particle() const;

      const dealii::parallel::distributed::Triangulation<2> &
      triangulation() const
      {
        return tria;
      }

      const dealii::Particles::ParticleHandler<2> &
      particles() const
      {
        return particle_handler;
      }

      const dealii::DoFHandler<2> &
      dof_handler() const
      {
        return dofs;
      }

      /** Nodal velocities after the last grid update (ghosted). */
      const dealii::LinearAlgebra::distributed::Vector<double> &
      nodal_velocity(unsigned int component) const
      {
        return velocity[component];
      }

      /** Lumped nodal masses of the last particle-to-grid transfer (owned entries). */
      const dealii::LinearAlgebra::distributed::Vector<double> &
      lumped_nodal_mass() const
      {
        return nodal_mass;
      }

      /** Max over mean of the ranks' work (cells and points; collective). */
      double
      load_imbalance() const;

      /** How often the grid was adapted or repartitioned. */
      unsigned int
      n_grid_adaptations() const
      {
        return n_grid_changes;
      }

      /** The per-step, per-rank times of the parts of the step ('Step timeline'), or null
       * when it is off. */
      const StepTimeline *
      step_timeline() const
      {
        return timeline.get();
      }

      /** Steps whose points were relocated by deal.II's full sort ('Particle relocation'). */
      unsigned int
      n_full_particle_sorts() const
      {
        return n_full_sorts;
      }

      /** Time of the particles' state. */
      double
      current_time() const
      {
        return time;
      }

      /**
       * Scatters the particles' mass and momentum to the grid and returns the totals over
       * all nodes {mass, momentum x, momentum y} (a check of the transfer; collective).
       */
      std::array<double, 3>
      nodal_totals();

    private:
      using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

      /** The coarse grid (as few cells as the sides allow; base_refinements global
       *  refinements make the base grid) and the weight signal. */
      void
      create_coarse_grid();

      /** Particle handler set-up and the particle_lost signal. */
      void
      initialize_particle_handler();

      /** Fills the owned cells with points: n x n per cell where they lie in a region. */
      void
      create_particles();

      /** Calls f(position, reference, region index, lattice index in the cell) for the
       * points that create_particles() puts in @p cell with @p n per direction. */
      template <typename Function>
      void
      for_each_point_to_create(const dealii::Triangulation<2>::cell_iterator &cell,
                               unsigned int                                   n,
                               const Function                                &f) const;

      /** Dofs, vectors, hanging nodes, boundary nodes, patches, walls of the grid. */
      void
      setup_grid_data();

      /** Active cells (owned and ghost) that hold material or lie within the buffer. */
      std::vector<bool>
      cells_near_material(bool from_regions) const;

      /** Partitioning weight of a cell without points (deal.II's convention; its 'weight'
       * signal adds none of its own). */
      static constexpr unsigned int cell_base_weight = 1000;

      /** Weight of a cell for partitioning: cell_base_weight plus particle_weight per point
       * (before the points exist, per point that create_particles() will put there), capped at
       * 2^31 - 1 (p4est takes an int). */
      unsigned int
      cell_weight(const dealii::Triangulation<2>::cell_iterator &cell,
                  dealii::Triangulation<2>::CellStatus           status) const;

      /** Repartition by cells and points when the imbalance exceeds the threshold. */
      void
      balance_load();

      /** Refine where material is, coarsen where it left, repartition if needed. */
      void
      adapt_grid();

      /** Sums on hanging nodes go to their parents (before compress). */
      void
      condense_hanging_nodes(dealii::LinearAlgebra::distributed::Vector<double> &v) const;

      /** Hanging nodes take their parents' interpolated values (ghosted vectors). */
      void
      interpolate_hanging_nodes(dealii::LinearAlgebra::distributed::Vector<double> &v) const;

      /** For each owned cell, the cells sharing a vertex with it (GIMP's reach). */
      void
      build_cell_patches();

      /** The owned nodes of each rigid wall. */
      void
      find_wall_nodes();

      /** sigma_v from the weight of the material above, sigma_h = K0 sigma_v. */
      void
      set_geostatic_stress();

      /** Gravity with heavy local damping, walls held, until gravity_loading_time. */
      void
      load_gravity();

      template <typename ParticleAccessorType>
      void
      shape_weights(const ParticleAccessorType &particle,
                    unsigned int                cell_index,
                    NodeWeights                &w) const;

      double
      empty_node_mass() const;

      /** Kinematic mode: nodal velocities from SolverParameters::prescribed_velocity. */
      void
      prescribe_nodal_velocities(double dt);

      /** Stresses of the points of one cell from their velocity gradients
       *  (cell_gradients, in the order of @p particles_in_cell). */
      void
      update_cell_stresses(
        const dealii::Particles::ParticleHandler<2>::particle_iterator_range &particles_in_cell,
        double                                                                dt);

      /**
       * Calls @p f(cell, particles) for every locally owned cell that holds material
       * points, in the particle handler's order of cells (after a full sort the points'
       * memory is in this order): empty cells cost nothing and the points' memory is
       * read front to back.
       */
      template <typename Function>
      void
      for_each_cell_with_particles(const Function &f)
      {
        auto       particle = particle_handler.begin();
        const auto end      = particle_handler.end();
        while (particle != end)
          {
            const auto cell  = particle->get_surrounding_cell();
            const auto range = particle_handler.particles_in_cell(cell);
            f(cell, range);
            particle = range.end();
          }
      }

      /**
       * Puts every point at its new position (new_positions) in its cell, looking only in
       * the patch of its old cell, and moves the points that changed cell (collective).
       * Returns false, having set the locations only, when some point on some rank left
       * its rank's cells or its patch: then deal.II's full sort must run.
       */
      bool
      relocate_within_patches();

      void
      particles_to_grid();

      /** Clears last step's nodal values on its active nodes and empties the list; the
       * scatter then marks the nodes of each cell it visits (particles_to_grid). */
      void
      clear_active_nodes();

      void
      mark_active(const unsigned int i)
      {
        if (node_is_active[i] == 0)
          {
            node_is_active[i] = 1;
            active_nodes.push_back(i);
          }
      }

      /** Adds the parents of active hanging nodes and the owned nodes other ranks send to. */
      void
      complete_active_nodes();

      void
      update_grid(double dt);

      void
      grid_to_particles(double dt, bool with_stresses);

      void
      remap_velocities_to_grid();

      void
      update_stresses(double dt);

      void
      apply_boundary_conditions(Vector &vx, Vector &vy) const;

      SolverParameters                                prm;
      std::vector<materials::Material>                materials;
      dealii::parallel::distributed::Triangulation<2> tria;
      dealii::FE_Q<2>                                 fe;
      dealii::DoFHandler<2>                           dofs;
      dealii::Particles::ParticleHandler<2>           particle_handler;

      Vector                nodal_mass;
      std::array<Vector, 2> momentum, force, velocity, velocity_old;

      /** The grid work of a step is over the nodes the points talk to, not the whole grid
       * (most of which is empty in a landslide): active_nodes are the local indices (owned
       * and ghost) of the nodes of the cells with points (their patches with GIMP), the
       * parents of hanging ones among them and the owned nodes other ranks send to. Outside
       * them the nodal mass, momentum, force and velocities are zero (a step clears them
       * on last step's active nodes before it scatters). */
      std::vector<unsigned int> active_nodes;
      /** The scatter's sums per local node, side by side (mass, momentum x, y, force x,
       * y: one cache line per node instead of five vectors); zero between steps. */
      std::vector<double> node_sums;
      /** The gather's values per local node, side by side: v^new x, y and v^new - v^old
       * x, y, set on the active nodes by update_grid(). */
      std::vector<double> node_velocities;
      /** Per local node (owned and ghost): in active_nodes. */
      std::vector<unsigned char> node_is_active;
      /** Owned nodes (local indices) that are ghosts of other ranks. */
      std::vector<unsigned int> import_nodes;

      /** Local indices of owned nodes where v_x (0) or v_y (1) is held at zero. */
      std::array<std::vector<unsigned int>, 2> constrained_dofs;

      /** A rigid wall's owned nodes (local indices) per held component. */
      struct WallNodes
      {
        std::array<std::vector<unsigned int>, 2> nodes;
        double                                   release_time;
        bool                                     active = true;
      };
      std::vector<WallNodes> supports;

      /** Each owned cell's own entry, by active cell index (a copy of the first of its
       * patch): what Q1 and the relocation read for every point, densely stored. */
      std::vector<PatchCell> own_cell;
      /** Cells of each owned cell's patch: patch_cells[patch_start[c] .. patch_start[c+1]),
       * the cell itself first. */
      std::vector<unsigned int> patch_start;
      /** The active cells around each vertex (rebuilt when the grid changes). */
      std::vector<std::set<dealii::Triangulation<2>::active_cell_iterator>> vertex_cells;
      std::vector<PatchCell>                                                patch_cells;
      /** The cell of each entry of patch_cells. */
      std::vector<dealii::Triangulation<2>::active_cell_iterator> patch_cell_iterators;

      /** Hanging nodes (local indices) and their parents and weights:
       * hanging_parent[hanging_start[k] .. hanging_start[k+1]) for hanging_node[k]. */
      std::vector<unsigned int> hanging_node, hanging_start, hanging_parent;
      std::vector<double>       hanging_weight;

      unsigned int n_steps = 0, n_grid_changes = 0;
      /** Global refinements of the coarse grid up to the base grid (create_coarse_grid). */
      unsigned int base_refinements = 0;
      /** Steps relocated by the full sort (advance). */
      unsigned int n_full_sorts = 0;
      /** A point that changed cell within its patch (relocate_within_patches). */
      struct MovingParticle
      {
        dealii::Particles::ParticleHandler<2>::particle_iterator particle;
        dealii::Triangulation<2>::active_cell_iterator           cell;
        dealii::types::particle_index                            id;
        dealii::Point<2>                                         location, reference;
      };
      /** Scratch of relocate_within_patches(), kept between steps (no allocation once
       *  grown): the moving points and their properties, one row each. */
      std::vector<MovingParticle> moving_particles;
      std::vector<double>         moving_data;

      /** Where the parts of a step are timed ('Detailed timing'), or null. */
      dealii::TimerOutput *timer = nullptr;
      /** Per-step times of the parts ('Step timeline'): only allocated when on. */
      std::unique_ptr<StepTimeline> timeline;

      /** The end of a part of the step for the step timeline, when it is on. */
      void
      lap(const StepTimeline::Part part)
      {
        if (timeline)
          timeline->lap(part);
      }

      double lost_mass = 0.;
      /** The first point of this rank that left through a side that is not free: points may
       *  only leave through free sides, one crossing a wall is a failed step. */
      std::string wall_crossing;
      double      time = 0.;
      /** Local damping in force now (heavier during gravity loading). */
      double damping         = 0.;
      bool   loading_gravity = false;
      /** Set-up, before the points exist: the cell weights count the points to come, so
       * that they are created on the ranks that keep them. */
      bool weights_from_regions = false;

      /** Positions of the owned nodes (local index), for a prescribed velocity only. */
      std::vector<dealii::Point<2>> node_positions;

      /** Side arrays reused every step (no allocation per particle). */
      std::vector<dealii::Point<2>>     new_positions;
      std::vector<dealii::Tensor<2, 2>> cell_gradients;
    };
  } // namespace mpm
} // namespace slidewave

#endif
