#ifndef slidewave_engine_transfer_kernels_h
#define slidewave_engine_transfer_kernels_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <slidewave/core/step_timeline.h>
#include <slidewave/grid/cell_patches.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/grid/velocity_constraints.h>
#include <slidewave/particles/point_cloud.h>
#include <vector>

namespace slidewave
{
  namespace engine
  {
    /**
     * The particle–grid cycle of the explicit material point method (paper 000, §3.1,
     * Eqs. 13–23), shared by every material-point model: particles to grid (lumped mass,
     * momentum and the model's nodal forces, Eqs. 14–17), the grid update (Eqs. 18–19,
     * Cundall's local damping, the velocity constraints), grid to particles (PIC/FLIP
     * velocities, Eq. 20, positions, Eq. 21, and velocity gradients for the model's
     * constitutive update), and the MUSL re-map of the nodal velocities from the updated
     * particle velocities.
     *
     * A template on the particle model, instantiated in the model's own source, so that
     * the model's per-point terms are inlined into the loops: nothing is virtual, nothing
     * is allocated per point, and the kernels hold no model's name or flag. What a model
     * declares (engine::ParticleModelDefaults gives every optional part a default that
     * compiles to nothing; doc/architecture.md walks through it):
     *
     * - the property indices `mass`, `volume`, `velocity_x`, `velocity_y`,
     *   `domain_half_x`, `domain_half_y` (static constexpr unsigned int);
     * - `ScatterTerms scatter_terms(const Properties &p, const Point<2> &x) const` (what
     *   the point at @p x scatters, read once per point) and `void nodal_force(const
     *   ScatterTerms &, const NodeWeights &, unsigned int k, double m_k, double &f_x,
     *   double &f_y) const` (the point's force on its k-th node);
     * - its nodal fields beyond mass, momentum and force: `static constexpr unsigned int
     *   n_nodal_fields`, `void scatter_fields(const ScatterTerms &, double N_k, double
     *   *sums) const` (adds the point's share to its k-th node's fields), and `void
     *   finish_nodal_fields(grid::NodalWorkspace &) const` (after the fields' exchange);
     * - what it does at the nodes in the grid update: `double nodal_force_at_node(double
     *   v, double f) const` (the force of one component that drives the node, e.g.
     *   damped) and `void update_nodal_velocity(const grid::NodalWorkspace &, unsigned
     *   int i, double m, double dt, double &v_x, double &v_y) const` (after Eqs. 18–19,
     *   before the constraints: e.g. friction);
     * - what it gathers at its points: `void gather_fields(const NodeWeights &, const
     *   grid::NodalWorkspace &, Properties &p, bool before_update) const`;
     * - `void update_cell(const particle_iterator_range &, const dealii::Tensor<2, 2> *L,
     *   double dt) const`: the constitutive update of the points of one cell from their
     *   velocity gradients (in the order of the points);
     * - `double wave_speed(const Properties &p) const`: the speed of the fastest wave in
     *   the point's material, for the time step (Eq. 23).
     */
    template <class Model>
    class TransferKernels
    {
    public:
      /** Settings of the cycle that are not the model's. */
      struct Settings
      {
        grid::ShapeFunction shape_function = grid::ShapeFunction::q1;
        /** Nodes with less mass are empty: their velocity is zero. */
        double empty_node_mass = 0.;
        /** Kinematic mode: the nodal velocities are this field (null: off). */
        dealii::FunctionParser<2> *prescribed_velocity = nullptr;
        /** APIC (VelocityTransfer::apic): the index of the affine matrix's first property
         *  (C_xx; C_xy, C_yx, C_yy follow) among the points' properties, which the
         *  workspace's node positions then serve; invalid: the PIC/FLIP blend. */
        unsigned int affine = dealii::numbers::invalid_unsigned_int;
      };

      TransferKernels(const Model                     &model,
                      particles::PointCloud           &cloud,
                      grid::NodalWorkspace            &nodes,
                      const grid::CellPatches         &patches,
                      const grid::VelocityConstraints &constraints,
                      const Settings                  &settings);

      /** Where the parts of the step are timed (null: nowhere). */
      void
      set_timeline(core::StepTimeline *step_timeline)
      {
        timeline = step_timeline;
      }

      /** Nodal mass, momentum and force from the points (Eqs. 14–17; collective). */
      void
      particles_to_grid();

      /** Nodal velocities after and before the step (Eqs. 18–19), with the model's nodal
       *  force and velocity update and the constraints; @p time: the start of the step. */
      void
      update_grid(double dt, double time);

      /** Velocities (PIC/FLIP, Eq. 20, with the step's FLIP fraction @p flip; with APIC
       *  the nodal velocity and its gradient, @p flip unused) and new positions (Eq. 21,
       *  in new_positions()); with @p with_stresses (USL) also the model's update in the
       *  same pass. */
      void
      grid_to_particles(double dt, bool with_stresses, double flip);

      /** MUSL: nodal velocities from the updated particle momenta (with APIC their
       *  affine parts too; collective). */
      void
      remap_velocities_to_grid();

      /** MUSL: the model's update from the re-mapped nodal velocities. */
      void
      update_stresses(double dt);

      /** max_p (c_p + |v_p|) over this rank's points. */
      double
      max_signal_speed() const;

      /** New positions of the points by local index (sized by the caller). */
      std::vector<dealii::Point<2>> &
      new_positions()
      {
        return positions;
      }

    private:
      /** APIC: a point's affine matrix C (xx, xy, yx, yy) and the centre of its lever
       *  arms, x̄ = Σ_k N_k x_k over its nodes @p w: x_p wherever the functions reproduce
       *  linear fields, the centroid of the domain's part on the grid where a GIMP or
       *  B-spline domain is cut by the grid's side. Arms from x̄ sum to zero with the
       *  weights, so the affine part adds no momentum. */
      struct AffinePart
      {
        double           C[4];
        dealii::Point<2> centre;
      };

      template <typename Properties>
      AffinePart
      affine_part(const Properties &p, const grid::NodeWeights &w) const
      {
        AffinePart a;
        for (unsigned int i = 0; i < 4; ++i)
          a.C[i] = p[settings.affine + i];
        for (unsigned int k = 0; k < w.n; ++k)
          a.centre += w.value[k] * nodes.position(w.node[k]);
        return a;
      }

      /** APIC: C (x_I − x̄) of the point's affine part @p a at the node at @p node. */
      static void
      affine_velocity(const AffinePart &a, const dealii::Point<2> &node, double &vx, double &vy)
      {
        const double dx = node[0] - a.centre[0], dy = node[1] - a.centre[1];
        vx = a.C[0] * dx + a.C[1] * dy;
        vy = a.C[2] * dx + a.C[3] * dy;
      }

      template <typename ParticleAccessorType>
      void
      shape_weights(const ParticleAccessorType &particle,
                    unsigned int                cell_index,
                    grid::NodeWeights          &w) const;

      /** Kinematic mode: the nodal velocities at @p time and @p time + @p dt. */
      void
      prescribe_nodal_velocities(double dt, double time);

      void
      lap(const core::StepTimeline::Part part)
      {
        if (timeline)
          timeline->lap(part);
      }

      const Model                     &model;
      particles::PointCloud           &cloud;
      grid::NodalWorkspace            &nodes;
      const grid::CellPatches         &patches;
      const grid::VelocityConstraints &constraints;
      const Settings                   settings;
      core::StepTimeline              *timeline = nullptr;

      /** Side arrays reused every step (no allocation per particle). */
      std::vector<dealii::Point<2>>     positions;
      std::vector<dealii::Tensor<2, 2>> cell_gradients;

      /** Keeps the velocity gradient of the @p k-th point of a cell; the storage grows (by
       *  doubling, so rarely) to the most points a cell has had. */
      void
      store_gradient(const unsigned int k, const dealii::Tensor<2, 2> &L)
      {
        if (k >= cell_gradients.size())
          cell_gradients.resize(2 * k + 16);
        cell_gradients[k] = L;
      }
    };
  } // namespace engine
} // namespace slidewave

#endif
