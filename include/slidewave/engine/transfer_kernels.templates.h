#ifndef slidewave_engine_transfer_kernels_templates_h
#define slidewave_engine_transfer_kernels_templates_h

#include <algorithm>
#include <array>
#include <cmath>
#include <slidewave/engine/transfer_kernels.h>
#include <utility>

// The definitions of TransferKernels, included only by the sources of the particle models
// that instantiate it (explicitly, for their model class).

namespace slidewave
{
  namespace engine
  {
    template <class Model>
    TransferKernels<Model>::TransferKernels(const Model                     &model,
                                            particles::PointCloud           &cloud,
                                            grid::NodalWorkspace            &nodes,
                                            const grid::CellPatches         &patches,
                                            const grid::VelocityConstraints &constraints,
                                            const Settings                  &settings)
      : model(model)
      , cloud(cloud)
      , nodes(nodes)
      , patches(patches)
      , constraints(constraints)
      , settings(settings)
    {
    }



    template <class Model>
    template <typename ParticleAccessorType>
    inline void
    TransferKernels<Model>::shape_weights(const ParticleAccessorType &particle,
                                          const unsigned int          cell_index,
                                          grid::NodeWeights          &w) const
    {
      if (settings.shape_function == grid::ShapeFunction::q1)
        {
          const dealii::Point<2> ref = particle.get_reference_location();
          grid::q1_weights(patches.own(cell_index), ref[0], ref[1], w);
        }
      else if (settings.shape_function == grid::ShapeFunction::bspline)
        {
          const dealii::Point<2> x = particle.get_location();
          grid::bspline_weights(patches.begin(cell_index), patches.end(cell_index), x[0], x[1], w);
        }
      else
        {
          const dealii::Point<2> x = particle.get_location();
          const auto             p = particle.get_properties();
          grid::gimp_weights(patches.begin(cell_index),
                             patches.end(cell_index),
                             x[0],
                             x[1],
                             p[Model::domain_half_x],
                             p[Model::domain_half_y],
                             w);
        }
    }



    template <class Model>
    void
    TransferKernels<Model>::particles_to_grid()
    {
      nodes.clear_active_nodes();
      grid::NodeWeights w;
      // Q1 talks to the nodes of the point's cell, GIMP to those of the cell's patch.
      const bool whole_patch = settings.shape_function != grid::ShapeFunction::q1;
      const bool apic        = settings.affine != dealii::numbers::invalid_unsigned_int;
      // The workspace's sums as a plain pointer, taken once: the point loop then indexes
      // it directly instead of going through the workspace on every node. The stride is
      // known at compile time: mass, momentum, force and the model's nodal fields.
      constexpr unsigned int n_sums   = grid::NodalWorkspace::n_base_sums + Model::n_nodal_fields;
      double *const          all_sums = nodes.sums(0);
      cloud.for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        if (whole_patch)
          for (unsigned int e = patches.start(cell_index); e < patches.start(cell_index + 1); ++e)
            for (const unsigned int i : patches.entry(e).node)
              nodes.mark_active(i);
        else
          for (const unsigned int i : patches.own(cell_index).node)
            nodes.mark_active(i);
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            const auto             p     = particle.get_properties();
            const dealii::Point<2> x     = particle.get_location();
            const auto             terms = model.scatter_terms(p, x);
            AffinePart             affine{};
            if (apic)
              affine = affine_part(p, w);
            for (unsigned int k = 0; k < w.n; ++k)
              {
                // Everything read from the weights before anything is written to the
                // sums (the compiler cannot tell that the two do not overlap).
                double      *sums = all_sums + n_sums * w.node[k];
                const double mk   = w.value[k] * terms.m;
                double       fx, fy;
                model.nodal_force(terms, w, k, mk, fx, fy);
                double vx = terms.vx, vy = terms.vy;
                if (apic)
                  {
                    double ax, ay;
                    affine_velocity(affine, nodes.position(w.node[k]), ax, ay);
                    vx += ax;
                    vy += ay;
                  }
                sums[0] += mk;
                sums[1] += mk * vx;
                sums[2] += mk * vy;
                sums[3] += fx;
                sums[4] += fy;
                model.scatter_fields(terms, w.value[k], sums + grid::NodalWorkspace::n_base_sums);
              }
          }
      });
      // Into the distributed vectors (the scratch is left zero for the next step).
      const unsigned int n_fields = nodes.n_fields();
      for (const unsigned int i : nodes.active())
        {
          double *sums                       = nodes.sums(i);
          nodes.nodal_mass.local_element(i)  = sums[0];
          nodes.momentum[0].local_element(i) = sums[1];
          nodes.momentum[1].local_element(i) = sums[2];
          nodes.force[0].local_element(i)    = sums[3];
          nodes.force[1].local_element(i)    = sums[4];
          for (unsigned int f = 0; f < n_fields; ++f)
            nodes.fields[f].local_element(i) = sums[grid::NodalWorkspace::n_base_sums + f];
          std::fill(sums, sums + n_sums, 0.);
        }
      nodes.complete_active_nodes();
      nodes.condense_hanging_nodes(nodes.nodal_mass);
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(nodes.momentum[d]);
          nodes.condense_hanging_nodes(nodes.force[d]);
        }
      for (auto &field : nodes.fields)
        nodes.condense_hanging_nodes(field);
      lap(core::StepTimeline::scatter);
      nodes.nodal_mass.compress(dealii::VectorOperation::add);
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.momentum[d].compress(dealii::VectorOperation::add);
          nodes.force[d].compress(dealii::VectorOperation::add);
        }
      for (auto &field : nodes.fields)
        field.compress(dealii::VectorOperation::add);
      // What the model does with its summed fields (a depth from a volume, ghost values
      // for its gather).
      model.finish_nodal_fields(nodes);
      lap(core::StepTimeline::exchange_sums);
    }



    template <class Model>
    void
    TransferKernels<Model>::update_grid(const double dt, const double time)
    {
      const double tiny         = settings.empty_node_mass;
      auto        &velocity     = nodes.velocity;
      auto        &velocity_old = nodes.velocity_old;
      if (settings.prescribed_velocity != nullptr)
        prescribe_nodal_velocities(dt, time);
      else
        {
          // Ghost entries among the active nodes hold no mass after the compress (their
          // velocities come from their owners below).
          for (const unsigned int i : nodes.active())
            {
              const double m = nodes.nodal_mass.local_element(i);
              for (unsigned int d = 0; d < 2; ++d)
                {
                  if (m > tiny)
                    {
                      const double v = nodes.momentum[d].local_element(i) / m;
                      // The model's own force at the node (a damping of the unbalanced
                      // force), then Eqs. 18-19.
                      const double f
                        = model.nodal_force_at_node(v, nodes.force[d].local_element(i));
                      velocity_old[d].local_element(i) = v;
                      velocity[d].local_element(i)     = v + dt * f / m; // Eqs. 18-19
                    }
                  else
                    {
                      velocity_old[d].local_element(i) = 0.;
                      velocity[d].local_element(i)     = 0.;
                    }
                }
            }
        }
      constraints.apply(velocity[0], velocity[1]);
      constraints.apply(velocity_old[0], velocity_old[1]);
      // What the model does at a node with mass once the walls have taken their share
      // (friction that stops the node but never reverses it): after the constraints, so
      // that a wall's reaction is not counted as motion the friction must stop. A model's
      // hook only scales or reduces the velocity it is given, so a held component stays
      // zero.
      if (settings.prescribed_velocity == nullptr)
        for (const unsigned int i : nodes.active())
          {
            const double m = nodes.nodal_mass.local_element(i);
            if (m > tiny)
              model.update_nodal_velocity(
                nodes, i, m, dt, velocity[0].local_element(i), velocity[1].local_element(i));
          }
      lap(core::StepTimeline::grid_update);
      for (unsigned int d = 0; d < 2; ++d)
        {
          velocity[d].update_ghost_values();
          velocity_old[d].update_ghost_values();
        }
      lap(core::StepTimeline::exchange_velocities);
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.interpolate_hanging_nodes(velocity[d]);
          nodes.interpolate_hanging_nodes(velocity_old[d]);
        }
      // What the gather reads per node, side by side: v^new and v^new - v^old.
      for (const unsigned int i : nodes.active())
        {
          double *v = nodes.velocities(i);
          v[0]      = velocity[0].local_element(i);
          v[1]      = velocity[1].local_element(i);
          v[2]      = v[0] - velocity_old[0].local_element(i);
          v[3]      = v[1] - velocity_old[1].local_element(i);
        }
      lap(core::StepTimeline::grid_update);
    }



    template <class Model>
    void
    TransferKernels<Model>::prescribe_nodal_velocities(const double dt, const double time)
    {
      // Kinematic mode: the field at the node at the start and the end of the step (zero
      // on nodes without mass, as in the dynamic update).
      using Vector         = grid::NodalWorkspace::Vector;
      const double   tiny  = settings.empty_node_mass;
      const unsigned n_own = nodes.nodal_mass.locally_owned_size();
      for (const auto &[when, target] :
           {std::pair<double, std::array<Vector, 2> *>{time, &nodes.velocity_old},
            {time + dt, &nodes.velocity}})
        {
          settings.prescribed_velocity->set_time(when);
          for (unsigned int i = 0; i < n_own; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              (*target)[d].local_element(i)
                = nodes.nodal_mass.local_element(i) > tiny ?
                    settings.prescribed_velocity->value(nodes.position(i), d) :
                    0.;
        }
    }



    template <class Model>
    void
    TransferKernels<Model>::remap_velocities_to_grid()
    {
      if (settings.prescribed_velocity != nullptr)
        return; // the nodal velocities are given
      auto &momentum = nodes.momentum;
      // MUSL: nodal momentum from the updated particle velocities, on the old positions.
      for (const unsigned int i : nodes.active())
        for (unsigned int d = 0; d < 2; ++d)
          momentum[d].local_element(i) = 0.;
      grid::NodeWeights w;
      const bool        apic = settings.affine != dealii::numbers::invalid_unsigned_int;
      cloud.for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            const auto   p  = particle.get_properties();
            const double m  = p[Model::mass];
            const double px = m * p[Model::velocity_x];
            const double py = m * p[Model::velocity_y];
            // With APIC the updated affine part too, about the old position.
            AffinePart affine{};
            if (apic)
              affine = affine_part(p, w);
            for (unsigned int k = 0; k < w.n; ++k)
              {
                double qx = px, qy = py;
                if (apic)
                  {
                    double ax, ay;
                    affine_velocity(affine, nodes.position(w.node[k]), ax, ay);
                    qx += m * ax;
                    qy += m * ay;
                  }
                momentum[0].local_element(w.node[k]) += w.value[k] * qx;
                momentum[1].local_element(w.node[k]) += w.value[k] * qy;
              }
          }
      });
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(momentum[d]);
          momentum[d].compress(dealii::VectorOperation::add);
        }
      const double tiny = settings.empty_node_mass;
      for (const unsigned int i : nodes.active())
        {
          const double m = nodes.nodal_mass.local_element(i);
          for (unsigned int d = 0; d < 2; ++d)
            nodes.velocity[d].local_element(i) = m > tiny ? momentum[d].local_element(i) / m : 0.;
        }
      constraints.apply(nodes.velocity[0], nodes.velocity[1]);
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.velocity[d].update_ghost_values();
          nodes.interpolate_hanging_nodes(nodes.velocity[d]);
        }
    }



    template <class Model>
    void
    TransferKernels<Model>::grid_to_particles(const double dt,
                                              const bool   with_stresses,
                                              const double flip)
    {
      // Velocities (PIC/FLIP, Eq. 20) and new positions (Eq. 21); the positions are
      // kept aside until the stresses have been updated on the old positions. With USL
      // the velocity gradients come from the same nodal velocities, so the stresses are
      // updated in the same pass.
      grid::NodeWeights w;
      const bool        apic      = settings.affine != dealii::numbers::invalid_unsigned_int;
      const bool        kinematic = settings.prescribed_velocity != nullptr;
      // The workspace's velocities as a plain pointer, taken once (see particles_to_grid).
      const double *const all_velocities = nodes.velocities(0);
      cloud.for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        unsigned int       k          = 0;
        for (auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            double               v_new[2] = {0., 0.}, dv[2] = {0., 0.};
            dealii::Tensor<2, 2> L;
            bool                 grid_moves = false;
            for (unsigned int e = 0; e < w.n; ++e)
              {
                const double *v  = all_velocities + grid::NodalWorkspace::n_velocities * w.node[e];
                const double  vx = v[0];
                const double  vy = v[1];
                if constexpr (Model::rests_with_its_nodes)
                  grid_moves = grid_moves || vx != 0. || vy != 0.;
                v_new[0] += w.value[e] * vx;
                v_new[1] += w.value[e] * vy;
                dv[0] += w.value[e] * v[2];
                dv[1] += w.value[e] * v[3];
                L[0][0] += vx * w.grad_x[e];
                L[0][1] += vx * w.grad_y[e];
                L[1][0] += vy * w.grad_x[e];
                L[1][1] += vy * w.grad_y[e];
              }
            auto p = particle.get_properties();
            // The model's nodal fields at the point (before its update, with_stresses).
            model.gather_fields(w, nodes, p, with_stresses);
            // A point whose nodes are all at rest (held by friction) is at rest with them
            // when the model says so: FLIP would keep its departure from their mean. APIC
            // takes the nodal velocity and keeps its gradient. In the kinematic mode the
            // nodal velocities are the prescribed field's, not the points' momentum's: FLIP's
            // increment (the field's change over the step) would leave the points' initial
            // velocities where the field is steady, so they take the field (PIC).
            const double f
              = apic || kinematic || (Model::rests_with_its_nodes && !grid_moves) ? 0. : flip;
            if (apic)
              for (unsigned int i = 0; i < 2; ++i)
                for (unsigned int j = 0; j < 2; ++j)
                  p[settings.affine + 2 * i + j] = L[i][j];
            p[Model::velocity_x] = f * (p[Model::velocity_x] + dv[0]) + (1. - f) * v_new[0];
            p[Model::velocity_y] = f * (p[Model::velocity_y] + dv[1]) + (1. - f) * v_new[1];
            dealii::Point<2> &x  = positions[particle.get_local_index()];
            x = particle.get_location() + dt * dealii::Tensor<1, 2>({v_new[0], v_new[1]});
            cloud.hold_at_closed_sides(x, p[Model::velocity_x], p[Model::velocity_y]);
            if (with_stresses)
              store_gradient(k++, L);
          }
        if (with_stresses)
          model.update_cell(particles_in_cell, cell_gradients.data(), dt);
      });
    }



    template <class Model>
    void
    TransferKernels<Model>::update_stresses(const double dt)
    {
      grid::NodeWeights w;
      cloud.for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        const unsigned int cell_index = cell->active_cell_index();
        unsigned int       k          = 0;
        for (const auto &particle : particles_in_cell)
          {
            shape_weights(particle, cell_index, w);
            dealii::Tensor<2, 2> L;
            for (unsigned int e = 0; e < w.n; ++e)
              {
                const double vx = nodes.velocity[0].local_element(w.node[e]);
                const double vy = nodes.velocity[1].local_element(w.node[e]);
                L[0][0] += vx * w.grad_x[e];
                L[0][1] += vx * w.grad_y[e];
                L[1][0] += vy * w.grad_x[e];
                L[1][1] += vy * w.grad_y[e];
              }
            store_gradient(k++, L);
          }
        model.update_cell(particles_in_cell, cell_gradients.data(), dt);
      });
    }



    template <class Model>
    double
    TransferKernels<Model>::max_signal_speed() const
    {
      double max_speed = 0.;
      for (const auto &particle : cloud.particles())
        {
          const auto   p = particle.get_properties();
          const double c = model.wave_speed(p);
          const double v = std::sqrt(p[Model::velocity_x] * p[Model::velocity_x]
                                     + p[Model::velocity_y] * p[Model::velocity_y]);
          max_speed      = std::max(max_speed, c + v);
        }
      return max_speed;
    }
  } // namespace engine
} // namespace slidewave

#endif
