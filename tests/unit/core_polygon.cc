// The polygon helper shared by the rigid solids and the material regions (core/polygon.h),
// against hand values:
//  - the shoelace area of a unit square both ways round (+1, -1), of an L-shape (3), of a
//    degenerate ring (three collinear vertices: 0) and of two vertices (0);
//  - the bounding box of the L-shape;
//  - side_of with both edge tests: the centre inside, a point beyond the right side
//    outside, the L's notch (inside the box, outside the ring) outside, a vertex and a
//    point on a side on the edge, a point 1e-3 off a side on the edge with the distance
//    test at tolerance 1e-2 and inside at tolerance 0, the collinear test's 1e-12;
//  - the even-odd rule where the ray towards +x passes through a vertex;
//  - parse_polygon: three vertices read back exactly; a vertex of one number, a word and
//    an infinite value refused, each naming the parameter; without a unit, no "[m]".
#include "unit_check.h"

#include <cmath>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/polygon.h>

using namespace unit_check;
using dealii::Point;
using slidewave::core::EdgeTest;
using slidewave::core::PolygonSide;

int
main()
{
  using namespace slidewave::core;
  const std::vector<Point<2>> square{{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}};
  const std::vector<Point<2>> clockwise{{0., 0.}, {0., 1.}, {1., 1.}, {1., 0.}};
  // An L: the unit square's right upper quarter taken out of a 2 x 2 square.
  const std::vector<Point<2>> ell{{0., 0.}, {2., 0.}, {2., 1.}, {1., 1.}, {1., 2.}, {0., 2.}};

  std::printf("areas and boxes\n");
  check(signed_area(square) == 1., "unit square counter-clockwise: +1");
  check(signed_area(clockwise) == -1., "unit square clockwise: -1");
  check(signed_area(ell) == 3., "L-shape: 3");
  check(signed_area({{0., 0.}, {1., 1.}, {2., 2.}}) == 0., "three collinear vertices: 0");
  check(signed_area({{0., 0.}, {1., 1.}}) == 0., "two vertices: 0");
  const auto box = bounding_box(ell);
  check(box.first == Point<2>(0., 0.) && box.second == Point<2>(2., 2.),
        "box of the L: (0, 0) to (2, 2)");

  std::printf("side_of\n");
  for (const EdgeTest test : {EdgeTest::distance, EdgeTest::collinear})
    {
      const double tolerance = test == EdgeTest::distance ? 0. : 1e-12;
      const char  *name      = test == EdgeTest::distance ? " (distance)" : " (collinear)";
      const auto   say       = [&](const char *what) { return std::string(what) + name; };
      check(side_of(square, {0.5, 0.5}, test, tolerance) == PolygonSide::inside,
            say("centre inside").c_str());
      check(side_of(clockwise, {0.5, 0.5}, test, tolerance) == PolygonSide::inside,
            say("centre inside, clockwise ring").c_str());
      check(side_of(square, {1.5, 0.5}, test, tolerance) == PolygonSide::outside,
            say("right of the square outside").c_str());
      check(side_of(ell, {1.5, 1.5}, test, tolerance) == PolygonSide::outside,
            say("the L's notch outside").c_str());
      check(side_of(ell, {0.5, 1.5}, test, tolerance) == PolygonSide::inside,
            say("the L's upper arm inside").c_str());
      check(side_of(square, {1., 1.}, test, tolerance) == PolygonSide::on_edge,
            say("a vertex on the edge").c_str());
      check(side_of(square, {0.25, 0.}, test, tolerance) == PolygonSide::on_edge,
            say("a point on a side on the edge").c_str());
      check(side_of(ell, {1.5, 1.}, test, tolerance) == PolygonSide::on_edge,
            say("a point on the notch's side on the edge").c_str());
      // The ray towards +x from (0.5, 1) in the L passes through the vertex (1, 1).
      check(side_of(ell, {0.5, 1.}, test, tolerance) == PolygonSide::inside,
            say("the ray through a vertex: inside").c_str());
    }
  check(side_of(square, {0.5, 1e-3}, EdgeTest::distance, 1e-2) == PolygonSide::on_edge,
        "1e-3 from a side, distance tolerance 1e-2: on the edge");
  check(side_of(square, {0.5, 1e-3}, EdgeTest::distance, 0.) == PolygonSide::inside,
        "1e-3 from a side, tolerance 0: inside");
  check(side_of(square, {0.5, -1e-3}, EdgeTest::distance, 0.) == PolygonSide::outside,
        "1e-3 outside a side, tolerance 0: outside");
  check(side_of(square, {0.5, 1e-14}, EdgeTest::collinear, 1e-12) == PolygonSide::on_edge,
        "1e-14 from a side, collinear to 1e-12: on the edge");
  check(side_of(square, {0.5, 1e-6}, EdgeTest::collinear, 1e-12) == PolygonSide::inside,
        "1e-6 from a side, collinear to 1e-12: inside");

  std::printf("parse_polygon\n");
  const auto read = parse_polygon("Region 1/Polygon", "0, 0; 2.5, 0; 0, -1e-3", "m");
  check(read.size() == 3 && read[1] == Point<2>(2.5, 0.) && read[2] == Point<2>(0., -1e-3),
        "three vertices read back exactly");
  const auto names_it = [](const std::string &text) {
    try
      {
        parse_polygon("Region 1/Polygon", text, "m");
      }
    catch (const slidewave::InputError &e)
      {
        std::printf("    (%s)\n", e.allowed.c_str());
        return std::string(e.what()).find("Region 1/Polygon") != std::string::npos;
      }
    return false;
  };
  check(names_it("0, 0; 1; 1, 1"), "a vertex of one number refused, naming the parameter");
  check(names_it("0, 0; one, 1; 1, 1"), "a word refused, naming the parameter");
  check(names_it("0, 0; inf, 1; 1, 1"), "an infinite value refused, naming the parameter");
  // Without a unit (the material regions): the message has no " [m]".
  try
    {
      parse_polygon("Region 1/Polygon", "0, 0; x, 1; 1, 1", "");
      check(false, "without a unit: a word refused");
    }
  catch (const slidewave::InputError &e)
    {
      std::printf("    (%s)\n", e.allowed.c_str());
      check(e.allowed.find("[m]") == std::string::npos, "without a unit: no unit in the message");
    }
  return finish();
}
