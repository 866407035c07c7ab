#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <limits>
#include <map>
#include <slidewave/core/input_error.h>
#include <slidewave/granular/drag_law.h>
#include <slidewave/granular/granular_verification.h>
#include <slidewave/granular/terzaghi.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/soil/particle_properties.h>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** Terzaghi's pore pressure profiles, a row per height at each time factor. */
      const std::string profile_file_name = "terzaghi_profiles.csv";

      bool
      is_root()
      {
        return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }

      /** Calls @p f(y, p) for the pressure dofs of every owned cell of @p flow (a node
       *  shared by cells is visited once per cell: the callers take maxima). */
      template <class Function>
      void
      for_each_pressure_node(const grid::FiniteElementField &flow, const Function &f)
      {
        const auto                                  &fe = flow.finite_element();
        std::vector<dealii::types::global_dof_index> indices(fe.n_dofs_per_cell());
        // (in the tree's order: the least squares' sums repeat in a resumed run)
        grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
          cell->get_dof_indices(indices);
          for (unsigned int k = 0; k < indices.size(); ++k)
            if (fe.system_to_component_index(k).first == 2)
              f(cell->vertex(fe.system_to_component_index(k).second)[1],
                flow.values(0)[indices[k]]);
        });
      }
    } // namespace



    GranularVerification::GranularVerification(const SceneParameters               &scene,
                                               const soil::MaterialPointParameters &soil_parameters,
                                               const fluid::FreeSurfaceParameters &fluid_parameters,
                                               const GranularWaterParameters      &parameters)
      : scene(scene)
      , soil_parameters(soil_parameters)
      , fluid_parameters(fluid_parameters)
      , parameters(parameters)
    {
    }



    void
    GranularVerification::open_files(const bool append)
    {
      if (parameters.exact_solution != GranularExactSolution::terzaghi || !is_root())
        return;
      const std::string file = scene.output_directory + "/" + profile_file_name;
      profile_file = std::make_unique<std::ofstream>(file, append ? std::ios::app : std::ios::out);
      require_written(*profile_file, file);
      profile_file->precision(10);
      if (!append)
        *profile_file << "time_factor,time,y,pore_pressure,exact\n";
    }



    std::vector<std::string>
    GranularVerification::growing_files() const
    {
      if (parameters.exact_solution != GranularExactSolution::terzaghi)
        return {};
      return {profile_file_name};
    }



    double
    GranularVerification::time_factor(const double t) const
    {
      const auto  &material = soil_parameters.materials[0];
      const double c_v      = consolidation_coefficient(material.youngs_modulus,
                                                   material.poisson_ratio,
                                                   parameters.permeability,
                                                   fluid_parameters.fluid.water_viscosity);
      const double H        = parameters.column_height;
      return c_v * (t - scene.start_time) / (H * H);
    }



    void
    GranularVerification::after_step(const double time, const grid::FiniteElementField &flow)
    {
      if (parameters.exact_solution != GranularExactSolution::terzaghi)
        return;
      while (profiles.size() < parameters.time_factors.size()
             && time_factor(time) >= parameters.time_factors[profiles.size()] * (1. - 1e-12))
        {
          std::vector<double> samples;
          const auto          e  = terzaghi_errors(flow, time, &samples);
          const double        tv = time_factor(time);
          profiles.push_back({{tv, e[0], e[1], terzaghi_average_degree(tv)}});
          write_profile(tv, time, samples);
        }
    }



    std::array<double, 2>
    GranularVerification::terzaghi_errors(const grid::FiniteElementField &flow,
                                          const double                    time,
                                          std::vector<double>            *samples) const
    {
      const double H       = parameters.column_height;
      const double base    = fluid_parameters.lower_left[1];
      const double p0      = parameters.top_load;
      const double tv      = time_factor(time);
      double       largest = 0.;
      for_each_pressure_node(flow, [&](const double y, const double p) {
        if (y > base + H)
          return;
        const double exact = p0 * terzaghi_pore_pressure((base + H - y) / H, tv);
        largest            = std::max(largest, std::abs(p - exact) / p0);
        if (samples)
          samples->insert(samples->end(), {y, p, exact});
      });
      // U from the pore pressure: 1 - its integral over the column / (p0 area).
      const dealii::QGauss<2>                  quadrature(2);
      dealii::FEValues<2>                      fv(flow.finite_element(),
                             quadrature,
                             dealii::update_values | dealii::update_JxW_values);
      const dealii::FEValuesExtractors::Scalar pressure(2);
      std::vector<double>                      p(quadrature.size());
      double                                   integral = 0., area = 0.;
      grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
        if (cell->center()[1] >= base + H)
          return;
        fv.reinit(cell);
        fv[pressure].get_function_values(flow.values(0), p);
        for (unsigned int q = 0; q < p.size(); ++q)
          {
            integral += p[q] * fv.JxW(q);
            area += fv.JxW(q);
          }
      });
      largest  = dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
      integral = dealii::Utilities::MPI::sum(integral, MPI_COMM_WORLD);
      area     = dealii::Utilities::MPI::sum(area, MPI_COMM_WORLD);
      return {{largest, 1. - integral / (p0 * area)}};
    }



    void
    GranularVerification::write_profile(const double               tv,
                                        const double               time,
                                        const std::vector<double> &samples) const
    {
      // Every node's (y, p, exact) on rank 0, sorted by height and averaged over each row
      // of nodes (the nodes of a row share one exact value).
      const auto all = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, samples, 0);
      if (!profile_file)
        return;
      std::map<long long, std::array<double, 4>> rows; // y / h rounded: sum y, p, exact, count
      const double                               h = fluid_parameters.cell_size;
      for (const auto &part : all)
        for (std::size_t k = 0; k + 2 < part.size(); k += 3)
          {
            auto &row = rows[std::llround(part[k] / h * 1e3)];
            row[0] += part[k];
            row[1] += part[k + 1];
            row[2] += part[k + 2];
            row[3] += 1.;
          }
      for (const auto &[key, row] : rows)
        *profile_file << tv << ',' << time << ',' << row[0] / row[3] << ',' << row[1] / row[3]
                      << ',' << row[2] / row[3] << '\n';
      profile_file->flush();
      require_written(*profile_file, scene.output_directory + "/" + profile_file_name);
    }



    std::array<double, 2>
    GranularVerification::at_rest_errors(const grid::FiniteElementField &flow,
                                         const particles::PointCloud    &cloud) const
    {
      const double g     = fluid_parameters.fluid.gravity.norm();
      const double rho_w = fluid_parameters.fluid.water_density;
      const double top   = fluid_parameters.upper_right[1];
      const double base  = fluid_parameters.lower_left[1];
      const double H     = parameters.column_height;
      double       pore  = 0.;
      for_each_pressure_node(flow, [&](const double y, const double p) {
        pore = std::max(pore, std::abs(p - rho_w * g * (top - y)) / (rho_w * g * H));
      });
      // The buoyant weight of the skeleton per unit volume: its grains' weight less the
      // water they displace, (rho_dry - (1 - n_0) rho^w) g.
      const auto  &material = soil_parameters.materials[0];
      const double solid    = material.density / parameters.grain_density;
      const double buoyant  = (material.density - solid * rho_w) * g;
      const double K0       = material.poisson_ratio / (1. - material.poisson_ratio);
      double       stress   = 0.;
      for (const auto &particle : cloud.particles())
        {
          const auto   q     = particle.get_properties();
          const double exact = -buoyant * (base + H - q[soil::property::initial_y]);
          stress             = std::max({stress,
                                         std::abs(q[soil::property::stress_yy] - exact),
                                         std::abs(q[soil::property::stress_xx] - K0 * exact)});
        }
      return {{dealii::Utilities::MPI::max(pore, MPI_COMM_WORLD),
               dealii::Utilities::MPI::max(stress, MPI_COMM_WORLD) / (buoyant * H)}};
    }



    double
    GranularVerification::seepage_inflow(const fluid::FreeSurfaceParameters &fluid_parameters,
                                         const double                        end_time)
    {
      dealii::FunctionParser<2> inflow(2, end_time);
      inflow.initialize("x,y,t", fluid_parameters.boundaries.inflow_velocity, {}, true);
      return inflow.value(
        dealii::Point<2>(0.5 * (fluid_parameters.lower_left[0] + fluid_parameters.upper_right[0]),
                         fluid_parameters.upper_right[1]),
        1);
    }



    std::array<double, 4>
    GranularVerification::seepage_gradients(const grid::FiniteElementField &flow) const
    {
      const double base = fluid_parameters.lower_left[1], H = parameters.column_height;
      const double h = fluid_parameters.cell_size;
      // Least squares of p = a + G y + c (-1)^j over the nodes of the layer's middle half
      // (row j of nodes; each cell's corners, so every interior node counts as often as it
      // has cells): the gradient G free of the pressure's odd-even mode between rows, whose
      // amplitude c is reported beside it.
      dealii::FullMatrix<double> normal(3, 3);
      dealii::Vector<double>     right(3);
      for_each_pressure_node(flow, [&](const double y, const double p) {
        if (y < base + 0.25 * H - 1e-12 || y > base + 0.75 * H + 1e-12)
          return;
        const long   row = std::lround((y - base) / h);
        const double f[3]{1., y - base, row % 2 == 0 ? 1. : -1.};
        for (unsigned int a = 0; a < 3; ++a)
          {
            right(a) += f[a] * p;
            for (unsigned int b = 0; b < 3; ++b)
              normal(a, b) += f[a] * f[b];
          }
      });
      for (unsigned int a = 0; a < 3; ++a)
        {
          right(a) = dealii::Utilities::MPI::sum(right(a), MPI_COMM_WORLD);
          for (unsigned int b = 0; b < 3; ++b)
            normal(a, b) = dealii::Utilities::MPI::sum(normal(a, b), MPI_COMM_WORLD);
        }
      dealii::Vector<double> fit(3);
      normal.gauss_jordan();
      normal.vmult(fit, right);
      const double  measured = fit(1), odd_even = std::abs(fit(2));
      const double  U = std::abs(seepage_inflow(fluid_parameters, scene.end_time));
      const DragLaw law(fluid_parameters.fluid.water_density,
                        fluid_parameters.fluid.water_viscosity,
                        parameters.d50);
      const double  n0 = 1. - soil_parameters.materials[0].density / parameters.grain_density;
      const double  k  = parameters.permeability_law == PermeabilityLaw::constant ?
                           parameters.permeability :
                           law.permeability(n0);
      const double  C  = parameters.forchheimer ? law.drag_coefficient(n0, k, U / n0) :
                                                  law.darcy_coefficient(n0, k);
      return {
        {measured, C * U / (n0 * n0), law.darcy_coefficient(n0, k) * U / (n0 * n0), odd_even}};
    }



    void
    GranularVerification::add_statistics(Statistics                     &statistics,
                                         const double                    time,
                                         const grid::FiniteElementField &flow) const
    {
      if (parameters.exact_solution != GranularExactSolution::terzaghi)
        return;
      const auto   e  = terzaghi_errors(flow, time, nullptr);
      const double tv = time_factor(time);
      statistics.add_value("time_factor", tv);
      statistics.add_value("pore_pressure_error", e[0]);
      statistics.add_value("consolidation_degree", e[1]);
      statistics.add_value("consolidation_degree_exact", terzaghi_average_degree(tv));
    }



    void
    GranularVerification::check_points(const particles::PointCloud &cloud) const
    {
      if (parameters.exact_solution == GranularExactSolution::settling)
        settling_row(cloud);
    }



    double
    GranularVerification::settling_row(const particles::PointCloud &cloud) const
    {
      // The row of points that started highest at or below 0.7 H: clear of the top, where
      // the water's velocity jumps and the grid smears the suspension's edge over a cell or
      // two, and above the bed until the fall reaches its height times (n_0 - n_s) /
      // (1 - n_s).
      const double H    = parameters.column_height;
      const double base = fluid_parameters.lower_left[1];
      double       row  = -std::numeric_limits<double>::max();
      for (const auto &particle : cloud.particles())
        {
          const double y0 = particle.get_properties()[soil::property::initial_y];
          if (y0 <= base + 0.7 * H)
            row = std::max(row, y0);
        }
      row = dealii::Utilities::MPI::max(row, MPI_COMM_WORLD);
      if (row == -std::numeric_limits<double>::max())
        throw InputError("Granular water/Verification/Column height",
                         to_string(H),
                         "the height of the suspension, with points below 0.7 of it ('Exact "
                         "solution = settling' follows the row that started highest there)");
      return row;
    }



    std::array<double, 3>
    GranularVerification::settling_values(const particles::PointCloud &cloud,
                                          const double                 time) const
    {
      // One dimension: n u + (1 - n) v = 0 in the closed column, so the water rises at
      // (1 - n) v / n through the grains; eliminating the pressure gradient from the two
      // momentum balances leaves
      //   (1 - n) (rho^s + rho^w (1 - n) / n) dv/dt = -(1 - n) (rho^s - rho^w) g - C v / n^2,
      // with C = n^2 mu / k (Darcy): v_inf = -(1 - n) (rho^s - rho^w) g k / mu, and tau the
      // inertia over C / n^2. The bed at n_s takes the solids that cross its top: its
      // height is b = (1 - n_0) d / (n_0 - n_s) after a fall d, and the top meets it at
      // d* = H (n_0 - n_s) / (1 - n_s).
      const auto  &material = soil_parameters.materials[0];
      const double rho_s = parameters.grain_density, n0 = 1. - material.density / rho_s;
      const double rho_w = fluid_parameters.fluid.water_density;
      const double mu    = fluid_parameters.fluid.water_viscosity;
      const double g     = fluid_parameters.fluid.gravity.norm();
      const double k     = parameters.permeability_law == PermeabilityLaw::constant ?
                             parameters.permeability :
                             DragLaw(rho_w, mu, parameters.d50).permeability(n0);
      const double v_inf = (1. - n0) * (rho_s - rho_w) * g * k / mu;
      const double tau   = (rho_s + rho_w * (1. - n0) / n0) * k / mu * (1. - n0);
      const double t     = time - scene.start_time;
      const double fall  = v_inf * (t - tau * (1. - std::exp(-t / tau)));
      const double H = parameters.column_height, ns = parameters.suspension_porosity;
      const double base = fluid_parameters.lower_left[1];

      const double row     = settling_row(cloud);
      const bool   met     = fall >= (row - base) * (n0 - ns) / (1. - ns);
      double       sums[3] = {0., 0., 0.}; // the row's fall, its count, all points' volume
      for (const auto &particle : cloud.particles())
        {
          const auto p = particle.get_properties();
          sums[2] += p[soil::property::volume];
          if (std::abs(p[soil::property::initial_y] - row) <= 1e-9 * H)
            {
              sums[0] += p[soil::property::initial_y] - particle.get_location()[1];
              sums[1] += 1.;
            }
        }
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 3),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(sums, 3));
      const double width = fluid_parameters.upper_right[0] - fluid_parameters.lower_left[0];
      // Once the bed reaches the row: the points' volume over the width, the bed at n_s
      // under what is left of the suspension at n_0, H - fall, until the top meets the bed
      // (fall = d*) and the bed alone is left, H (1 - n_0) / (1 - n_s).
      if (met)
        return {{sums[2] / width, std::max(H - fall, H * (1. - n0) / (1. - ns)), 1.}};
      return {{sums[0] / sums[1], fall, 0.}};
    }



    bool
    GranularVerification::finish(const grid::FiniteElementField &flow,
                                 const particles::PointCloud    &cloud,
                                 const double                    time) const
    {
      double largest = 0.;
      if (parameters.exact_solution == GranularExactSolution::terzaghi)
        {
          largest = profiles.size() < parameters.time_factors.size() ? 1. : 0.;
          if (is_root())
            std::printf("Terzaghi consolidation (error of the nodes' pore pressure relative "
                        "to the load p0 = %g Pa):\n",
                        parameters.top_load);
          for (const auto &[tv, error, degree, exact] : profiles)
            {
              largest = std::max(largest, error);
              if (is_root())
                std::printf("  T_v = %.4f: largest error %.3e; U %.5f against %.5f (error "
                            "%.2e)\n",
                            tv,
                            error,
                            degree,
                            exact,
                            degree - exact);
            }
          if (is_root())
            std::printf("Terzaghi: largest pore pressure error %.3e", largest);
        }
      else if (parameters.exact_solution == GranularExactSolution::at_rest)
        {
          const auto e = at_rest_errors(flow, cloud);
          largest      = std::max(e[0], e[1]);
          if (is_root())
            std::printf("Saturated column at rest: pore pressure against hydrostatic %.3e "
                        "(of rho g H), effective stresses against the buoyant geostatic "
                        "state %.3e (of its value at the base); largest %.3e",
                        e[0],
                        e[1],
                        largest);
        }
      else if (parameters.exact_solution == GranularExactSolution::seepage)
        {
          const auto g = seepage_gradients(flow);
          largest      = std::abs(g[0] - g[1]) / g[1];
          if (is_root())
            std::printf("Steady seepage: pressure gradient %.6e Pa/m against %.6e (Darcy "
                        "%.6e, Forchheimer %.6e), odd-even mode between rows of nodes "
                        "%.3e Pa: relative error %.3e",
                        g[0],
                        g[1],
                        g[2],
                        g[1] - g[2],
                        g[3],
                        largest);
        }
      else if (parameters.exact_solution == GranularExactSolution::settling)
        {
          const auto s = settling_values(cloud, time);
          largest      = std::abs(s[0] - s[1]) / s[1];
          if (is_root())
            std::printf(
              s[2] > 0. ?
                "Settling suspension: the points' height (volume over width) %.6e m against "
                "%.6e: relative error %.3e" :
                "Settling suspension: the fall of the row started at 0.7 H %.6e m against "
                "%.6e: relative error %.3e",
              s[0],
              s[1],
              largest);
        }
      else
        return true;
      const bool ok = !(parameters.tolerance > 0.) || largest <= parameters.tolerance;
      if (is_root())
        {
          if (parameters.tolerance > 0.)
            std::printf(" <= %g: %s", parameters.tolerance, ok ? "yes" : "no");
          std::printf("\n");
          std::fflush(stdout);
        }
      return ok;
    }



    void
    GranularVerification::save(io::CheckpointRecord &record) const
    {
      std::vector<double> flat;
      for (const auto &row : profiles)
        flat.insert(flat.end(), row.begin(), row.end());
      record.put("granular/profiles", flat);
    }



    void
    GranularVerification::load(const io::CheckpointRecord &record)
    {
      const auto &flat = record.get_vector("granular/profiles");
      if (flat.size() % 4 != 0)
        throw InputError("Checkpoint/Resume",
                         "granular/profiles",
                         "rows of four numbers (damaged checkpoint)");
      profiles.clear();
      for (std::size_t k = 0; k < flat.size(); k += 4)
        profiles.push_back({{flat[k], flat[k + 1], flat[k + 2], flat[k + 3]}});
    }
  } // namespace granular
} // namespace slidewave
