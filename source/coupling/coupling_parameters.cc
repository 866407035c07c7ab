#include <slidewave/core/input_error.h>
#include <slidewave/coupling/coupling_parameters.h>
#include <string>

namespace slidewave
{
  namespace coupling
  {
    namespace
    {
      const std::string section = "Coupling";
    } // namespace



    void
    CouplingParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Water density",
                        "1000",
                        Double(0.),
                        "rho_w [kg/m^3]: the water's pressure and bed shear on the soil "
                        "(paper 000, Eq. 10).");
      prm.declare_entry("Water cells",
                        "grid columns",
                        Selection("grid columns|water mesh"),
                        "'grid columns': the water cells are the columns of the material "
                        "points' grid at set-up (non-uniform where it is refined; the bed is "
                        "the soil surface of each column, no interpolation between meshes). "
                        "'water mesh': the cells of 'Shallow water/Mesh'; the bed is "
                        "reconstructed on them by monotone cubic interpolation through the "
                        "column surfaces.");
      prm.declare_entry("Soil surface",
                        "envelope",
                        Selection("envelope|top"),
                        "How the soil makes the water's bed in each grid column. 'top': the "
                        "top of the highest point domain in the column, max (y_p + l_p); it "
                        "jumps by the height of a face when the first point enters a column. "
                        "'envelope': the mean across the column of the upper envelope of the "
                        "point domains (8 samples per column; the grid's floor where there "
                        "is no soil): the top where the soil fills the column, and growing "
                        "continuously as a face moves into a column.");
      prm.declare_entry("Water loads on soil",
                        "true",
                        Bool(),
                        "Whether the water's pressure and bed shear act on the soil (false: "
                        "one-way coupling, the soil moves the water only).");
      prm.declare_entry(
        "Water pressure on soil",
        "hydrostatic",
        Selection("hydrostatic|excess over initial level"),
        "Which water pressure loads the soil (with 'Water loads on soil = true'). "
        "'hydrostatic': the full pressure of the water, rho_w g (eta - z), applied as the "
        "buoyancy of the soil below the still level eta_s (a body force rho_w g V on the "
        "points below it) plus the pressure in excess of eta_s's on the soil's top and "
        "faces; the soil's stress then leaves out the still water's pressure (Terzaghi's "
        "effective stress; same deviator), and a submerged soil is driven by its buoyant "
        "unit weight. "
        "'excess over initial level': paper 000, Eq. 10, p = -rho_w g (eta - eta_0), "
        "eta_0 = h_0 + B_0 the free surface of each water cell at the start (after any "
        "gravity loading), kept through the run: still water loads nothing, a wave's crest "
        "pushes down and its trough pulls up; on a face of the bed, the thrust of the "
        "present level less that of the initial level. The soil then moves under its full "
        "weight, as if the still water were not there. Dry cells load nothing in both "
        "forms. See doc/coupled.md for when to choose which.");
      prm.declare_entry("Maximum substeps",
                        "1",
                        Integer(1, 1000),
                        "1: one step of both solvers per coupled step, the smaller of the two "
                        "stable steps (Eq. 38). N > 1: the solver with the smaller stable step "
                        "takes up to N steps inside one step of the other; bed and loads are "
                        "exchanged once per coupled step.");
      prm.enter_subsection("Verification");
      {
        prm.declare_entry("Tolerance on volume balance",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when, at any step, the water "
                          "volume differs from the initial volume plus the boundary inflow by "
                          "more than this fraction of the initial volume.");
        prm.declare_entry("Tolerance on free surface",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when, at any step, the free "
                          "surface over the wet cells is not flat to within this [m] (max eta "
                          "- min eta): the coupled lake at rest.");
        prm.declare_entry("Tolerance on soil speed",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when a material point ever "
                          "moves faster than this [m/s]: soil that must stay at rest.");
      }
      prm.leave_subsection();
    }



    void
    CouplingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      water_density  = prm.get_double("Water density");
      water_cells    = prm.get("Water cells") == "grid columns" ? WaterCells::grid_columns :
                                                                  WaterCells::water_mesh;
      soil_surface   = prm.get("Soil surface") == "top" ? SoilSurface::top : SoilSurface::envelope;
      loads_on_soil  = prm.get_bool("Water loads on soil");
      water_pressure = prm.get("Water pressure on soil") == "hydrostatic" ?
                         WaterPressure::hydrostatic :
                         WaterPressure::excess_over_initial_level;
      maximum_substeps = prm.get_integer("Maximum substeps");
      if (!(water_density > 0.))
        throw InputError(section + "/Water density",
                         to_string(water_density),
                         "a density > 0 kg/m^3");
      prm.enter_subsection("Verification");
      tolerance_volume       = prm.get_double("Tolerance on volume balance");
      tolerance_free_surface = prm.get_double("Tolerance on free surface");
      tolerance_soil_speed   = prm.get_double("Tolerance on soil speed");
      prm.leave_subsection();
    }
  } // namespace coupling
} // namespace slidewave
