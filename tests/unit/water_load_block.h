// The fixture of the water-load unit tests (coupling_water_loads.cc,
// coupling_excess_water_loads.cc): the check printer and a 1 m x 1 m block of elastic soil
// [0, 1] x [0, 1] against the left side of a [0, 2] x [0, 1.5] grid of 0.1 m cells, 2 x 2
// GIMP points per cell, with point forces.
#ifndef slidewave_tests_unit_water_load_block_h
#define slidewave_tests_unit_water_load_block_h

#include "unit_check.h"

#include <cstdio>
#include <deal.II/base/parameter_handler.h>
#include <slidewave/soil/material_point_parameters.h>

namespace
{
  using unit_check::check;
  /** Rank 0 prints (unit_check::print follows it). */
  inline bool root = true;

  slidewave::soil::MaterialPointParameters
  block_in_a_tank()
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Material points");
    slidewave::soil::MaterialPointParameters::declare_parameters(prm);
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
    slidewave::soil::MaterialPointParameters result;
    prm.enter_subsection("Material points");
    result.parse_parameters(prm, "Material points");
    prm.leave_subsection();
    result.point_forces = true;
    return result;
  }
} // namespace

#endif
