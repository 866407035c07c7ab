// The water's loads on the soil in the form of paper 000, Eq. 10 (coupling::WaterPressure::
// excess_over_initial_level): the pressure in excess of that of the initial water level
// eta_0, for a block of soil in a tank whose water level is then raised or lowered, where
// the loads are known exactly.
//
// Grid [0, 2] x [0, 1.5] of 0.1 m cells, 2 x 2 GIMP points per cell; a 1 m x 1 m block
// [0, 1] x [0, 1] against the left side; water cells = the 20 grid columns; the initial
// level eta_0 = 1.5 m (0.5 m over the block, 1.5 m beside it). rho_w = 1000, g = 9.81.
// Exact (per m of thickness), for a level eta:
//  - eta = eta_0 (still water): no load at all, every point force exactly zero (eta and
//    eta_0 are computed the same way, so their difference is an exact zero);
//  - eta = 1.6 and 1.4 m (both levels above the block): the excess pressure
//    rho g (eta - eta_0) is uniform below both levels, so the vertical load is
//    -rho g (eta - eta_0) x 1 m = -/+981 N, shared equally by the 20 surface points, and the
//    thrust on the face is -rho g (eta - eta_0) x 1 m (towards -x for a rise), shared
//    equally by the 40 points of the face column (the excess pressure is the same at every
//    height of the face); it equals the hydrostatic load at eta less that at eta_0;
//  - eta_0 = 1.0 m (the block's top dry at the start: no initial pressure there), eta =
//    1.2 m: the 0.2 m of water now over the block loads it with its full weight,
//    -rho g 0.2 m x 1 m = -1962 N, and the face's thrust grows by that of 1.2 m less that of
//    1.0 m of water, rho g (1.2^2 - 0.2^2 - 1) / 2 = 0.2 rho g = 1962 N (towards -x); both
//    the hydrostatic loads at eta less those at eta_0;
//  - eta = 0.8 m (the block's top dry): no vertical load (dry cells load nothing), and the
//    thrust of 0.8 m of water less that of the initial 1.5 m on the face,
//    rho g (0.8^2 - (1.5^2 - 0.5^2)) / 2 = -0.68 rho g = -6670.8 N: the face is pulled
//    towards the water (+x).
// Sums of a few hundred point forces: checked to 1e-10 relative (round-off). On 1 and 2
// ranks (same numbers).
#include "water_load_block.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <limits>
#include <slidewave/coupling/soil_water_interface.h>
#include <slidewave/soil/material_point_solver.h>
#include <slidewave/soil/particle_properties.h>
#include <slidewave/water/shallow_water_1d.h>
#include <vector>

using namespace slidewave;

namespace
{
  constexpr double rho_g = 1000. * 9.81;

  /** Sets still water at @p level over the interface's bed. */
  void
  set_level(water::ShallowWater1D &water, const std::vector<double> &bed, const double level)
  {
    std::vector<double> depth(bed.size()), discharge(bed.size(), 0.);
    for (unsigned int i = 0; i < bed.size(); ++i)
      depth[i] = std::max(level - bed[i], 0.);
    water.set_state(depth, discharge);
  }

  /** The loads on the soil with the water at @p level, the initial level being @p initial. */
  dealii::Tensor<1, 2>
  loads_at(soil::MaterialPointSolver    &soil,
           const double                  initial,
           const double                  level,
           const coupling::WaterPressure pressure)
  {
    const water::WaterMesh       mesh = water::WaterMesh::uniform(0., 2., 20);
    water::ShallowWater1D        water(mesh, water::ShallowWaterParameters());
    const std::vector<double>    terrain(20, 0.);
    coupling::SoilWaterInterface interface(mesh.interfaces(),
                                           mesh,
                                           terrain,
                                           terrain,
                                           coupling::WaterConstants::of(1000., water.parameters()),
                                           soil.property_layout(),
                                           coupling::SoilSurface::envelope,
                                           0.,
                                           pressure);
    interface.update_surface(soil.particles());
    const std::vector<double> bed = interface.bed();
    water.set_bed(bed);
    set_level(water, bed, initial);
    interface.set_initial_level(water);
    set_level(water, bed, level);
    interface.apply_water_loads(soil.points(), water, 0.);
    return interface.load_on_soil();
  }

  void
  check_level(soil::MaterialPointSolver &soil,
              const double               initial_level,
              const double               level,
              const double               exact_x,
              const double               exact_y)
  {
    if (root)
      std::printf("water level from %.1f m to %.1f m, excess over initial level\n",
                  initial_level,
                  level);
    const dealii::Tensor<1, 2> own
      = loads_at(soil, initial_level, level, coupling::WaterPressure::excess_over_initial_level);
    const dealii::Tensor<1, 2> total = soil.total_point_force();

    // The shares: vertical forces on the surface points, horizontal ones on the face column.
    double       largest = 0.;
    double       x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
    double       y_min = x_min, y_max = -x_min;
    unsigned int n_x = 0, n_y = 0;
    double       stray_x = 0.;
    for (const auto &particle : soil.particles())
      {
        const auto   p  = particle.get_properties();
        const double fx = p[soil::property::point_force_x], fy = p[soil::property::point_force_y];
        largest = std::max({largest, std::abs(fx), std::abs(fy)});
        if (particle.get_location()[0] < 0.9)
          stray_x = std::max(stray_x, std::abs(fx));
        else
          {
            ++n_x;
            x_min = std::min(x_min, fx);
            x_max = std::max(x_max, fx);
          }
        if (fy != 0.)
          {
            ++n_y;
            y_min = std::min(y_min, fy);
            y_max = std::max(y_max, fy);
          }
      }
    largest = dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
    stray_x = dealii::Utilities::MPI::max(stray_x, MPI_COMM_WORLD);
    x_min   = dealii::Utilities::MPI::min(x_min, MPI_COMM_WORLD);
    x_max   = dealii::Utilities::MPI::max(x_max, MPI_COMM_WORLD);
    y_min   = dealii::Utilities::MPI::min(y_min, MPI_COMM_WORLD);
    y_max   = dealii::Utilities::MPI::max(y_max, MPI_COMM_WORLD);
    n_x     = dealii::Utilities::MPI::sum(n_x, MPI_COMM_WORLD);
    n_y     = dealii::Utilities::MPI::sum(n_y, MPI_COMM_WORLD);
    if (root)
      std::printf("  load on the soil: (%.6f, %.6f) N/m, exact (%.6f, %.6f)\n",
                  total[0],
                  total[1],
                  exact_x,
                  exact_y);

    if (exact_x == 0. && exact_y == 0.)
      {
        check(largest == 0., "every point force exactly zero");
        return;
      }
    const double scale = std::abs(exact_x) + std::abs(exact_y);
    check(std::abs(total[0] - exact_x) < 1e-10 * scale, "thrust on the face");
    check(std::abs(total[1] - exact_y) < 1e-10 * scale, "vertical load");
    check((own - total).norm() < 1e-10 * scale, "interface total = sum of point forces");
    check(stray_x < 1e-10 * scale, "no horizontal force away from the face");
    if (exact_y != 0.)
      check(n_y == 20 && std::abs(y_max - y_min) < 1e-10 * scale
              && std::abs(y_min - exact_y / 20.) < 1e-10 * scale,
            "vertical load shared equally by the 20 surface points");
    if (level > 1.)
      {
        check(n_x == 40 && std::abs(x_max - x_min) < 1e-10 * scale
                && std::abs(x_min - exact_x / 40.) < 1e-10 * scale,
              "thrust shared equally by the 40 points of the face column");
        // The excess form is the hydrostatic load at eta less that at eta_0.
        const dealii::Tensor<1, 2> at_level
          = loads_at(soil, initial_level, level, coupling::WaterPressure::hydrostatic);
        const dealii::Tensor<1, 2> at_initial
          = loads_at(soil, initial_level, initial_level, coupling::WaterPressure::hydrostatic);
        check((at_level - at_initial - own).norm() < 1e-10 * scale,
              "= hydrostatic load at eta less hydrostatic load at eta_0");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  root              = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  unit_check::print = root;
  {
    const auto                soil_parameters = block_in_a_tank();
    auto                      grid = soil::MaterialPointSolver::make_grid(soil_parameters);
    soil::MaterialPointSolver soil(soil_parameters, *grid);
    soil.setup();
    check_level(soil, 1.5, 1.5, 0., 0.);
    check_level(soil, 1.5, 1.6, -rho_g * 0.1, -rho_g * 0.1);
    check_level(soil, 1.5, 1.4, rho_g * 0.1, rho_g * 0.1);
    check_level(soil, 1.5, 0.8, -rho_g * (0.8 * 0.8 - (1.5 * 1.5 - 0.5 * 0.5)) / 2., 0.);
    check_level(soil, 1.0, 1.2, -rho_g * 0.2, -rho_g * 0.2);
  }
  if (root)
    std::printf(unit_check::all_passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return unit_check::all_passed ? 0 : 1;
}
