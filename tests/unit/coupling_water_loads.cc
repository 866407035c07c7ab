// The water's loads on the soil (coupling::SoilWaterInterface) under 'Water pressure on
// soil = hydrostatic', for a block of soil standing in water, where the loads are known
// exactly.
//
// The full hydrostatic pressure rho_w g (eta - z) is applied as two parts that add up to
// it: the pressure of the still level eta_s (the lowest initial free surface of the wet
// cells), whose integral over the boundary of the soil below eta_s (the base included, where
// the pore water presses as everywhere else) is the buoyancy rho_w g V of that soil, applied
// to each point as a body force rho_w g V_p times the part of its domain below eta_s; and the
// pressure in excess of eta_s's on the soil's top and faces. The soil's stress then leaves
// out the still water's pressure rho_w g (eta_s - z) (an isotropic part: the deviator, which
// decides an undrained clay's failure, is the same), so that still water puts no force at
// all on the boundary points, whose forces would otherwise load the outer cells unevenly.
//
// Grid [0, 2] x [0, 1.5] of 0.1 m cells, 2 x 2 GIMP points per cell; a 1 m x 1 m block
// [0, 1] x [0, 1] against the left side; water cells = the 20 grid columns. rho_w = 1000,
// g = 9.81. Exact (per m of thickness):
//  - still water at eta = 1.5 m (0.5 m over the block): the bed is the block's top (1 m)
//    over the block and the floor beside it; every point carries its buoyancy
//    rho_w g V_p upwards and nothing else; the total is rho_w g x 1 m^2 = 9810 N up;
//  - still water at eta = 1.0 m (the block's top dry): the same buoyancy, 9810 N;
//  - still water at eta = 0.5 m (the block half out of the water): the points of the lower
//    half are buoyant, the upper half not (the level is a boundary between point domains):
//    4905 N up;
//  - the level raised from 1.5 m to 1.6 m (still level 1.5 m): the buoyancy, 9810 N up, plus
//    the excess pressure rho_w g 0.1 m on the top (-981 N) and on the face (-981 N, towards
//    -x): (-981, 8829) N (tests/unit/coupling_excess_water_loads checks how the excess is
//    shared among the points).
// Sums of a few hundred numbers: checked to 1e-10 relative (round-off). The interface's own
// total (load_on_soil) and the sum of the point forces agree. On 1 and 2 ranks (same numbers).
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
  /** The loads with the water at @p level, the still level (the initial state) being
   *  @p still. */
  void
  check_water(soil::MaterialPointSolver &soil,
              const double               still,
              const double               level,
              const double               exact_x,
              const double               exact_y,
              const double               buoyant_below)
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
                                           coupling::WaterPressure::hydrostatic);
    interface.update_surface(soil.particles());
    const std::vector<double> bed       = interface.bed();
    double                    bed_error = 0.;
    for (unsigned int i = 0; i < 20; ++i)
      bed_error = std::max(bed_error, std::abs(bed[i] - (mesh.center(i) < 1. ? 1. : 0.)));
    if (root)
      std::printf("still level %.1f m, water at %.1f m\n", still, level);
    check(bed_error < 1e-14, "bed = block top (1 m) over the block, floor beside it");
    water.set_bed(bed);
    const auto set_level = [&](const double eta) {
      std::vector<double> depth(20), discharge(20, 0.);
      for (unsigned int i = 0; i < 20; ++i)
        depth[i] = std::max(eta - bed[i], 0.);
      water.set_state(depth, discharge);
    };
    set_level(still);
    interface.set_initial_level(water);
    set_level(level);
    interface.apply_water_loads(soil.points(), water, 0.);

    const dealii::Tensor<1, 2> total = soil.total_point_force();
    const dealii::Tensor<1, 2> own   = interface.load_on_soil();
    // In still water every point carries exactly its buoyancy: rho_w g V_p below the
    // level, nothing above it, and no horizontal force.
    double off_buoyancy = 0.;
    for (const auto &particle : soil.particles())
      {
        const auto   p        = particle.get_properties();
        const double buoyancy = particle.get_location()[1] < buoyant_below ?
                                  1000. * 9.81 * p[soil::property::volume] :
                                  0.;
        off_buoyancy          = std::max({off_buoyancy,
                                          std::abs(p[soil::property::point_force_x]),
                                          std::abs(p[soil::property::point_force_y] - buoyancy)});
      }
    off_buoyancy = dealii::Utilities::MPI::max(off_buoyancy, MPI_COMM_WORLD);
    if (root)
      std::printf("  load on the soil: (%.6f, %.6f) N/m, exact (%.6f, %.6f)\n",
                  total[0],
                  total[1],
                  exact_x,
                  exact_y);
    const double scale = std::abs(exact_x) + std::abs(exact_y);
    check(std::abs(total[0] - exact_x) < 1e-10 * scale, "horizontal load");
    check(std::abs(total[1] - exact_y) < 1e-10 * scale, "vertical load");
    check((own - total).norm() < 1e-10 * scale, "interface total = sum of point forces");
    if (still == level)
      check(off_buoyancy < 1e-12 * scale,
            "every point carries its buoyancy and nothing else (no boundary load)");
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
    const double rho_g = 1000. * 9.81;
    check_water(soil, 1.5, 1.5, 0., rho_g * 1.0, 2.);
    check_water(soil, 1.0, 1.0, 0., rho_g * 1.0, 2.);
    check_water(soil, 0.5, 0.5, 0., rho_g * 0.5, 0.5);
    check_water(soil, 1.5, 1.6, -rho_g * 0.1, rho_g * (1.0 - 0.1), 2.);
  }
  if (root)
    std::printf(unit_check::all_passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return unit_check::all_passed ? 0 : 1;
}
