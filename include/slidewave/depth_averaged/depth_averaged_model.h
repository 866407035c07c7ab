#ifndef slidewave_depth_averaged_depth_averaged_model_h
#define slidewave_depth_averaged_depth_averaged_model_h

#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <memory>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/engine/particle_model_defaults.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/particles/property_layout.h>
#include <slidewave/terrain/elevation_grid.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /** What a column of the depth-averaged flow carries, as indices into its properties. */
    namespace property
    {
      enum Index : unsigned int
      {
        mass,       ///< m_p [kg], fixed (Eq. 17)
        volume,     ///< V_p = m_p / rho = h_p A_p [m^3], fixed (incompressible)
        depth,      ///< h_p [m] (Eq. 38)
        velocity_x, ///< depth-averaged v_p [m/s]
        velocity_y,
        stress_xx, ///< the Bingham stress sigma of Eq. 3 [Pa]
        stress_yy,
        stress_xy,
        effective_stress_xx, ///< sigma^nabla of Eq. 14 [Pa], refreshed for output
        effective_stress_yy,
        effective_stress_xy,
        initial_x, ///< position at t = 0 [m]
        initial_y,
        domain_half_x, ///< GIMP: half-lengths of the point's domain [m]
        domain_half_y,
        width_x, ///< the column's width along x and y, following its stretch [m]
        width_y,
        n_properties
      };
    } // namespace property

    /**
     * The depth-averaged flow of paper 001 as a particle model of the material point
     * engine (TransferKernels<DepthAveragedModel>): each point is a column of material
     * with mass m_p, volume V_p = h_p A_p, depth h_p, depth-averaged velocity and Bingham
     * stress. Its per-point terms:
     *
     * - the nodal force of Eq. 28: -V_p sigma^nabla_p grad N_i (sigma^nabla of Eq. 14, or
     *   its still-level form, Eq. 41) plus rho V_p b_p N_i with b = -g grad Z (or
     *   -g (1 - H/h) grad Z about the still level); with 'Slope correction = bed
     *   normal' g becomes the normal gravity g cos^2 theta and the pressure is the
     *   slope-parallel one projected on the plan view (doc/depth-averaged.md);
     * - the basal resistance A_p tau_b of Voellmy's law (Eq. 2), applied by the engine
     *   at the nodes against the motion (TransferKernels::update_grid);
     * - the update of USL (Eqs. 36–38): the depth h_p / (1 + tr(delta eps_p)) and the
     *   Bingham stress of the new rate (Eqs. 3–9, depth_averaged/bingham.h);
     * - the wave speed sqrt(g h_p) of the time step (Eq. 22 with |v_p| + sqrt(g h_p)).
     *
     * The terrain is a terrain::ElevationGrid: Z and grad Z at a point are one bilinear
     * lookup.
     */
    class DepthAveragedModel : public engine::ParticleModelDefaults
    {
    public:
      static constexpr unsigned int mass          = property::mass;
      static constexpr unsigned int volume        = property::volume;
      static constexpr unsigned int velocity_x    = property::velocity_x;
      static constexpr unsigned int velocity_y    = property::velocity_y;
      static constexpr unsigned int domain_half_x = property::domain_half_x;
      static constexpr unsigned int domain_half_y = property::domain_half_y;
      static constexpr unsigned int depth         = property::depth;
      /** Columns on nodes that friction holds are at rest, with FLIP too. */
      static constexpr bool rests_with_its_nodes = true;
      /**
       * The model's nodal fields: the basal resistance (the largest force Voellmy's
       * friction can exert at the node [N], applied in the grid update) and, with 'Depth
       * update = projection', the columns' volume, divided by the node's lumped area into
       * the depth the columns give the node (read back by the points).
       */
      enum NodalField : unsigned int
      {
        resistance_field,
        depth_field,
      };
      static constexpr unsigned int n_nodal_fields = 2;

      bool
      projects_depth() const
      {
        return project_depth;
      }

      /** The resistance always; the depth only when it is projected. */
      unsigned int
      n_used_nodal_fields() const
      {
        return project_depth ? 2 : 1;
      }

      /** The depth is a volume over the node's lumped area. */
      bool
      needs_lumped_area() const
      {
        return project_depth;
      }

      using ParticleRange = dealii::Particles::ParticleHandler<2>::particle_iterator_range;

      DepthAveragedModel(const DepthAveragedParameters &parameters,
                         const terrain::ElevationGrid  &terrain);

      const particles::PropertyLayout &
      layout() const
      {
        return property_layout;
      }

      const terrain::ElevationGrid &
      terrain() const
      {
        return elevation;
      }

      /** What a point scatters (Eqs. 27–28), read once per point. */
      struct ScatterTerms
      {
        double m, vx, vy, V;
        /** sigma^nabla (Eq. 14, or about the still level, Eq. 41). */
        double sxx, syy, sxy;
        /** The body force per unit mass. */
        double bx, by;
        /** A_p tau_b, the basal friction force the column can exert (Eq. 2). */
        double resistance;
      };

      template <typename Properties>
      ScatterTerms
      scatter_terms(const Properties &p, const dealii::Point<2> &x) const
      {
        const double         h = p[property::depth];
        dealii::Tensor<1, 2> grad_z;
        const double         z = elevation.value_and_gradient(x, grad_z);
        // The pressure and the weight's slope term (Eqs. 14-15), or both about the still
        // level H (Eq. 41): 1/2 rho g (h^2 - H^2) / h and -g (1 - H / h) grad Z.
        double pressure = half_rho_g * h, slope = g;
        if (still_level_form)
          {
            const double H = std::max(still_level - z, 0.);
            // (h - H)(h + H) / h: exactly zero when h = H.
            pressure = half_rho_g * (h - H) * (h + H) / h;
            slope    = g * (1. - H / h);
          }
        const double vx = p[property::velocity_x], vy = p[property::velocity_y];
        const double zx = grad_z[0], zy = grad_z[1];
        // The slope correction (issue 28; doc/depth-averaged.md, "Slope correction"): the
        // slope-parallel shallow-layer equations (Savage-Hutter; Mangeney et al. 2000)
        // projected on the plan view, i.e. the weight on the bed through the normal
        // gravity g cos^2 theta (the basal normal stress rho g h cos^2 theta of Denlinger
        // and Iverson 2004 on a plane), cos^2 theta = 1 / (1 + |grad Z|^2) at the column;
        // the column moves along the bed with the vertical velocity v . grad Z; the
        // friction per unit of bed area is projected on the plan view with the factor
        // |v| / (|v_bed| cos theta) (1 down the fall line). On flat ground every factor
        // is exactly 1. Paper 001 ('none'): all 1.
        double normal = 1., projection = 1.;
        double speed_squared = vx * vx + vy * vy;
        if (bed_normal)
          {
            normal                    = 1. / (1. + zx * zx + zy * zy);
            const double vertical     = vx * zx + vy * zy;
            const double plan_squared = speed_squared;
            speed_squared += vertical * vertical;
            if (plan_squared > 0.)
              projection = std::sqrt(plan_squared / (normal * speed_squared));
            pressure *= normal;
            slope *= normal;
          }
        double resistance = 0.;
        if (friction)
          {
            // Voellmy (Eq. 2) on the column's area A_p = V_p / h_p, with the normal stress
            // rho g h cos^2 theta and the speed along the bed when corrected.
            resistance = p[property::volume] / h * projection
                         * ((atmospheric_pressure + rho_g * normal * h) * tan_phi
                            + rho_g_over_xi * speed_squared);
          }
        double sxx = p[property::stress_xx] - pressure, syy = p[property::stress_yy] - pressure,
               sxy = p[property::stress_xy];
        if (bed_normal)
          {
            // The slope-parallel pressure projected on the plan view: a further
            // cos^2 theta along the fall line, pressure (1 - cos^2 theta grad Z grad Z^T).
            const double k = pressure * normal;
            sxx += k * zx * zx;
            syy += k * zy * zy;
            sxy += k * zx * zy;
          }
        return {p[property::mass],
                vx,
                vy,
                p[property::volume],
                sxx,
                syy,
                sxy,
                -slope * zx,
                -slope * zy,
                resistance};
      }

      /** The point's force on its k-th node (Eq. 28 without the friction): the internal
       *  force -V_p sigma^nabla grad N and the weight's slope term m N b. */
      void
      nodal_force(const ScatterTerms      &t,
                  const grid::NodeWeights &w,
                  const unsigned int       k,
                  const double             mk,
                  double                  &fx,
                  double                  &fy) const
      {
        fx = -t.V * (t.sxx * w.grad_x[k] + t.sxy * w.grad_y[k]) + mk * t.bx;
        fy = -t.V * (t.sxy * w.grad_x[k] + t.syy * w.grad_y[k]) + mk * t.by;
      }

      /** The column's basal resistance A_p tau_b and, when the depth is projected, its
       *  volume V_p, to its k-th node with weight @p N_k. */
      void
      scatter_fields(const ScatterTerms &t, const double N_k, double *sums) const
      {
        sums[resistance_field] += N_k * t.resistance;
        if (project_depth)
          sums[depth_field] += N_k * t.V;
      }

      /** The projected volume over the nodes' lumped area: the depth the columns give each
       *  node, read by the gather at owned and ghost nodes. */
      void
      finish_nodal_fields(grid::NodalWorkspace &nodes) const;

      /**
       * Voellmy's friction as a nodal force of at most R_i opposing the motion the node
       * would have without it: it takes |v| dt R_i / m off the speed, down to zero, never
       * past it. So friction stops a node but cannot reverse it, and a node at rest stays
       * there while the other forces stay below R_i (static friction). Called after the
       * sides and walls have removed their normal components (issue 28): a wall's
       * reaction is not motion, so it must not use up the friction (applied before, the
       * lateral push of the depth on a wall made a slab at rest on a slope creep along it).
       */
      void
      update_nodal_velocity(const grid::NodalWorkspace &nodes,
                            const unsigned int          i,
                            const double                m,
                            const double                dt,
                            double                     &vx_node,
                            double                     &vy_node) const
      {
        const double vx    = vx_node;
        const double vy    = vy_node;
        const double speed = std::sqrt(vx * vx + vy * vy);
        const double loss  = dt * nodes.fields[resistance_field].local_element(i) / m;
        const double scale = speed > loss ? 1. - loss / speed : 0.;
        vx_node            = scale * vx;
        vy_node            = scale * vy;
      }

      /** With the projected depth, before the update: the depth the columns around give
       *  the point at the start of the step; the update then adds the step's own change. */
      template <typename Properties>
      void
      gather_fields(const grid::NodeWeights    &w,
                    const grid::NodalWorkspace &nodes,
                    Properties                 &p,
                    const bool                  before_update) const
      {
        if (project_depth && before_update)
          {
            const auto &depth = nodes.fields[depth_field];
            double      h     = 0.;
            for (unsigned int e = 0; e < w.n; ++e)
              h += w.value[e] * depth.local_element(w.node[e]);
            p[property::depth] = h;
          }
      }

      /** USL (Eqs. 36–38): new depths and Bingham stresses of the points of one cell. */
      void
      update_cell(const ParticleRange        &particles_in_cell,
                  const dealii::Tensor<2, 2> *L,
                  double                      dt) const;

      /** With 'Split stretch' > 0: the splitting (finish_point). The walls hold the
       *  columns in the engine's gather (particles::PointCloud::hold_at_closed_sides). */
      bool
      finishes_points() const
      {
        return split_width > 0.;
      }

      /**
       * The end of a column's step (the engine's hook, before the columns move to their
       * cells): split_point() when 'Split stretch' > 0.
       */
      template <typename Properties>
      bool
      finish_point(Properties       &p,
                   dealii::Point<2> &x,
                   double           *child,
                   dealii::Point<2> &child_x) const
      {
        return split_width > 0. && split_point(p, x, child, child_x);
      }

      template <typename Properties>
      bool
      split_point(Properties       &p,
                  dealii::Point<2> &x,
                  double           *child,
                  dealii::Point<2> &child_x) const
      {
        const double       wx = p[property::width_x], wy = p[property::width_y];
        const unsigned int d     = wx >= wy ? 0 : 1;
        const double       width = d == 0 ? wx : wy;
        if (width <= split_width)
          return false;
        // The halves, and their shape functions' domains, stay inside the grid.
        const unsigned int w     = d == 0 ? property::width_x : property::width_y;
        const unsigned int half  = d == 0 ? property::domain_half_x : property::domain_half_y;
        const double       shift = 0.25 * width;
        const double       reach = shift + std::max(shift, p[half]);
        if (x[d] - reach < prm.lower_left[d] || x[d] + reach > prm.upper_right[d])
          return false;
        for (unsigned int k = 0; k < property::n_properties; ++k)
          child[k] = p[k];
        child_x = x;
        x[d] -= shift;
        child_x[d] += shift;
        for (const unsigned int k : {static_cast<unsigned int>(property::mass),
                                     static_cast<unsigned int>(property::volume),
                                     w})
          {
            p[k] *= 0.5;
            child[k] = p[k];
          }
        // 'cpgimp': the domain is half the column's width, at most half a cell.
        if (prm.shape_function == grid::ShapeFunction::cpgimp)
          {
            p[half]     = std::min(p[half], 0.25 * width);
            child[half] = p[half];
          }
        return true;
      }

      /** sqrt(g h_p), the speed of gravity waves in the column. */
      template <typename Properties>
      double
      wave_speed(const Properties &p) const
      {
        return std::sqrt(g * std::max(p[property::depth], 0.));
      }

      /** Nodes with less mass than this are empty. */
      double
      empty_node_mass() const;

      /** The stable step: Eq. 22's h / max_speed (max_speed = max_p (|v_p| + sqrt(g h_p)))
       *  and the viscous limit of an explicit step (the engine's stability_limit()). */
      double
      stability_limit(double max_speed, double h) const;

      /** The properties of a new point at @p position in a cell hx x hy, of depth @p h
       *  and velocity @p v (the release's there); false where there is no material
       *  (h <= 0). */
      bool
      fill_new_point(std::vector<double>        &properties,
                     const dealii::Point<2>     &position,
                     double                      h,
                     const dealii::Tensor<1, 2> &v,
                     double                      hx,
                     double                      hy) const;

      /** sigma^nabla of every point, for output (Eq. 14 or 41). */
      void
      refresh_effective_stress(particles::PointCloud &cloud) const;

      /** Integral quantities, reduced over all ranks (collective). */
      struct Integrals
      {
        double       mass = 0., lost_mass = 0., momentum_x = 0., momentum_y = 0.;
        double       kinetic_energy = 0., potential_energy = 0.;
        double       max_speed = 0., max_depth = 0., max_travel = 0.;
        double       centroid_x = 0., centroid_y = 0.;
        double       x_min = 0., x_max = 0., y_min = 0., y_max = 0.;
        double       covered_area = 0.;
        unsigned int n_particles  = 0;
      };

      Integrals
      integrals(const particles::PointCloud &cloud) const;

      /** L1 (sum over the points of |e| A_p) and L-infinity norms of the errors of h, h u
       *  and h v against material at rest with depth @p exact_depth(x) (collective). */
      struct StillStateErrors
      {
        double l1[3]   = {0., 0., 0.};
        double linf[3] = {0., 0., 0.};
      };

      StillStateErrors
      still_state_errors(const particles::PointCloud                           &cloud,
                         const std::function<double(const dealii::Point<2> &)> &exact_depth) const;

      /** The columns against a rigid translation (collective): the relative L1 error of
       *  their depth, sum_p |h_p - h_p0| A_p0 / sum_p h_p0 A_p0, with h_p0 =
       *  @p initial_depth(x_p0) the release's depth where the column started and
       *  A_p0 = V_p / h_p0 its area (so a column that split counts with its half); the
       *  largest |h_p - h_p0| / h_p0; and the largest distance of a column from
       *  x_p0 + v_p0 t, v_p0 = @p initial_velocity(x_p0). */
      struct TranslationErrors
      {
        double depth_l1 = 0., depth_max = 0., position_max = 0.;
      };

      TranslationErrors
      translation_errors(
        const particles::PointCloud                                         &cloud,
        double                                                               t,
        const std::function<dealii::Tensor<1, 2>(const dealii::Point<2> &)> &initial_velocity,
        const std::function<double(const dealii::Point<2> &)>               &initial_depth) const;

      /**
       * A description of the first point with a non-finite state or a depth that is not
       * positive, on any rank, or "" (collective).
       */
      std::string
      find_invalid_particle(const particles::PointCloud &cloud) const;

      /** "material point ID at (x y) with speed S m/s and depth h m" for the fastest
       *  point (collective). */
      std::string
      describe_fastest_particle(const particles::PointCloud &cloud) const;

    private:
      const DepthAveragedParameters &prm;
      const terrain::ElevationGrid  &elevation;
      particles::PropertyLayout      property_layout;

      // Constants of the per-point terms, computed once.
      const double g, half_rho_g, rho_g;
      const bool   still_level_form;
      const double still_level;
      const bool   friction;
      const double tan_phi, rho_g_over_xi, atmospheric_pressure;
      /** 'Depth update = projection'. */
      const bool project_depth;
      /** 'Slope correction = bed normal'. */
      const bool bed_normal;
      /** 'Split stretch' times the columns' initial width, the cell over the columns per
       *  direction (0: no splitting). */
      const double split_width;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
