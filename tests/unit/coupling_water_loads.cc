// The water's loads on the soil (coupling::SoilWaterInterface) against hydrostatics, for a
// block of soil standing in still water, where the loads are known exactly.
//
// Grid [0, 2] x [0, 1.5] of 0.1 m cells, 2 x 2 GIMP points per cell; a 1 m x 1 m block
// [0, 1] x [0, 1] against the left side; water cells = the 20 grid columns; still water at
// eta = 1.5 m: 0.5 m over the block, 1.5 m beside it. rho_w = 1000, g = 9.81.
// Exact (per m of thickness):
//  - the soil surface is 1 m in the block's columns, both as the top of the point domains
//    and as the mean of their upper envelope (the block fills its columns); the bed is
//    1 m there and the floor (0) beyond;
//  - vertical load: the weight of the water over the block, -rho g 0.5 m x 1 m = -4905 N,
//    shared equally by the surface points (two per column, -24.525 N each);
//  - horizontal load: the thrust on the block's face, -rho g (1.5^2 - 0.5^2) / 2 =
//    -9810 N (towards -x), borne by the points of the column next to the face whose
//    height y lies below the water (all of them), in proportion to rho g (1.5 - y); no
//    other point gets a horizontal force (beyond round-off);
//  - dry water beside a dry block (eta = 1 m, the block's top dry): the thrust is
//    rho g 1^2 / 2 = 4905 N, the vertical load zero.
// The sums run over a few hundred points: checked to 1e-10 relative (round-off). The
// interface's own total (load_on_soil) and the sum of the point forces agree. On 1 and 2
// ranks (same numbers: the points of a column may sit on different ranks).
#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <limits>
#include <slidewave/coupling/soil_water_interface.h>
#include <slidewave/mpm/material_point_solver.h>
#include <slidewave/mpm/particle_properties.h>
#include <slidewave/water/shallow_water_1d.h>
#include <vector>

using namespace slidewave;

namespace
{
  bool all_passed = true;
  bool root       = true;

  void
  check(const bool condition, const char *what)
  {
    if (root)
      std::printf("  %s: %s\n", what, condition ? "yes" : "no");
    all_passed = all_passed && condition;
  }

  mpm::MaterialPointParameters
  block_in_a_tank()
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Material points");
    mpm::MaterialPointParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string(R"(subsection Material points
set Shape functions = gimp
set Particles per direction = 2
subsection Grid
  set Lower left  = 0, 0
  set Upper right = 2, 1.5
  set Cell size   = 0.1
end
subsection Material 1
  set Name            = soil
  set Model           = linear elastic
  set Density         = 2000
  set Young's modulus = 1e6
  set Poisson ratio   = 0.3
end
subsection Region 1
  set Shape     = rectangle
  set Rectangle = 0, 0, 1, 1
  set Material  = soil
end
end
)");
    mpm::MaterialPointParameters result;
    prm.enter_subsection("Material points");
    result.parse_parameters(prm, "Material points");
    prm.leave_subsection();
    result.point_forces = true;
    return result;
  }

  void
  check_still_water(mpm::MaterialPointSolver   &soil,
                    const double                level,
                    const double                exact_x,
                    const double                exact_y,
                    const coupling::SoilSurface surface)
  {
    const water::WaterMesh       mesh = water::WaterMesh::uniform(0., 2., 20);
    water::ShallowWater1D        water(mesh, water::ShallowWaterParameters());
    const std::vector<double>    terrain(20, 0.);
    coupling::SoilWaterInterface interface(
      mesh.interfaces(), mesh, terrain, terrain, 1000., surface, 0.);
    interface.update_surface(soil);
    const std::vector<double> &bed       = interface.bed();
    double                     bed_error = 0.;
    for (unsigned int i = 0; i < 20; ++i)
      bed_error = std::max(bed_error, std::abs(bed[i] - (mesh.center(i) < 1. ? 1. : 0.)));
    if (root)
      std::printf("still water at eta = %.1f m, soil surface = %s\n",
                  level,
                  surface == coupling::SoilSurface::top ? "top" : "envelope");
    check(bed_error < 1e-14, "bed = block top (1 m) over the block, floor beside it");
    water.set_bed(bed);
    std::vector<double> depth(20), discharge(20, 0.);
    for (unsigned int i = 0; i < 20; ++i)
      depth[i] = std::max(level - bed[i], 0.);
    water.set_state(depth, discharge);
    interface.apply_water_loads(soil, water, 0.);

    const dealii::Tensor<1, 2> total = soil.total_point_force();
    const dealii::Tensor<1, 2> own   = interface.load_on_soil();
    // Horizontal forces off the face column, and the smallest and largest vertical share.
    double stray = 0., share_min = std::numeric_limits<double>::infinity(), share_max = -share_min;
    for (const auto &particle : soil.particles())
      {
        const auto p = particle.get_properties();
        if (particle.get_location()[0] < 0.9)
          stray = std::max(stray, std::abs(p[mpm::property::point_force_x]));
        if (p[mpm::property::point_force_y] != 0.)
          {
            share_min = std::min(share_min, p[mpm::property::point_force_y]);
            share_max = std::max(share_max, p[mpm::property::point_force_y]);
          }
      }
    stray     = dealii::Utilities::MPI::max(stray, MPI_COMM_WORLD);
    share_min = dealii::Utilities::MPI::min(share_min, MPI_COMM_WORLD);
    share_max = dealii::Utilities::MPI::max(share_max, MPI_COMM_WORLD);
    if (root)
      std::printf("  load on the soil: (%.6f, %.6f) N/m, exact (%.6f, %.6f)\n",
                  total[0],
                  total[1],
                  exact_x,
                  exact_y);
    const double scale = std::abs(exact_x) + std::abs(exact_y);
    check(std::abs(total[0] - exact_x) < 1e-10 * scale, "thrust on the face = hydrostatic");
    check(std::abs(total[1] - exact_y) < 1e-10 * scale, "vertical load = water's weight");
    check((own - total).norm() < 1e-10 * scale, "interface total = sum of point forces");
    check(stray < 1e-10 * scale, "no horizontal force away from the face");
    if (exact_y != 0.)
      check(std::abs(share_min - share_max) < 1e-10 * scale
              && std::abs(share_min - exact_y / 20.) < 1e-10 * scale,
            "weight shared equally by the 20 surface points");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  {
    mpm::MaterialPointSolver soil(block_in_a_tank());
    soil.setup();
    const double rho_g = 1000. * 9.81;
    for (const auto surface : {coupling::SoilSurface::top, coupling::SoilSurface::envelope})
      {
        check_still_water(soil, 1.5, -rho_g * (1.5 * 1.5 - 0.5 * 0.5) / 2., -rho_g * 0.5, surface);
        check_still_water(soil, 1.0, -rho_g * 0.5, 0., surface);
      }
  }
  if (root)
    std::printf(all_passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return all_passed ? 0 : 1;
}
