#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/grid/grid_extent.h>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      /** The gravity, the hydrostatic term, the transfer scheme and the time step. */
      void
      declare_scheme_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.declare_entry("Gravity", "9.81", Double(0.), "g [m/s^2], along -z.");
        prm.declare_entry("Hydrostatic term",
                          "standard",
                          Selection("standard|still level"),
                          "'standard': the pressure 1/2 rho g h merged into the effective "
                          "stress and the body force -rho g h grad Z (paper 001, Eqs. 14-15). "
                          "'still level': both written about a known still level H + Z = "
                          "'Still level' (Eq. 41): 1/2 rho g (h^2 - H^2) and -rho g (h - H) "
                          "grad Z, which vanish exactly for material at rest at that level "
                          "(H = 0 where the terrain is above it).");
        prm.declare_entry("Still level",
                          "0",
                          Double(),
                          "Elevation of the still level [m] ('Hydrostatic term = still level').");
        prm.declare_entry("Slope correction",
                          "bed normal",
                          Selection("none|bed normal"),
                          "'bed normal': the weight of a column on a slope of angle theta "
                          "(cos^2 theta = 1 / (1 + |grad Z|^2) at the column) acts on the bed "
                          "with the normal stress rho g h cos^2 theta (h the vertical "
                          "thickness): the slope term, the Coulomb friction and the pressure "
                          "are those of the slope-parallel (Savage-Hutter) equations projected "
                          "on the plan view, and a block slides at the exact g cos^2 theta "
                          "(tan theta - tan phi) horizontally at every slope. 'none': paper "
                          "001's plan-view terms with the full g, a block sliding at "
                          "g (tan theta - tan phi), 1 / cos^2 theta too fast (twice at 45 deg). "
                          "Both take 'depth' as the vertical thickness "
                          "(doc/depth-averaged.md, Slope correction).");
        prm.declare_entry("Shape functions",
                          "gimp",
                          Selection("q1|gimp|cpgimp"),
                          "'q1': bilinear (paper 001, Eqs. 20-21; the paper's choice). "
                          "'gimp', 'cpgimp': the generalized interpolation of paper 000, "
                          "Eq. 11 (the domain of 'cpgimp' follows the column's stretch). "
                          "The default 'gimp' converges on every exact case of "
                          "doc/depth-averaged.md and, unlike 'q1', stays stable at a dry front "
                          "with viscosity (What to choose).");
        prm.declare_entry("FLIP fraction",
                          "0.8",
                          Double(0., 1.),
                          "Velocity update of the points: 0 = PIC (paper 001, Eq. 33, the "
                          "paper's choice), 1 = FLIP (Eq. 34), between = the blend. The "
                          "default 0.8 puts the dry fronts of the exact cases within 2 % "
                          "(PIC's damping holds them back by 5-10 %) and gives Stoker's wet "
                          "dam break a smaller error than PIC (doc/depth-averaged.md, The dry "
                          "front). It is the blend of a step at the default 'Courant number' "
                          "0.5 (dt_ref = 0.5 times the stable step, Eq. 22's and the viscous "
                          "one); a step dt blends FLIP^(dt / dt_ref), so that PIC's damping "
                          "is a rate and the results converge as the step shrinks.");
        prm.declare_entry("Split stretch",
                          "1.5",
                          Double(0.),
                          "A column whose width along x or y has grown to this many times its "
                          "initial width (the cell over 'Particles per direction') splits in two "
                          "along that direction, each half with half its mass and volume; 0: "
                          "never. Without splitting the columns of a thinning front drift "
                          "apart until they no longer feel one another, whatever the cell "
                          "size (doc/depth-averaged.md, Column splitting). At least 1.5 (the "
                          "halves then start at least three quarters of a new column wide).");
        prm.declare_entry("Courant number",
                          "0.5",
                          Double(0.),
                          "C of Eq. 22: dt = C h / max_p (|v_p| + sqrt(g h_p)), at most "
                          "0.7071 (the explicit step on a 2D grid of bilinear cells).");
        prm.declare_entry("Depth update",
                          "projection",
                          Selection("strain|projection"),
                          "'strain': h_p / (1 + tr(delta eps_p)) each step (paper 001, Eq. 38, "
                          "the paper's choice), the depth carried by the point: exact for "
                          "material at rest or translating, but it does not converge under "
                          "refinement once the flow stretches. 'projection' (the default): "
                          "each step the depth "
                          "starts from the columns' volumes projected on the nodes, "
                          "h_i = sum_p V_p N_i / a_i (a_i the node's lumped area), read back at "
                          "the point, then Eq. 38 adds the step's change: the depth stays "
                          "consistent with where the columns are (doc/depth-averaged.md, "
                          "Shallow-water limit), but a depth that varies within a cell is "
                          "smoothed: a lake at rest over a bump is no longer exact, and the "
                          "edge of a layer is spread over one cell (first order, "
                          "doc/depth-averaged.md, Rigid translation).");
        prm.declare_entry("Fixed time step",
                          "0",
                          Double(0.),
                          "If > 0, this step instead of Eq. 22 (checked against its limit at "
                          "the start).");
        prm.declare_entry("Detailed timing",
                          "false",
                          Bool(),
                          "Time the parts of each step as rows 'depth averaged step: ...' of "
                          "the timer summary.");
      }



      /** Subsection "Grid": its extent and the condition on each side. */
      void
      declare_grid_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Grid");
        {
          grid::GridExtent::declare_parameters(prm, "0.2");
          prm.declare_entry("Extent",
                            "corners",
                            Selection("corners|terrain raster"),
                            "'corners': the grid spans 'Lower left' to 'Upper right'. 'terrain "
                            "raster': the largest grid of whole cells, its corners on multiples "
                            "of 'Cell size', inside the terrain raster's data (after "
                            "reprojection: inside the wedges of no-data a raster in degrees "
                            "gets at its corners); the corners are then not used. The grid "
                            "chosen is printed at the start.");
          for (const std::string side : {"Left", "Right", "Bottom", "Top"})
            prm.declare_entry(side + " side",
                              "wall",
                              Selection("wall|open"),
                              "'wall': zero normal velocity (free slip). 'open': material "
                              "leaves the domain and is counted as lost mass.");
        }
        prm.leave_subsection();
      }



      /** Subsection "Material": the density and the Bingham law. */
      void
      declare_material_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Material");
        {
          prm.declare_entry("Density", "1200", Double(0.), "rho [kg/m^3].");
          prm.declare_entry("Viscosity",
                            "0",
                            Double(0.),
                            "mu of the depth-integrated Bingham law [Pa s] (Eq. 3).");
          prm.declare_entry("Yield stress",
                            "0",
                            Double(0.),
                            "tau_Y of the Bingham law [Pa] (Eq. 3). mu = tau_Y = 0: an "
                            "inviscid fluid, the shallow water equations.");
          prm.declare_entry("Regularization time",
                            "100",
                            Double(0.),
                            "m [s] of Papanastasiou's regularization of the yield stress: "
                            "tau_Y (1 - exp(-m sqrt(I_2))) / sqrt(I_2) instead of "
                            "tau_Y / sqrt(I_2), the same once m sqrt(I_2) >> 1 and a finite "
                            "viscosity tau_Y m at rest. 0: the plain law of Eq. 3, whose "
                            "stress at rest is undetermined: in an explicit step, round-off "
                            "sets still material moving (doc/depth-averaged.md). The time "
                            "step respects the viscous limit of 2 mu + tau_Y m.");
        }
        prm.leave_subsection();
      }



      /** Subsection "Basal friction": the Voellmy law. */
      void
      declare_basal_friction_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Basal friction");
        {
          prm.declare_entry("Model",
                            "none",
                            Selection("none|Voellmy"),
                            "'Voellmy' (paper 001, Eq. 2): a basal shear stress of "
                            "p_A tan(phi) + rho g h tan(phi) + rho g |v|^2 / xi against the "
                            "motion, applied at the nodes so that it can stop the material "
                            "but never reverse it (doc/depth-averaged.md).");
          prm.declare_entry("Friction angle", "0", Double(0., 89.), "phi [degrees].");
          prm.declare_entry("Turbulence coefficient",
                            "0",
                            Double(0.),
                            "xi [m/s^2]; 0: no turbulent term.");
          prm.declare_entry("Atmospheric pressure",
                            "0",
                            Double(0.),
                            "p_A of Eq. 2 [Pa] (the paper's term; 0 leaves the purely "
                            "frictional and turbulent parts).");
        }
        prm.leave_subsection();
      }



      /** Subsection "Terrain": where the elevation comes from. */
      void
      declare_terrain_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Terrain");
        {
          prm.declare_entry("Source",
                            "expression",
                            Selection("expression|table|raster"),
                            "'expression': 'Elevation', a function of x and y. 'table': 'Table "
                            "file', the elevations at the nodes of a regular grid. 'raster': "
                            "'Raster file', a DEM GDAL reads (GeoTIFF, ESRI ASCII grid, ...); the "
                            "grid's corners are then in the raster's metric coordinates.");
          prm.declare_entry("Raster file",
                            "",
                            Anything(),
                            "The DEM ('Source = raster'; a path relative to the scene file's "
                            "directory). Band 1 at the pixel centres, interpolated bilinearly; "
                            "no-data under the domain is refused; a raster in degrees is "
                            "reprojected by GDAL's warper to 'Target CRS'.");
          prm.declare_entry("Raster without CRS",
                            "refuse",
                            Selection("refuse|metric"),
                            "A raster that has no coordinate reference system is refused, or "
                            "with 'metric' its coordinates are taken as metres.");
          prm.declare_entry("Target CRS",
                            "",
                            Anything(),
                            "The projected CRS a raster in degrees is reprojected to, as GDAL "
                            "reads it (e.g. 'EPSG:32632'); empty: the UTM zone of the raster's "
                            "centre.");
          prm.declare_entry("Coordinates CRS",
                            "",
                            Anything(),
                            "The projected CRS of the model's x, y when the terrain has none "
                            "(an expression, a table, a raster read with 'Raster without CRS = "
                            "metric'), as GDAL reads it (e.g. 'EPSG:32616'): a release file or "
                            "depth raster in another CRS is then reprojected to it, and the "
                            "hazard maps carry it. Empty: the model's coordinates have no CRS, "
                            "and a release file or depth raster that has one is refused. A "
                            "terrain raster with its own CRS needs none (if given, it must be "
                            "the raster's).");
          prm.declare_entry("Table file",
                            "",
                            Anything(),
                            "A CSV file of rows x,y,z at the nodes of a regular grid covering "
                            "the domain (any order, '#' comments and a header allowed; a path "
                            "relative to the scene file's directory). Interpolated bilinearly, "
                            "as it is: its spacing is its own ('Spacing' is not used).");
          prm.declare_entry("Elevation",
                            "0",
                            Anything(),
                            "Z(x, y) [m], a muparser expression of x and y (pi defined). It is "
                            "sampled once on a grid of 'Spacing' and interpolated bilinearly "
                            "(terrain::ElevationGrid): a plane is exact.");
          prm.declare_entry("Spacing",
                            "0",
                            Double(0.),
                            "Spacing of the elevation grid [m]; 0: a quarter of the cell size.");
        }
        prm.leave_subsection();
      }



      /** Subsection "Release": the area and the initial depth of the material. */
      void
      declare_release_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Release");
        {
          particles::MaterialRegion::declare_parameters(prm,
                                                        /*with_material=*/false,
                                                        /*with_vector_file=*/true);
          prm.declare_entry("Depth",
                            "",
                            Anything(),
                            "Initial depth h(x, y) [m] of the material in the area, a muparser "
                            "expression; no point where it is 0 or less. Give exactly one of "
                            "'Depth', 'Surface', 'Depth raster' and 'Depth attribute'.");
          prm.declare_entry("Depth raster",
                            "",
                            Anything(),
                            "A raster GDAL reads (a path relative to the scene file's "
                            "directory) of the initial depth [m] inside the area: each point "
                            "takes the value of the pixel that holds it (r.avaflow's release "
                            "height map). Reprojected to the terrain's CRS when it is in "
                            "another one (nearest pixel); no-data under a point of the area is "
                            "refused, 0 or less means no material.");
          prm.declare_entry("Depth attribute",
                            "",
                            Anything(),
                            "With 'Shape = vector file': the numeric field of each polygon that "
                            "holds its depth [m] (AvaFrame's release files carry it as "
                            "'thickness').");
          prm.declare_entry("Surface",
                            "",
                            Anything(),
                            "Initial surface h + Z(x, y) [m] instead of the depth: h = "
                            "surface - Z with the terrain as interpolated (a still level is "
                            "then exact to the last bit).");
          prm.declare_entry("Particles per direction",
                            "4",
                            Integer(1, 10),
                            "n x n material points per cell at the centres of n x n sub-cells "
                            "(paper 001, Eqs. 17-18: V_p = h_p A_p, m_p = rho V_p; the paper "
                            "uses 2). 4 costs less than halving the cell for the same error "
                            "and keeps a thinning front connected longer "
                            "(doc/depth-averaged.md, What to choose).");
          prm.declare_entry("Depth measured",
                            "vertically",
                            Selection("vertically|normal to the slope"),
                            "How 'Depth' is measured: 'vertically' (the model's h), or 'normal "
                            "to the slope' (a thickness T, as release areas are often mapped): "
                            "h = T sqrt(1 + |grad Z|^2) = T / cos(slope). Not with 'Surface'.");
        }
        prm.leave_subsection();
      }
    } // namespace



    void
    DepthAveragedParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      declare_scheme_parameters(prm);
      declare_grid_parameters(prm);
      declare_material_parameters(prm);
      declare_basal_friction_parameters(prm);
      declare_terrain_parameters(prm);
      declare_release_parameters(prm);

      prm.enter_subsection("Adaptive grid");
      grid::AdaptiveGridParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Load balancing");
      grid::LoadBalancingParameters::declare_parameters(prm);
      prm.leave_subsection();
    }
  } // namespace depth_averaged
} // namespace slidewave
