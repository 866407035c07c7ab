#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <limits>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/fluid/free_surface_diagnostics.h>
#include <slidewave/grid/tree_order.h>

namespace slidewave
{
  namespace fluid
  {
    namespace diagnostics
    {
      namespace
      {
        /** phi at the four vertices of @p cell (deal.II's order: (x0,y0), (x1,y0),
         *  (x0,y1), (x1,y1)). */
        template <class Cell>
        std::array<double, 4>
        corner_values(const Cell &cell, const grid::FiniteElementField &phase)
        {
          std::array<double, 4> phi;
          for (unsigned int v = 0; v < 4; ++v)
            phi[v] = phase.values(0)[cell->vertex_dof_index(v, 0)];
          return phi;
        }

        /** The domain's lower left corner, from the coarse cells every rank holds (no
         *  pass over the active cells, no communication). */
        dealii::Point<2>
        lower_left(const dealii::Triangulation<2> &tria)
        {
          dealii::Point<2> corner(std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::max());
          for (auto cell = tria.begin(0); cell != tria.end(0); ++cell)
            for (unsigned int d = 0; d < 2; ++d)
              corner[d] = std::min(corner[d], cell->vertex(0)[d]);
          return corner;
        }

        /** Where the linear function from (a, fa) to (b, fb) crosses 0.5. */
        double
        crossing(const double a, const double fa, const double b, const double fb)
        {
          return a + (0.5 - fa) / (fb - fa) * (b - a);
        }
      } // namespace



      double
      front_position(const grid::FiniteElementField &phase)
      {
        const auto            &tria   = phase.dof_handler().get_triangulation();
        const dealii::Point<2> corner = lower_left(tria);
        const double           low    = corner[1];
        double                 front  = -std::numeric_limits<double>::max();
        for (const auto &cell : phase.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              if (std::abs(cell->vertex(0)[1] - low) > 1e-9 * cell->extent_in_direction(0))
                continue;
              const auto   phi = corner_values(cell, phase);
              const double x0 = cell->vertex(0)[0], x1 = cell->vertex(1)[0];
              if (phi[0] >= 0.5 && phi[1] >= 0.5)
                front = std::max(front, x1);
              else if (phi[0] >= 0.5)
                front = std::max(front, crossing(x0, phi[0], x1, phi[1]));
              else if (phi[1] >= 0.5)
                front = std::max(front, x1);
            }
        front = dealii::Utilities::MPI::max(front, tria.get_communicator());
        return front > -std::numeric_limits<double>::max() ? front : corner[0];
      }



      double
      surface_elevation(const grid::FiniteElementField &phase, const double x)
      {
        const auto &tria      = phase.dof_handler().get_triangulation();
        double      elevation = -std::numeric_limits<double>::max();
        for (const auto &cell : phase.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double x0 = cell->vertex(0)[0], x1 = cell->vertex(1)[0];
              if (x < x0 || x > x1)
                continue;
              // Along the vertical line x the bilinear phi is linear in y.
              const auto   phi = corner_values(cell, phase);
              const double s   = (x - x0) / (x1 - x0);
              const double low = (1. - s) * phi[0] + s * phi[1];
              const double up  = (1. - s) * phi[2] + s * phi[3];
              const double y0 = cell->vertex(0)[1], y1 = cell->vertex(2)[1];
              if (low >= 0.5 && up < 0.5)
                elevation = std::max(elevation, crossing(y0, low, y1, up));
              else if (low >= 0.5 && up >= 0.5)
                elevation = std::max(elevation, y1);
            }
        elevation = dealii::Utilities::MPI::max(elevation, tria.get_communicator());
        return elevation > -std::numeric_limits<double>::max() ? elevation : lower_left(tria)[1];
      }



      double
      pressure_at(const grid::FiniteElementField &flow, const dealii::Point<2> &point)
      {
        // The grid's cells are axis-aligned rectangles: the point's reference coordinates
        // are its place in the cell, and the pressure (component 2) is the sum of the
        // cell's pressure dofs times their shape functions there (Q1 or Q2). A point on the
        // grid's edge may lie an ulp outside the last cell: a relative tolerance, clamped.
        const auto                                  &fe     = flow.finite_element();
        const auto                                  &values = flow.values(0);
        std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::array<double, 2>                        sum_and_count = {{0., 0.}};
        for (const auto &cell : flow.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const dealii::Point<2> &a = cell->vertex(0), &b = cell->vertex(3);
              const double            tolerance = 1e-10 * (b[0] - a[0]);
              if (point[0] < a[0] - tolerance || point[0] > b[0] + tolerance
                  || point[1] < a[1] - tolerance || point[1] > b[1] + tolerance)
                continue;
              dealii::Point<2> unit;
              for (unsigned int d = 0; d < 2; ++d)
                unit[d] = std::clamp((point[d] - a[d]) / (b[d] - a[d]), 0., 1.);
              cell->get_dof_indices(dofs);
              double p = 0.;
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fe.system_to_component_index(i).first == 2)
                  p += values[dofs[i]] * fe.shape_value(i, unit);
              sum_and_count[0] += p;
              sum_and_count[1] += 1.;
              break; // a rank's first cell: on an edge its neighbour gives the same value
            }
        dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sum_and_count),
                                    flow.dof_handler().get_communicator(),
                                    dealii::ArrayView<double>(sum_and_count));
        return sum_and_count[1] > 0. ? sum_and_count[0] / sum_and_count[1] :
                                       std::numeric_limits<double>::quiet_NaN();
      }



      std::vector<std::array<double, 4>>
      surface_segments(const grid::FiniteElementField &phase)
      {
        std::vector<std::array<double, 4>> mine;
        for (const auto &cell : phase.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const auto phi = corner_values(cell, phase);
              // The edges counter-clockwise: bottom, right, top, left, each as two
              // vertex indices.
              const std::array<std::array<unsigned int, 2>, 4> edges{
                {{{0, 1}}, {{1, 3}}, {{3, 2}}, {{2, 0}}}};
              std::vector<dealii::Point<2>> points;
              for (const auto &e : edges)
                {
                  const double fa = phi[e[0]], fb = phi[e[1]];
                  if ((fa >= 0.5) == (fb >= 0.5))
                    continue;
                  const auto   a = cell->vertex(e[0]), b = cell->vertex(e[1]);
                  const double t = (0.5 - fa) / (fb - fa);
                  points.push_back(a + t * (b - a));
                }
              if (points.size() == 2)
                mine.push_back({{points[0][0], points[0][1], points[1][0], points[1][1]}});
              else if (points.size() == 4)
                {
                  // A saddle: the centre value decides which crossings belong together.
                  const double       centre            = 0.25 * (phi[0] + phi[1] + phi[2] + phi[3]);
                  const bool         first_with_second = (centre >= 0.5) == (phi[0] >= 0.5);
                  const unsigned int a = 0, b = first_with_second ? 3 : 1;
                  const unsigned int c = first_with_second ? 1 : 2, d = first_with_second ? 2 : 3;
                  mine.push_back({{points[a][0], points[a][1], points[b][0], points[b][1]}});
                  mine.push_back({{points[c][0], points[c][1], points[d][0], points[d][1]}});
                }
            }
        const auto all = dealii::Utilities::MPI::gather(
          phase.dof_handler().get_triangulation().get_communicator(), mine, 0);
        std::vector<std::array<double, 4>> segments;
        for (const auto &part : all)
          segments.insert(segments.end(), part.begin(), part.end());
        std::sort(segments.begin(), segments.end());
        return segments;
      }



      double
      kinetic_energy(const grid::FiniteElementField &flow,
                     const grid::FiniteElementField &phase,
                     const FluidProperties          &fluid)
      {
        const dealii::QGauss<2> quadrature(flow.finite_element().degree + 1);
        dealii::FEValues<2>     fv(flow.finite_element(),
                               quadrature,
                               dealii::update_values | dealii::update_JxW_values);
        dealii::FEValues<2>     fv_phase(phase.finite_element(), quadrature, dealii::update_values);
        const dealii::FEValuesExtractors::Vector velocity(0);
        std::vector<dealii::Tensor<1, 2>>        u(quadrature.size());
        std::vector<double>                      phi(quadrature.size());
        double                                   energy = 0.;
        grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
          fv.reinit(cell);
          fv_phase.reinit(phase.cell_on(cell));
          fv[velocity].get_function_values(flow.values(0), u);
          fv_phase.get_function_values(phase.values(0), phi);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            energy += 0.5 * fluid.density(phi[q]) * u[q].norm_square() * fv.JxW(q);
        });
        return dealii::Utilities::MPI::sum(energy, flow.dof_handler().get_communicator());
      }



      std::array<double, 2>
      hydrostatic_errors(const grid::FiniteElementField &flow,
                         const FreeSurfaceParameters    &parameters)
      {
        const ParsedExpression eta("Free surface flow/Initial water/Surface elevation",
                                   parameters.surface_elevation);
        const auto            &fluid   = parameters.fluid;
        const double           g       = fluid.gravity.norm();
        const double           epsilon = parameters.interface_thickness();
        const double           top     = parameters.upper_right[1];
        // ln(1 + e^a) without overflow.
        const auto softplus = [](const double a) {
          return a > 0. ? a + std::log1p(std::exp(-a)) : std::log1p(std::exp(a));
        };
        const auto &values = flow.values(0);
        double      error = 0., deepest = 0., fastest = 0.;
        for (const auto &cell : flow.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                const auto   x       = cell->vertex(v);
                const double surface = eta.value(x[0]);
                const double ux      = values[cell->vertex_dof_index(v, 0)];
                const double uy      = values[cell->vertex_dof_index(v, 1)];
                fastest              = std::max(fastest, std::sqrt(ux * ux + uy * uy));
                deepest              = std::max(deepest, surface - x[1]);
                // The weight of the column above the node with the model's density
                // rho(phi) of the equilibrium profile phi = 1 / (1 + exp(-(eta - y) /
                // epsilon)): the integral of phi from y to the top is
                // epsilon (ln(1 + e^{(eta - y)/epsilon}) - ln(1 + e^{(eta - top)/epsilon})).
                const double water_column
                  = epsilon
                    * (softplus((surface - x[1]) / epsilon) - softplus((surface - top) / epsilon));
                const double exact = g
                                     * (fluid.air_density * (top - x[1])
                                        + (fluid.water_density - fluid.air_density) * water_column);
                error = std::max(error, std::abs(values[cell->vertex_dof_index(v, 2)] - exact));
              }
        const MPI_Comm communicator = flow.dof_handler().get_communicator();
        error                       = dealii::Utilities::MPI::max(error, communicator);
        deepest                     = dealii::Utilities::MPI::max(deepest, communicator);
        fastest                     = dealii::Utilities::MPI::max(fastest, communicator);
        const double scale          = fluid.water_density * g * deepest;
        return {{scale > 0. ? error / scale : error, fastest}};
      }



      double
      poiseuille_error(const grid::FiniteElementField &flow,
                       const FreeSurfaceParameters    &parameters)
      {
        const double y0   = parameters.lower_left[1];
        const double H    = parameters.upper_right[1] - y0;
        const double nu   = parameters.fluid.water_viscosity / parameters.fluid.water_density;
        const double gx   = parameters.fluid.gravity[0];
        const double peak = std::abs(gx) * H * H / (8. * nu);
        // The open ends hold the shear traction at zero (the symmetric-gradient form of
        // the viscous stress), which the parabola does not: the flow is compared at least
        // two channel heights away from them.
        const double x_low  = parameters.lower_left[0] + 2. * H;
        const double x_high = parameters.upper_right[0] - 2. * H;
        const auto  &values = flow.values(0);
        double       error  = 0.;
        for (const auto &cell : flow.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                if (cell->vertex(v)[0] < x_low - 1e-12 || cell->vertex(v)[0] > x_high + 1e-12)
                  continue;
                const double y     = cell->vertex(v)[1] - y0;
                const double exact = gx * y * (H - y) / (2. * nu);
                error = std::max(error, std::abs(values[cell->vertex_dof_index(v, 0)] - exact));
              }
        error = dealii::Utilities::MPI::max(error, flow.dof_handler().get_communicator());
        return peak > 0. ? error / peak : error;
      }



      double
      darcy_error(const grid::FiniteElementField &flow, const FreeSurfaceParameters &parameters)
      {
        const dealii::Point<2> centre = 0.5 * (parameters.lower_left + parameters.upper_right);
        const double           n      = evaluate_xy("Porosity", parameters.porosity, centre);
        const double           kappa = evaluate_xy("Permeability", parameters.permeability, centre);
        const auto            &fluid = parameters.fluid;
        const double           exact
          = fluid.water_density * fluid.gravity[0] * kappa / (n * fluid.water_viscosity);
        const auto &values = flow.values(0);
        double      error  = 0.;
        for (const auto &cell : flow.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              error = std::max(error, std::abs(values[cell->vertex_dof_index(v, 0)] - exact));
        error = dealii::Utilities::MPI::max(error, flow.dof_handler().get_communicator());
        return exact != 0. ? error / std::abs(exact) : error;
      }



      double
      taylor_green_error(const grid::FiniteElementField &flow,
                         const FreeSurfaceParameters    &parameters,
                         const double                    time)
      {
        // u = U (sin k x' cos k y', -cos k x' sin k y') exp(-2 nu k^2 t), x' = x - x0,
        // k = pi / L: free slip on the four sides of the square holds it exactly (u . n
        // and the shear vanish there). U from the initial field at (x0 + L/2, y0).
        const dealii::Point<2> origin = parameters.lower_left;
        const double           k      = M_PI / (parameters.upper_right[0] - origin[0]);
        const double nu = parameters.fluid.water_viscosity / parameters.fluid.water_density;
        dealii::FunctionParser<2> initial(2);
        initial.initialize("x,y", parameters.initial_velocity, {});
        const double U = initial.value(origin + dealii::Point<2>(0.5 * M_PI / k, 0.), 0)
                         * std::exp(-2. * nu * k * k * time);

        const dealii::QGauss<2>                  quadrature(flow.finite_element().degree + 2);
        const dealii::FEValuesExtractors::Vector velocity(0);
        dealii::FEValues<2>                      fv(flow.finite_element(),
                               quadrature,
                               dealii::update_values | dealii::update_quadrature_points
                                 | dealii::update_JxW_values);
        std::vector<dealii::Tensor<1, 2>>        u(quadrature.size());
        double                                   error = 0., norm = 0.;
        grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
          fv.reinit(cell);
          fv[velocity].get_function_values(flow.values(0), u);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const dealii::Tensor<1, 2> p = fv.quadrature_point(q) - origin;
              const dealii::Tensor<1, 2> exact({U * std::sin(k * p[0]) * std::cos(k * p[1]),
                                                -U * std::cos(k * p[0]) * std::sin(k * p[1])});
              error += (u[q] - exact).norm_square() * fv.JxW(q);
              norm += exact.norm_square() * fv.JxW(q);
            }
        });
        const MPI_Comm communicator = flow.dof_handler().get_communicator();
        error                       = dealii::Utilities::MPI::sum(error, communicator);
        norm                        = dealii::Utilities::MPI::sum(norm, communicator);
        return norm > 0. ? std::sqrt(error / norm) : std::sqrt(error);
      }
    } // namespace diagnostics
  }   // namespace fluid
} // namespace slidewave
