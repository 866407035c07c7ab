#ifndef slidewave_engine_particle_model_defaults_h
#define slidewave_engine_particle_model_defaults_h

#include <deal.II/base/point.h>
#include <limits>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/shape_functions.h>

namespace slidewave
{
  namespace engine
  {
    /**
     * The optional parts of a particle model of the engine (TransferKernels<Model>), each
     * with a default that does nothing and compiles to nothing: a model derives from this
     * struct and declares again (hides) only what it does. Nothing here is virtual: the
     * kernels call the model's own function, inlined in the point loop.
     *
     * A model's nodal fields are its own: it says how many it has (n_nodal_fields), what
     * each point adds to them (scatter_fields), what to do with them once summed
     * (finish_nodal_fields), how they act at a node in the grid update
     * (update_nodal_velocity) and what the points read back (gather_fields). The engine
     * sums, condenses and exchanges them like the mass, and knows nothing else of them.
     * A model may also see each point at the end of a step (finish_point), move it and
     * split it in two: the engine inserts the new half and moves both to their cells
     * with the others.
     */
    struct ParticleModelDefaults
    {
      /** Whether a point whose nodes are all at rest after the grid update takes their
       *  velocity (zero) whatever the FLIP fraction: for a model whose nodes can be held
       *  by friction, so that a deposit comes to rest exactly. */
      static constexpr bool rests_with_its_nodes = false;
      /** Nodal fields beyond mass, momentum and force: none. */
      static constexpr unsigned int n_nodal_fields = 0;

      /** How many of the nodal fields this run uses (the first ones); all by default. */
      unsigned int
      n_used_nodal_fields() const
      {
        return 0;
      }

      /** The stable step of the explicit scheme for cells of size @p h whose fastest point
       *  carries signals at @p max_speed (paper 000, Eq. 23 with alpha = 1): h / max_speed,
       *  unbounded when nothing moves or carries a wave. The scenes' step is a multiplier
       *  times it, and the FLIP blend is a rate relative to it (ParticleEngine::Settings). */
      double
      stability_limit(const double max_speed, const double h) const
      {
        return max_speed > 0. ? h / max_speed : std::numeric_limits<double>::infinity();
      }

      /** Whether the workspace keeps 1 / the lumped area of each node. */
      bool
      needs_lumped_area() const
      {
        return false;
      }

      /** Adds the point's share (with the shape weight @p N_k) to the fields of its k-th
       *  node, @p sums[f] for field f. */
      template <typename ScatterTerms>
      void
      scatter_fields(const ScatterTerms & /*terms*/, double /*N_k*/, double * /*sums*/) const
      {
      }

      /** After the fields were summed and exchanged (owned nodes hold the totals). */
      void
      finish_nodal_fields(grid::NodalWorkspace & /*nodes*/) const
      {
      }

      /** The force of one component that drives a node of velocity @p v (from its
       *  momentum) under the summed force @p f: f itself. */
      double
      nodal_force_at_node(const double /*v*/, const double f) const
      {
        return f;
      }

      /** After Eqs. 18–19 and the constraints (sides, walls) at a node @p i with mass @p m:
       *  may only scale or reduce the velocity (a held component must stay zero). */
      void
      update_nodal_velocity(const grid::NodalWorkspace & /*nodes*/,
                            unsigned int /*i*/,
                            double /*m*/,
                            double /*dt*/,
                            double & /*vx*/,
                            double & /*vy*/) const
      {
      }

      /** The model's nodal fields at a point with shape weights @p w, into its properties
       *  @p p; @p before_update: the model's update follows in the same pass (USL). */
      template <typename Properties>
      void
      gather_fields(const grid::NodeWeights & /*w*/,
                    const grid::NodalWorkspace & /*nodes*/,
                    Properties & /*p*/,
                    bool /*before_update*/) const
      {
      }

      /** Whether finish_point() is called for every point at the end of a step. */
      bool
      finishes_points() const
      {
        return false;
      }

      /**
       * At the end of a step, before the points move to their new cells, for the point
       * with properties @p p and new position @p x: the model may move @p x (back inside
       * the grid, say) and may split the point in two. It returns whether it splits; if so
       * it makes @p p and @p x one half and @p child and @p child_x the other (it fills
       * every property of @p child). Called only when finishes_points().
       */
      template <typename Properties>
      bool
      finish_point(Properties & /*p*/,
                   dealii::Point<2> & /*x*/,
                   double * /*child*/,
                   dealii::Point<2> & /*child_x*/) const
      {
        return false;
      }
    };
  } // namespace engine
} // namespace slidewave

#endif
