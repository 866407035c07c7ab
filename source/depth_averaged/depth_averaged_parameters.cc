#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/grid/grid_extent.h>
#include <slidewave/terrain/crs.h>
#include <sstream>

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



    namespace
    {
      /** Checks that @p expression parses as a function of x and y. */
      void
      check_expression(const std::string &parameter, const std::string &expression)
      {
        // deal.II prints muparser's diagnosis to std::cerr before it throws: keep it
        // quiet, the InputError says what is wrong.
        std::ostringstream        diagnosis;
        std::streambuf           *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
        dealii::FunctionParser<2> f(1);
        try
          {
            f.initialize("x,y", expression, {{"pi", M_PI}});
            f.value(dealii::Point<2>());
            std::cerr.rdbuf(cerr_buffer);
          }
        catch (...)
          {
            std::cerr.rdbuf(cerr_buffer);
            throw InputError(parameter, expression, "an expression of x and y (muparser syntax)");
          }
      }



      /** Subsection "Grid": the extent (the corners, or the terrain raster's) and the sides. */
      void
      parse_grid_parameters(dealii::ParameterHandler &prm,
                            const std::string        &path,
                            DepthAveragedParameters  &parameters)
      {
        prm.enter_subsection("Grid");
        {
          parameters.grid_from_raster = prm.get("Extent") == "terrain raster";
          grid::GridExtent extent;
          extent.parse_parameters(prm,
                                  path + "/Grid",
                                  /*with_corners=*/!parameters.grid_from_raster);
          parameters.lower_left  = extent.lower_left;
          parameters.upper_right = extent.upper_right;
          parameters.cell_size   = extent.cell_size;
          unsigned int d         = 0;
          for (const std::string side : {"Left", "Right", "Bottom", "Top"})
            parameters.sides[d++] = prm.get(side + " side") == "open" ? grid::GridBoundary::free :
                                                                        grid::GridBoundary::roller;
        }
        prm.leave_subsection();
      }



      /** Subsection "Material": the density (> 0) and the Bingham law. */
      void
      parse_material_parameters(dealii::ParameterHandler &prm,
                                const std::string        &path,
                                DepthAveragedParameters  &parameters)
      {
        prm.enter_subsection("Material");
        {
          parameters.density = prm.get_double("Density");
          require_positive(path + "/Material/Density", parameters.density);
          parameters.viscosity      = prm.get_double("Viscosity");
          parameters.yield_stress   = prm.get_double("Yield stress");
          parameters.regularization = prm.get_double("Regularization time");
        }
        prm.leave_subsection();
      }



      /** Subsection "Basal friction": the model and its coefficients. */
      void
      parse_basal_friction_parameters(dealii::ParameterHandler &prm,
                                      DepthAveragedParameters  &parameters)
      {
        prm.enter_subsection("Basal friction");
        {
          parameters.friction             = prm.get("Model") == "Voellmy";
          parameters.friction_angle       = prm.get_double("Friction angle") * M_PI / 180.;
          parameters.turbulence           = prm.get_double("Turbulence coefficient");
          parameters.atmospheric_pressure = prm.get_double("Atmospheric pressure");
        }
        prm.leave_subsection();
      }



      /** Subsection "Terrain": the elevation's source, checked against the grid. */
      void
      parse_terrain_parameters(dealii::ParameterHandler &prm,
                               const std::string        &path,
                               DepthAveragedParameters  &parameters)
      {
        prm.enter_subsection("Terrain");
        {
          parameters.elevation = dealii::Utilities::trim(prm.get("Elevation"));
          check_expression(path + "/Terrain/Elevation", parameters.elevation);
          parameters.elevation_table.clear();
          parameters.elevation_raster.clear();
          parameters.raster_options.assume_metric = prm.get("Raster without CRS") == "metric";
          parameters.raster_options.target_crs    = dealii::Utilities::trim(prm.get("Target CRS"));
          parameters.coordinates_crs_wkt
            = terrain::projected_crs_wkt(path + "/Terrain/Coordinates CRS",
                                         dealii::Utilities::trim(prm.get("Coordinates CRS")));
          if (parameters.grid_from_raster && prm.get("Source") != "raster")
            throw InputError(path + "/Grid/Extent",
                             "terrain raster",
                             "'corners' unless 'Terrain/Source = raster' (here it is '"
                               + prm.get("Source") + "')");
          if (prm.get("Source") == "raster")
            {
              parameters.elevation_raster = dealii::Utilities::trim(prm.get("Raster file"));
              if (parameters.elevation_raster.empty())
                throw InputError(path + "/Terrain/Raster file",
                                 "",
                                 "the name of a raster file ('Source = raster')");
            }
          if (prm.get("Source") == "table")
            {
              parameters.elevation_table = dealii::Utilities::trim(prm.get("Table file"));
              if (parameters.elevation_table.empty())
                throw InputError(path + "/Terrain/Table file",
                                 "",
                                 "the name of a CSV file x,y,z ('Source = table')");
            }
          parameters.terrain_spacing = prm.get_double("Spacing");
          if (parameters.terrain_spacing == 0.)
            parameters.terrain_spacing = 0.25 * parameters.cell_size;
          if (parameters.terrain_spacing > parameters.cell_size)
            throw InputError(path + "/Terrain/Spacing",
                             prm.get("Spacing"),
                             "0 or a spacing at most the cell size ("
                               + to_string(parameters.cell_size)
                               + " m): the terrain must be resolved at least as finely as the "
                                 "flow");
        }
        prm.leave_subsection();
      }



      /** Subsection "Release": the area inside the grid and one source of its depth. */
      void
      parse_release_parameters(dealii::ParameterHandler &prm,
                               const std::string        &path,
                               DepthAveragedParameters  &parameters)
      {
        prm.enter_subsection("Release");
        {
          const std::string release_path = path + "/Release";
          parameters.release             = particles::MaterialRegion();
          if (!parameters.release.parse_parameters(prm, release_path, /*with_material=*/false))
            throw InputError(release_path + "/Shape",
                             "none",
                             "'rectangle' or 'polygon': the area the material is released from");
          // A vector file's polygons are checked when read (they need the terrain's CRS),
          // all areas when the grid is fitted to the raster (by then).
          if (parameters.release.vector_file.empty() && !parameters.grid_from_raster)
            {
              const auto box = parameters.release.bounding_box();
              for (unsigned int d = 0; d < 2; ++d)
                if (box.first[d] < parameters.lower_left[d] - 1e-12
                    || box.second[d] > parameters.upper_right[d] + 1e-12)
                  throw InputError(release_path + "/Shape",
                                   prm.get("Shape"),
                                   "a release area inside the grid ["
                                     + to_string(parameters.lower_left[0]) + ", "
                                     + to_string(parameters.upper_right[0]) + "] x ["
                                     + to_string(parameters.lower_left[1]) + ", "
                                     + to_string(parameters.upper_right[1]) + "]");
            }
          parameters.depth             = dealii::Utilities::trim(prm.get("Depth"));
          parameters.surface           = dealii::Utilities::trim(prm.get("Surface"));
          parameters.depth_raster      = dealii::Utilities::trim(prm.get("Depth raster"));
          parameters.depth_attribute   = dealii::Utilities::trim(prm.get("Depth attribute"));
          const unsigned int n_sources = !parameters.depth.empty() + !parameters.surface.empty()
                                         + !parameters.depth_raster.empty()
                                         + !parameters.depth_attribute.empty();
          if (n_sources != 1)
            throw InputError(release_path + "/Depth",
                             parameters.depth,
                             "exactly one of 'Depth', 'Surface', 'Depth raster' and 'Depth "
                             "attribute' (here "
                               + std::string(n_sources == 0 ? "none is" : "several are")
                               + " given)");
          if (!parameters.depth.empty())
            check_expression(release_path + "/Depth", parameters.depth);
          if (!parameters.surface.empty())
            check_expression(release_path + "/Surface", parameters.surface);
          if (!parameters.depth_attribute.empty() && parameters.release.vector_file.empty())
            throw InputError(release_path + "/Depth attribute",
                             parameters.depth_attribute,
                             "an attribute only with 'Shape = vector file' (the field of its "
                             "polygons that holds their depth)");
          parameters.particles_per_direction = prm.get_integer("Particles per direction");
          parameters.depth_normal_to_slope   = prm.get("Depth measured") == "normal to the slope";
          if (parameters.depth_normal_to_slope && !parameters.surface.empty())
            throw InputError(release_path + "/Depth measured",
                             prm.get("Depth measured"),
                             "'vertically' when the release is given by its 'Surface'");
        }
        prm.leave_subsection();
      }
    } // namespace



    void
    DepthAveragedParameters::parse_parameters(dealii::ParameterHandler &prm,
                                              const std::string        &path)
    {
      gravity = prm.get_double("Gravity");
      require_positive(path + "/Gravity", gravity);
      hydrostatic_term        = prm.get("Hydrostatic term") == "still level" ?
                                  HydrostaticTerm::still_level :
                                  HydrostaticTerm::standard;
      still_level             = prm.get_double("Still level");
      slope_correction        = prm.get("Slope correction") == "none" ? SlopeCorrection::none :
                                                                        SlopeCorrection::bed_normal;
      const std::string shape = prm.get("Shape functions");
      shape_function          = shape == "gimp"   ? grid::ShapeFunction::gimp :
                                shape == "cpgimp" ? grid::ShapeFunction::cpgimp :
                                                    grid::ShapeFunction::q1;
      flip_fraction           = prm.get_double("FLIP fraction");
      split_stretch           = prm.get_double("Split stretch");
      if (split_stretch != 0. && split_stretch < 1.5)
        throw InputError(path + "/Split stretch",
                         prm.get("Split stretch"),
                         "0 (no splitting) or at least 1.5: the halves of a column split at "
                         "this stretch are half as wide, so below 1.5 they would start "
                         "narrower than three quarters of a new column, and below 1 every "
                         "new column would split at its first step");
      courant_number = prm.get_double("Courant number");
      if (!(courant_number > 0. && courant_number <= 0.70710678118654752))
        throw InputError(path + "/Courant number",
                         prm.get("Courant number"),
                         "a number in (0, 0.7071]: the explicit step on a 2D grid of "
                         "bilinear cells with lumped mass is stable only up to 1/sqrt(2)");
      fixed_time_step = prm.get_double("Fixed time step");
      depth_update
        = prm.get("Depth update") == "projection" ? DepthUpdate::projection : DepthUpdate::strain;
      detailed_timing = prm.get_bool("Detailed timing");

      parse_grid_parameters(prm, path, *this);
      parse_material_parameters(prm, path, *this);
      parse_basal_friction_parameters(prm, *this);
      parse_terrain_parameters(prm, path, *this);
      parse_release_parameters(prm, path, *this);

      prm.enter_subsection("Adaptive grid");
      adaptivity.parse_parameters(prm, path + "/Adaptive grid");
      prm.leave_subsection();
      if (adaptivity.enabled)
        {
          // The corners of 'Extent = terrain raster' are fitted to the coarsest cells later.
          if (!grid_from_raster)
            adaptivity.check_divides(lower_left, upper_right, cell_size, path + "/Adaptive grid");
          // Between two adaptations a column travels at most 'Courant number' cells per
          // step, and its shape functions reach one cell further: it must stay in fine cells.
          const double reach = courant_number * adaptivity.interval + 1.;
          if (fixed_time_step == 0. && !(adaptivity.buffer_cells > reach))
            throw InputError(path + "/Adaptive grid/Buffer cells",
                             std::to_string(adaptivity.buffer_cells),
                             "more layers than the columns can travel between two adaptations "
                             "plus their reach, 'Courant number' x 'Interval' + 1 = "
                               + to_string(reach) + " (or a shorter 'Interval')");
        }
      prm.enter_subsection("Load balancing");
      balancing.parse_parameters(prm);
      prm.leave_subsection();
    }
  } // namespace depth_averaged
} // namespace slidewave
