// Column splitting and the walls of the depth-averaged model (issue 28,
// DepthAveragedModel::finish_point; doc/depth-averaged.md, "Column splitting"), on a
// column of 1 m cells with 4 x 4 columns per cell (initial width 0.25 m; 'Split stretch =
// 1.5': a column splits once wider than 0.375 m):
//  - a column at its initial width, or stretched to just 0.375 m, does not split;
//  - stretched to 0.5 m along x it splits along x: the halves at -+0.125 m from it, each
//    with half its mass, volume and width, its depth, velocity and stress; mass, momentum
//    and the centre of mass exactly the column's (binary fractions: no round-off);
//  - stretched more along y than x it splits along y;
//  - a column whose halves' shape-function domains would reach past the grid's edge does
//    not split, at both ends of both directions;
//  - 'cpgimp': the halves' domains are half their width (at most the column's);
//  - 'Split stretch = 0': no splitting, whatever the stretch;
//  - the engine's hold of the closed sides (particles::PointCloud::hold_at_closed_sides,
//    in the gather, since 2026-12-06 for every model; this model's own keep_inside did it
//    before): a column's centre less than a cell past a closed side is put back on it and
//    loses its outward velocity; past an open side, or more than a cell past a closed one
//    (a run gone wrong, which the check of the sides then stops), it is left.
#include "depth_averaged_input.h"
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <slidewave/depth_averaged/depth_averaged_model.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/particles/point_cloud.h>
#include <vector>

using namespace slidewave;
using namespace slidewave::depth_averaged;
using unit_check::check;

namespace
{
  std::string
  scene(const std::string &shape, const std::string &split)
  {
    return "subsection Depth averaged\n"
           "  set Shape functions = "
           + shape + "\n  set Split stretch = " + split
           + "\n"
             "  subsection Grid\n"
             "    set Upper right = 10, 10\n"
             "    set Cell size   = 1\n"
             "    set Right side  = open\n"
             "  end\n"
             "  subsection Release\n"
             "    set Shape     = rectangle\n"
             "    set Rectangle = 2, 2, 4, 4\n"
             "    set Depth     = 2\n"
             "  end\n"
             "end\n";
  }

  /** A column at @p x: 2 m deep, moving at (1, -0.5) m/s, with a stress. */
  std::vector<double>
  column(const DepthAveragedModel &model, const dealii::Point<2> &x)
  {
    std::vector<double> p(property::n_properties, 0.);
    model.fill_new_point(p, x, 2., dealii::Tensor<1, 2>({1., -0.5}), 1., 1.);
    p[property::stress_xx] = 3.;
    p[property::stress_xy] = -1.;
    return p;
  }

  /** Splits (or not) @p p at @p x; returns whether it split. */
  bool
  split(const DepthAveragedModel &model,
        std::vector<double>      &p,
        dealii::Point<2>         &x,
        std::vector<double>      &child,
        dealii::Point<2>         &child_x)
  {
    child = p;
    return model.finish_point(p, x, child.data(), child_x);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto flat = terrain::ElevationGrid::from_function([](double, double) { return 0.; },
                                                          dealii::Point<2>(0., 0.),
                                                          dealii::Point<2>(10., 10.),
                                                          11,
                                                          11);
  const auto gimp = depth_averaged_parameters(scene("gimp", "1.5"));
  const DepthAveragedModel model(gimp, flat);
  std::vector<double>      child;
  dealii::Point<2>         child_x;
  const dealii::Point<2>   centre(5.125, 5.375);

  std::printf("no split below 'Split stretch'\n");
  {
    auto             p = column(model, centre);
    dealii::Point<2> x = centre;
    check(p[property::width_x] == 0.25 && p[property::width_y] == 0.25,
          "a new column is a cell over the columns per direction wide");
    check(!split(model, p, x, child, child_x) && x == centre, "at its initial width: no split");
    p[property::width_x] = 0.375;
    check(!split(model, p, x, child, child_x), "at 1.5 times its width: no split");
  }

  std::printf("a split along x\n");
  {
    const auto       before = column(model, centre);
    auto             p      = before;
    dealii::Point<2> x      = centre;
    p[property::width_x]    = 0.5;
    const bool split_x      = split(model, p, x, child, child_x);
    check(split_x, "at twice its width: it splits");
    check(x == dealii::Point<2>(5.0, 5.375) && child_x == dealii::Point<2>(5.25, 5.375),
          "the halves at -+ a quarter of its width along x");
    check(p[property::mass] + child[property::mass] == before[property::mass]
            && p[property::mass] == child[property::mass],
          "mass: two equal halves, the total the column's");
    check(p[property::volume] + child[property::volume] == before[property::volume],
          "volume: the column's");
    const double mx = p[property::mass] * p[property::velocity_x]
                      + child[property::mass] * child[property::velocity_x];
    const double my = p[property::mass] * p[property::velocity_y]
                      + child[property::mass] * child[property::velocity_y];
    check(mx == before[property::mass] * before[property::velocity_x]
            && my == before[property::mass] * before[property::velocity_y],
          "momentum: the column's");
    const double cx
      = (p[property::mass] * x[0] + child[property::mass] * child_x[0]) / before[property::mass];
    check(cx == centre[0], "centre of mass: the column's");
    check(p[property::width_x] == 0.25 && child[property::width_x] == 0.25
            && child[property::width_y] == 0.25,
          "each half a quarter of a cell wide, as a new column");
    bool same = true;
    for (const unsigned int k : {static_cast<unsigned int>(property::depth),
                                 static_cast<unsigned int>(property::velocity_x),
                                 static_cast<unsigned int>(property::velocity_y),
                                 static_cast<unsigned int>(property::stress_xx),
                                 static_cast<unsigned int>(property::stress_xy),
                                 static_cast<unsigned int>(property::initial_x),
                                 static_cast<unsigned int>(property::domain_half_x)})
      same = same && p[k] == before[k] && child[k] == before[k];
    check(same, "depth, velocity, stress, start and GIMP domain: the column's in both");
    check(!split(model, p, x, child, child_x), "a half does not split again at once");
  }

  std::printf("a split along y\n");
  {
    auto             p   = column(model, centre);
    dealii::Point<2> x   = centre;
    p[property::width_x] = 0.45;
    p[property::width_y] = 0.5;
    const bool split_y   = split(model, p, x, child, child_x);
    check(split_y && x == dealii::Point<2>(5.125, 5.25) && child_x == dealii::Point<2>(5.125, 5.5)
            && p[property::width_x] == 0.45,
          "stretched more along y: along y");
  }

  std::printf("no split past the grid's edges\n");
  {
    // Reach of a half: a quarter of the width (0.125) plus its domain (0.125).
    bool held = true;
    for (const auto &x0 : {dealii::Point<2>(0.24, 5.), dealii::Point<2>(9.76, 5.)})
      {
        auto             p   = column(model, x0);
        dealii::Point<2> x   = x0;
        p[property::width_x] = 0.5;
        held                 = held && !split(model, p, x, child, child_x) && x == x0;
      }
    for (const auto &x0 : {dealii::Point<2>(5., 0.24), dealii::Point<2>(5., 9.76)})
      {
        auto             p   = column(model, x0);
        dealii::Point<2> x   = x0;
        p[property::width_y] = 0.5;
        held                 = held && !split(model, p, x, child, child_x) && x == x0;
      }
    check(held, "0.24 m from an edge: no split, on all four sides");
    auto             p = column(model, dealii::Point<2>(0.25, 5.));
    dealii::Point<2> x(0.25, 5.);
    p[property::width_x] = 0.5;
    check(split(model, p, x, child, child_x) && x[0] == 0.125,
          "0.25 m from the edge: it splits, a half's domain touching the edge");
  }

  std::printf("cpgimp\n");
  {
    const auto               cp = depth_averaged_parameters(scene("cpgimp", "1.5"));
    const DepthAveragedModel cp_model(cp, flat);
    auto                     p = column(cp_model, centre);
    dealii::Point<2>         x = centre;
    p[property::width_x]       = 0.4;
    p[property::domain_half_x] = 0.2;
    check(split(cp_model, p, x, child, child_x) && p[property::domain_half_x] == 0.1
            && child[property::domain_half_x] == 0.1 && child[property::domain_half_y] == 0.125,
          "the halves' domains half their width along the split");
  }

  std::printf("'Split stretch = 0'\n");
  {
    const auto               none = depth_averaged_parameters(scene("gimp", "0"));
    const DepthAveragedModel none_model(none, flat);
    auto                     p = column(none_model, centre);
    dealii::Point<2>         x = centre;
    p[property::width_x]       = 5.;
    check(!split(none_model, p, x, child, child_x) && x == centre, "no split at 20 times");
  }

  std::printf("closed and open sides\n");
  {
    // The scene's grid: 10 m x 10 m of 1 m cells, the right side open, the others closed.
    grid::BackgroundGrid        grid(dealii::Point<2>(0., 0.), dealii::Point<2>(10., 10.), 1.);
    const particles::PointCloud cloud(grid,
                                      model.layout(),
                                      property::mass,
                                      {grid::GridBoundary::roller,
                                       grid::GridBoundary::free,
                                       grid::GridBoundary::roller,
                                       grid::GridBoundary::roller},
                                      1);
    dealii::Point<2>            x(-0.01, 10.02);
    double                      vx = -1., vy = 0.5;
    cloud.hold_at_closed_sides(x, vx, vy);
    check(x == dealii::Point<2>(0., 10.) && vx == 0. && vy == 0.,
          "past the left and top walls: put back on them, the outward velocities removed");
    dealii::Point<2> y(10.01, -1e-9);
    vx = 1.;
    vy = -0.5;
    cloud.hold_at_closed_sides(y, vx, vy);
    check(y == dealii::Point<2>(10.01, 0.) && vx == 1. && vy == 0.,
          "past the open right side: left there (and held on the bottom)");
    dealii::Point<2> inward(-0.01, 5.);
    vx = 0.3;
    cloud.hold_at_closed_sides(inward, vx, vy);
    check(inward == dealii::Point<2>(0., 5.) && vx == 0.3,
          "past a wall but moving back in: put back on it, its velocity kept");
    dealii::Point<2> far(-1.5, 5.);
    vx = -1.;
    cloud.hold_at_closed_sides(far, vx, vy);
    check(far == dealii::Point<2>(-1.5, 5.) && vx == -1.,
          "more than a cell past a wall: left there, for the check of the sides to stop the run");
  }

  std::printf(unit_check::all_passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return unit_check::all_passed ? 0 : 1;
}
