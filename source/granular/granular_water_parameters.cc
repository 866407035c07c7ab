#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/granular/granular_water_parameters.h>

namespace slidewave
{
  namespace granular
  {
    void
    GranularWaterParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Grain density",
                        "2650",
                        Double(0.),
                        "rho^s, the density of the grains [kg/m^3]. A point's mass is its "
                        "grains' mass: the materials' 'Density' is the dry density "
                        "(1 - n_0) rho^s, which sets the initial porosity n_0 = 1 - Density / "
                        "rho^s (must lie in (0, 0.99]).");
      prm.declare_entry("Permeability law",
                        "constant",
                        Selection("constant|Kozeny-Carman"),
                        "'constant': every point has the intrinsic permeability "
                        "'Permeability'. 'Kozeny-Carman': k(n) = D50^2 n^3 / (180 (1 - n)^2) "
                        "of each point's porosity n (capped at 0.99; paper 002, Eq. 4).");
      prm.declare_entry("Permeability",
                        "1e-10",
                        Double(0.),
                        "k, the intrinsic permeability of the 'constant' law [m^2] (the "
                        "hydraulic conductivity is k rho^f g / mu^f).");
      prm.declare_entry("D50",
                        "1e-3",
                        Double(0.),
                        "The grains' mean diameter [m] of the Kozeny-Carman law.");
      prm.declare_entry("Suspension porosity",
                        "0.6",
                        Double(0., 1.),
                        "n_s, in (0, 1]: where a cell's points together are looser than it (their "
                        "mass over their volume below (1 - n_s) rho^s), their grains are out "
                        "of contact, a suspension in the water: they carry no effective "
                        "stress and have no stiffness; compacted below n_s again, they take "
                        "stress from zero (the granular stress vanishes below the loosest packing, "
                        "as in Baumgarten and Kamrin's mixture model, J. Fluid Mech. 2019). "
                        "The step takes every point's P-wave speed at its density but not "
                        "below the density of contact (1 - n_s) rho^s, so a dilated point "
                        "keeps the step of the contact it may make within it. 0.6 is a "
                        "solid fraction of 0.4, looser than any random packing of grains "
                        "(spheres: 0.55); raise it for a skeleton that holds at a larger "
                        "porosity (soft clays). A material looser than n_s starts as a "
                        "suspension (with 'Initial stress/Type = none'); 1: the grains never "
                        "lose contact.");
      prm.declare_entry("Drag law",
                        "Forchheimer",
                        Selection("Darcy|Forchheimer"),
                        "'Forchheimer' (paper 002, Eq. 3): C = n^2 mu / k + n^3 rho^w F / "
                        "sqrt(k) |v^w - v^s|, F = 1.75 / sqrt(150 n^3) (Ergun's "
                        "coefficients), each point's relative speed that of the last step at "
                        "its nodes. 'Darcy': C = n^2 mu / k, linear in the relative velocity "
                        "(the limit of slow seepage, Re_p << 10).");
      prm.declare_entry(
        "Drag coupling",
        "semi-implicit projected",
        Selection("semi-implicit projected|semi-implicit consistent|semi-implicit|explicit"),
        "How the water's pressure and drag of the new step act on the "
        "skeleton. 'semi-implicit projected' (the default): the skeleton's "
        "nodal velocity of the new step, with the drag and the pressure "
        "gradient implicit, is eliminated from the water's equations (the "
        "drag against the skeleton's predicted velocity, the Darcy flow "
        "through the grains as a pressure diffusion); the skeleton's nodes "
        "then take the projection, on a weighted mass matrix (conjugate "
        "gradients), of the increment that elimination assumed. Stable at "
        "any ratio of the step to rho^s (1 - n) k / mu, so low "
        "permeabilities and fine grains do not limit the step; without "
        "the lumped drag's smoothing, so the locked mixture's motion "
        "converges in the step (doc/granular-water.md: the undrained "
        "vortex); with 'Velocity transfer = flip' only (with apic a short "
        "standing wave grows where the grains are permeable). "
        "'semi-implicit consistent': the skeleton's nodal velocity is solved "
        "with the water's (GMRES on the water's system with the grains' "
        "nodal momentum eliminated, a conjugate-gradient solve of the grains' "
        "nodes per product, preconditioned by the projected coupling's "
        "matrix): the grains, on their lumped nodal masses, take exactly the "
        "drag and pressure the water loses, and the pressure's increment does "
        "on them the work the water's continuity counts; with flip and with "
        "apic. "
        "Toward the undrained limit less accurate than the projected "
        "coupling (doc/granular-water.md, \"The consistent coupling\"). "
        "'semi-implicit': the same water as the projected; the skeleton's nodes take the "
        "drag implicitly, lumped: v_I = (m_I v_I^trial + dt integral of N_I "
        "C u) / (m_I + dt integral of N_I C). Where the drag is stiff this "
        "smooths the grains' velocity once per step, a damping that grows "
        "as the step shrinks (the undrained vortex loses its energy at a "
        "rate that rises as the step falls); with 'Sub-cycling' this or "
        "'explicit'. "
        "'explicit': the water sees the skeleton's velocity of the old step "
        "and the skeleton the water's force of the new one (paper 002, "
        "§3.5); stable only for steps below about rho^s (1 - n) k / mu, "
        "which then limits the step.");
      prm.declare_entry("Top load",
                        "0",
                        Double(0.),
                        "A pressure [Pa] on the top row of points of the skeleton, as a "
                        "downward point force of the load times each point's width "
                        "(Terzaghi's load p0); 0: none.");
      prm.declare_entry("Sub-cycling",
                        "false",
                        Bool(),
                        "true: the skeleton takes several explicit steps (each within its "
                        "P-wave limit) inside one step of the water, whose step is then "
                        "limited only by its Courant number and the explicit coupling's "
                        "rho^s (1 - n) k / mu: fewer water solves where the skeleton's wave "
                        "speed, not the coupling, limits the step (permeable sands). The "
                        "water sees the skeleton of the start of its step; the skeleton "
                        "feels the water's new pressure and velocity with its own current "
                        "velocity in the drag at every sub-step. With 'Drag coupling' = "
                        "semi-implicit or explicit. false: one step each.");
      prm.enter_subsection("Verification");
      {
        prm.declare_entry("Exact solution",
                          "none",
                          Selection("none|Terzaghi|at rest|seepage|settling"),
                          "'Terzaghi': one-dimensional consolidation of a column of height "
                          "'Column height' with a drained top and an impervious base under "
                          "'Top load' (Material 1 linear elastic, no gravity): the pore "
                          "pressure of the nodes in the column at the 'Time factors' "
                          "T_v = c_v t / H^2 against the series solution, normalized by the "
                          "load, and the average degree of consolidation U against "
                          "1 - sum 2 / M^2 exp(-M^2 T_v). 'at rest': a saturated column of "
                          "height 'Column height' under water up to the grid's open top, "
                          "settled under gravity by the end: the pore pressure of the nodes "
                          "against rho^w g (top - y), relative to rho^w g H, and the points' "
                          "effective stresses against the buoyant geostatic state "
                          "sigma'_yy = -(rho_dry - (1 - n_0) rho^w) g (H - y), sigma'_xx = "
                          "nu / (1 - nu) sigma'_yy (Material 1 linear elastic), relative "
                          "to its value at the base. 'seepage': water flowing down at the "
                          "superficial velocity U of the top inflow ('Free surface flow/"
                          "Boundary conditions/Top = inflow', bottom open, no gravity) through "
                          "a layer of height 'Column height' resting on the grid's bottom: "
                          "the pressure gradient in the layer's middle half (nodes' least "
                          "squares) against the steady dp/dy = C(n_0, k, U / n_0) U / n_0^2 "
                          "of the drag law (Darcy's mu U / k plus the Forchheimer term), "
                          "relative to it. 'settling': a uniform suspension (Material 1, of any "
                          "model, looser than 'Suspension porosity', Darcy drag) from the grid's "
                          "bottom to 'Column height' H in a closed column of water: before "
                          "the bed reaches it, the fall of the row of points started nearest "
                          "below 0.7 H against v_inf (t - tau (1 - exp(-t / tau))), v_inf = "
                          "(1 - n_0) (rho^s - rho^w) g k / mu; after, the points' volume over "
                          "the width against max(H - fall, H (1 - n_0) / (1 - n_s)) (the bed "
                          "under the rest of the suspension, then the bed alone); relative "
                          "to the exact value.");
        prm.declare_entry("Column height", "1", Double(0.), "H of the column [m].");
        prm.declare_entry("Time factors",
                          "0.05, 0.1, 0.2, 0.5, 1",
                          Anything(),
                          "T_v at which the pore pressure is compared (comma-separated, > 0, "
                          "increasing).");
        prm.declare_entry("Tolerance",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when the largest error of "
                          "the pore pressure over the profiles exceeds it (relative to the "
                          "load).");
      }
      prm.leave_subsection();
    }



    void
    GranularWaterParameters::parse_parameters(dealii::ParameterHandler &prm,
                                              const std::string        &path)
    {
      grain_density       = prm.get_double("Grain density");
      permeability_law    = prm.get("Permeability law") == "constant" ? PermeabilityLaw::constant :
                                                                        PermeabilityLaw::kozeny_carman;
      permeability        = prm.get_double("Permeability");
      d50                 = prm.get_double("D50");
      top_load            = prm.get_double("Top load");
      suspension_porosity = prm.get_double("Suspension porosity");
      if (!(suspension_porosity > 0.))
        throw InputError(path + "/Suspension porosity",
                         to_string(suspension_porosity),
                         "a porosity in (0, 1] (1: the grains never lose contact)");
      forchheimer                = prm.get("Drag law") == "Forchheimer";
      sub_cycling                = prm.get_bool("Sub-cycling");
      const std::string coupling = prm.get("Drag coupling");
      implicit_drag              = coupling != "explicit";
      projected_drag             = coupling == "semi-implicit projected";
      consistent_drag            = coupling == "semi-implicit consistent";
      for (const auto &[name, value] :
           {std::pair<std::string, double>{"Grain density", grain_density},
            {"Permeability", permeability},
            {"D50", d50}})
        if (!(value > 0.) || !std::isfinite(value))
          throw InputError(path + "/" + name, to_string(value), "a finite number > 0");
      prm.enter_subsection("Verification");
      {
        const std::string exact = prm.get("Exact solution");
        exact_solution          = exact == "Terzaghi" ? GranularExactSolution::terzaghi :
                                  exact == "at rest"  ? GranularExactSolution::at_rest :
                                  exact == "seepage"  ? GranularExactSolution::seepage :
                                  exact == "settling" ? GranularExactSolution::settling :
                                                        GranularExactSolution::none;
        column_height           = prm.get_double("Column height");
        tolerance               = prm.get_double("Tolerance");
        const std::string name  = path + "/Verification/Time factors";
        time_factors            = parse_number_list(name,
                                         prm.get("Time factors"),
                                         "comma-separated numbers > 0, increasing");
        for (unsigned int i = 0; i < time_factors.size(); ++i)
          if (!(time_factors[i] > 0.) || (i > 0 && !(time_factors[i] > time_factors[i - 1])))
            throw InputError(name,
                             prm.get("Time factors"),
                             "comma-separated numbers > 0, increasing");
        if (exact_solution == GranularExactSolution::terzaghi && !(top_load > 0.))
          throw InputError(path + "/Top load",
                           to_string(top_load),
                           "a load > 0 with 'Exact solution = Terzaghi'");
        if (exact_solution != GranularExactSolution::none && !(column_height > 0.))
          throw InputError(path + "/Verification/Column height",
                           to_string(column_height),
                           "a height > 0 with an exact solution");
      }
      prm.leave_subsection();
    }
  } // namespace granular
} // namespace slidewave
