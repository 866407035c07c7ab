#ifndef slidewave_depth_averaged_depth_averaged_solver_h
#define slidewave_depth_averaged_depth_averaged_solver_h

#include <array>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/particles/particle_handler.h>
#include <memory>
#include <slidewave/depth_averaged/depth_averaged_model.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/depth_averaged/release.h>
#include <slidewave/engine/particle_engine.h>
#include <slidewave/engine/transfer_kernels.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/cell_patches.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/velocity_constraints.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/terrain/elevation_grid.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * The depth-averaged material point method of paper 001 (§3): the columns in deal.II's
     * ParticleHandler on a plan-view grid of Q1 cells over the terrain, and per step
     *
     *   1. particles to grid: lumped mass, momentum, internal and external forces and the
     *      basal resistance (Eqs. 27–31);
     *   2. grid update: explicit velocities (Eq. 32) with Voellmy's friction at the nodes,
     *      walls;
     *   3. grid to particles: PIC (Eq. 33), FLIP (Eq. 34) or a blend, positions (Eq. 35);
     *   4. USL: depth (Eq. 38) and Bingham stress (Eqs. 36–37) from the new nodal
     *      velocities.
     *
     * The same engine as the soil (engine::ParticleEngine: point cloud, nodal workspace,
     * constraints, patches and the particle–grid cycle, on the scene's background grid)
     * with the model DepthAveragedModel. The terrain is sampled once onto a
     * terrain::ElevationGrid.
     */
    class DepthAveragedSolver
    {
    public:
      /** The flow of @p parameters on the scene's @p grid (attaches to it). */
      DepthAveragedSolver(const DepthAveragedParameters &parameters, grid::BackgroundGrid &grid);

      /** The grid of the flow's parameters ('Grid', 'Adaptive grid', 'Load balancing'). */
      static std::unique_ptr<grid::BackgroundGrid>
      make_grid(const DepthAveragedParameters &parameters);

      /** Creates the grid and fills the release with columns at @p start_time. */
      void
      setup(double start_time);

      /** Writes the grid and the points under @p prefix (collective). */
      void
      save(const std::string &prefix);

      /** Instead of setup(): the grid and points written by save(), on any number of ranks. */
      void
      load(const std::string &prefix);

      /** Time, lost mass (summed over ranks) and step counter. */
      using State = engine::ParticleEngine<DepthAveragedModel>::State;

      State
      state() const;

      void
      set_state(const State &state);

      /** The smaller of h / max_p (|v_p| + sqrt(g h_p)) (Eq. 22 with C = 1) and the
       *  viscous limit rho h^2 / (4 (2 mu + tau_Y m)) (collective). */
      double
      stability_limit() const;

      /** C times the limit (Eq. 22), or the fixed step. */
      double
      stable_time_step() const;

      void
      set_timer(dealii::TimerOutput &timer_output);

      /** One step of length @p dt. */
      void
      advance(double dt);

      /** Scatters the points and returns the nodal totals {mass, momentum x, y}. */
      std::array<double, 3>
      nodal_totals();

      /** What the columns give the nodes now (ghosted): the depth sum_p V_p N_i / a_i
       *  (a_i the node's lumped area) and the mass-weighted mean velocity
       *  sum_p m_p v_p N_i / sum_p m_p N_i (never faster than the columns). */
      struct NodalState
      {
        dealii::LinearAlgebra::distributed::Vector<double>                depth;
        std::array<dealii::LinearAlgebra::distributed::Vector<double>, 2> velocity;
      };

      /** @p with_velocity false: the depth only (the velocities stay empty). */
      NodalState
      nodal_state(bool with_velocity = true) const;

      /** Lumped nodal depth sum_p V_p N_i / sum of the cells' areas at node i, ghosted. */
      dealii::LinearAlgebra::distributed::Vector<double>
      nodal_depth() const
      {
        return nodal_state(false).depth;
      }

      /** The terrain at the nodes (ghosted). */
      dealii::LinearAlgebra::distributed::Vector<double>
      nodal_elevation() const;

      /** Max over mean of the ranks' work (collective). */
      double
      load_imbalance() const;

      const DepthAveragedModel &
      model() const
      {
        return flow;
      }

      particles::PointCloud &
      point_cloud()
      {
        return engine.point_cloud();
      }

      const particles::PointCloud &
      point_cloud() const
      {
        return engine.point_cloud();
      }

      const dealii::Particles::ParticleHandler<2> &
      particles() const
      {
        return engine.point_cloud().particles();
      }

      const dealii::DoFHandler<2> &
      dof_handler() const
      {
        return grid.dof_handler();
      }

      const dealii::parallel::distributed::Triangulation<2> &
      triangulation() const
      {
        return grid.triangulation();
      }

      /** Nodal velocities after the last grid update (ghosted). */
      const dealii::LinearAlgebra::distributed::Vector<double> &
      nodal_velocity(const unsigned int component) const
      {
        return engine.nodal_workspace().velocity[component];
      }

      /** The released material. */
      const Release &
      release_area() const
      {
        return release;
      }

      /** The model's CRS (the terrain raster's) as WKT; "" when the terrain has none. */
      const std::string &
      crs() const
      {
        return model_crs;
      }

    private:
      DepthAveragedParameters prm;
      /** The terrain raster's CRS as WKT; "" for an expression or a table. */
      std::string                                model_crs;
      terrain::ElevationGrid                     elevation;
      Release                                    release;
      DepthAveragedModel                         flow;
      grid::BackgroundGrid                      &grid;
      engine::ParticleEngine<DepthAveragedModel> engine;
    };
  } // namespace depth_averaged

  extern template class engine::TransferKernels<depth_averaged::DepthAveragedModel>;
  extern template class engine::ParticleEngine<depth_averaged::DepthAveragedModel>;
} // namespace slidewave

#endif
