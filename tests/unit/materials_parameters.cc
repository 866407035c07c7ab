// MaterialParameters::parse_parameters() accepts a named material with the
// default values and a valid undrained clay, and refuses a missing name and
// out-of-range values with an InputError that names the parameter by its full
// path, repeats the value and says what is allowed: a negative density, nu =
// 0.5, phi = 95 degrees, a dilatancy angle above the friction angle, and the
// other range limits. The messages are printed and compared; the program exits
// non-zero if a bad value is accepted or a good one refused.
#include <cstdio>
#include <deal.II/base/parameter_handler.h>
#include <slidewave/core/input_error.h>
#include <slidewave/materials/material.h>
#include <string>
#include <utility>
#include <vector>

using namespace slidewave::materials;

namespace
{
  bool all_passed = true;

  /**
   * Declares the entries in "Materials/Clay", sets @p values, parses and prints
   * the outcome; @p should_pass says whether the values are valid.
   */
  void
  try_values(const std::vector<std::pair<std::string, std::string>> &values, const bool should_pass)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Materials");
    prm.enter_subsection("Clay");
    MaterialParameters::declare_parameters(prm);
    for (const auto &[entry, value] : values)
      prm.set(entry, value);

    std::string description;
    for (const auto &[entry, value] : values)
      description += (description.empty() ? "" : ", ") + entry + " = '" + value + "'";
    std::printf("%s\n", description.empty() ? "defaults" : description.c_str());

    MaterialParameters parameters;
    bool               passed = false;
    try
      {
        parameters.parse_parameters(prm, "Materials/Clay");
        passed = true;
        std::printf("  accepted: name '%s', density %g, E %g, nu %g, phi %g, c "
                    "%g, psi %g, "
                    "T %g\n",
                    parameters.name.c_str(),
                    parameters.density,
                    parameters.youngs_modulus,
                    parameters.poisson_ratio,
                    parameters.friction_angle,
                    parameters.cohesion,
                    parameters.dilatancy_angle,
                    parameters.tension_cutoff);
      }
    catch (const slidewave::InputError &e)
      {
        std::printf("  refused: %s\n", e.what());
      }
    if (passed != should_pass)
      {
        std::printf("  UNEXPECTED\n");
        all_passed = false;
      }
  }
} // namespace

int
main()
{
  // "Name" has no default: every material must be named.
  try_values({}, false);
  try_values({{"Name", "clay"}}, true);
  try_values({{"Name", "clay"},
              {"Model", "drucker prager"},
              {"Density", "2700"},
              {"Young's modulus", "1e6"},
              {"Poisson ratio", "0.4"},
              {"Friction angle", "0"},
              {"Cohesion", "3200"},
              {"Dilatancy angle", "0"},
              {"Tension cutoff", "0"}},
             true);
  try_values({{"Name", "clay"}, {"Poisson ratio", "-0.5"}}, true);

  try_values({{"Name", "clay"}, {"Density", "-1800"}}, false);
  try_values({{"Name", "clay"}, {"Young's modulus", "0"}}, false);
  try_values({{"Name", "clay"}, {"Poisson ratio", "0.5"}}, false);
  try_values({{"Name", "clay"}, {"Poisson ratio", "-1"}}, false);
  try_values({{"Name", "clay"}, {"Friction angle", "95"}}, false);
  try_values({{"Name", "clay"}, {"Friction angle", "-5"}}, false);
  try_values({{"Name", "clay"}, {"Friction angle", "25"}, {"Dilatancy angle", "30"}}, false);
  try_values({{"Name", "clay"}, {"Dilatancy angle", "-10"}}, true);
  try_values({{"Name", "clay"}, {"Dilatancy angle", "-31"}}, false);
  // The Hencky model takes a negative dilatancy as the small-strain one does, and refuses
  // an ill-posed one (nu = 0.45: G + 9 K alpha_phi alpha_psi = -1.2 G at psi = -30).
  try_values({{"Name", "clay"}, {"Model", "hencky drucker prager"}, {"Dilatancy angle", "-10"}},
             true);
  try_values({{"Name", "clay"},
              {"Model", "hencky drucker prager"},
              {"Poisson ratio", "0.45"},
              {"Dilatancy angle", "-30"}},
             false);
  try_values({{"Name", "clay"}, {"Cohesion", "-10"}}, false);
  try_values({{"Name", "clay"}, {"Tension cutoff", "-1"}}, false);
  try_values({{"Name", "  "}}, false);

  std::printf("\n%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
