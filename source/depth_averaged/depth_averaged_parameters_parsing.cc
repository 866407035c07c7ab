#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/grid/grid_extent.h>
#include <slidewave/terrain/crs.h>
#include <sstream>

// DepthAveragedParameters, its reading: parse_parameters() reads every subsection and
// checks what it read (an InputError naming the parameter, the value and what is
// allowed). The declarations, with their documentation, are in
// depth_averaged_parameters.cc.
namespace slidewave
{
  namespace depth_averaged
  {
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
