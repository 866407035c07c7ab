#include <algorithm>
#include <cmath>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/release.h>
#include <slidewave/terrain/crs.h>
#include <slidewave/terrain/raster_source.h>
#include <slidewave/terrain/vector_polygons.h>
#include <sstream>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      const std::string path = "Depth averaged/Release";

      /** Refuses @p area unless it lies inside the grid: an InputError naming @p parameter
       *  = @p value, what is allowed and @p which ("it", "polygon 2"). */
      void
      check_inside_grid(const particles::MaterialRegion &area,
                        const DepthAveragedParameters   &prm,
                        const std::string               &parameter,
                        const std::string               &value,
                        const std::string               &which);

      /** "[x0, x1] x [y0, y1]" */
      std::string
      box_text(const dealii::Point<2> &lower, const dealii::Point<2> &upper)
      {
        std::ostringstream text;
        text.precision(12);
        text << "[" << lower[0] << ", " << upper[0] << "] x [" << lower[1] << ", " << upper[1]
             << "]";
        return text.str();
      }



      void
      check_inside_grid(const particles::MaterialRegion &area,
                        const DepthAveragedParameters   &prm,
                        const std::string               &parameter,
                        const std::string               &value,
                        const std::string               &which)
      {
        const auto [lower, upper] = area.bounding_box();
        for (unsigned int d = 0; d < 2; ++d)
          if (lower[d] < prm.lower_left[d] - 1e-12 || upper[d] > prm.upper_right[d] + 1e-12)
            throw InputError(parameter,
                             value,
                             "a release area inside the grid "
                               + box_text(prm.lower_left, prm.upper_right) + " (" + which
                               + " spans " + box_text(lower, upper)
                               + " in the model's coordinates)");
      }
    } // namespace



    Release::Release(const DepthAveragedParameters &parameters,
                     const terrain::ElevationGrid  &terrain,
                     const std::string             &model_crs_wkt)
      : prm(parameters)
      , elevation(terrain)
    {
      if (prm.release.vector_file.empty())
        {
          areas.push_back(prm.release);
          check_inside_grid(prm.release, prm, path + "/Shape", prm.release.shape, "it");
        }
      else
        for (auto &polygon : terrain::read_polygons(path + "/Vector file",
                                                    prm.release.vector_file,
                                                    prm.release.vector_layer,
                                                    model_crs_wkt,
                                                    prm.depth_attribute))
          {
            particles::MaterialRegion area = prm.release;
            area.vector_file.clear();
            area.polygon = std::move(polygon.outer);
            area.holes   = std::move(polygon.holes);
            check_inside_grid(area,
                              prm,
                              path + "/Vector file",
                              prm.release.vector_file,
                              "polygon " + std::to_string(areas.size() + 1));
            if (!prm.depth_attribute.empty() && !std::isfinite(polygon.attribute))
              throw InputError(path + "/Depth attribute",
                               prm.depth_attribute,
                               "a field with a finite value on every polygon");
            areas.push_back(std::move(area));
            area_depth.push_back(polygon.attribute);
          }

      if (!prm.depth_raster.empty())
        {
          // The window under the areas; a raster that stops within half a pixel of it
          // still covers it (the pixel holding a point is what is read).
          dealii::Point<2> lower = areas.front().bounding_box().first, upper = lower;
          for (const auto &area : areas)
            {
              const auto [l, u] = area.bounding_box();
              for (unsigned int d = 0; d < 2; ++d)
                {
                  lower[d] = std::min(lower[d], l[d]);
                  upper[d] = std::max(upper[d], u[d]);
                }
            }
          terrain::RasterOptions options = prm.raster_options;
          options.match_crs              = model_crs_wkt;
          options.resampling             = "near";
          options.nodata_as_nan          = true;
          options.window_name            = "the release area";
          // Values of 0 or less mean no material, whatever they are.
          options.lowest_value   = -std::numeric_limits<double>::infinity();
          options.highest_value  = terrain::largest_release_depth;
          options.values_allowed = "release depths of at most "
                                   + to_string(terrain::largest_release_depth)
                                   + " m, 0 or less meaning no material";
          // One opening (and warp) for the extent and the values.
          const terrain::RasterSource raster(path + "/Depth raster", prm.depth_raster, options);
          const auto                  extent = raster.extent();
          if (model_crs_wkt.empty() && !extent.crs_wkt.empty())
            throw InputError(path + "/Depth raster",
                             prm.depth_raster,
                             "a raster in the model's coordinates: this one has a CRS ("
                               + terrain::crs_name(extent.crs_wkt)
                               + ") and the terrain has none to reproject it to (set "
                                 "'Terrain/Coordinates CRS' to the CRS of the model's x, y, or "
                                 "use a terrain raster with a CRS)");
          const double half[2] = {0.5 * extent.pixel_x, 0.5 * extent.pixel_y};
          for (unsigned int d = 0; d < 2; ++d)
            {
              if (lower[d] < extent.lower[d] && lower[d] >= extent.lower[d] - half[d])
                lower[d] = extent.lower[d];
              if (upper[d] > extent.upper[d] && upper[d] <= extent.upper[d] + half[d])
                upper[d] = extent.upper[d];
            }
          depth_raster = std::make_unique<terrain::ElevationGrid>(raster.window(lower, upper));
        }
      else if (prm.depth_attribute.empty())
        {
          depth_function = std::make_unique<dealii::FunctionParser<2>>(1);
          depth_function->initialize("x,y",
                                     prm.depth.empty() ? prm.surface : prm.depth,
                                     {{"pi", M_PI}});
        }
    }



    double
    Release::depth(const dealii::Point<2> &p, const unsigned int region) const
    {
      double h;
      if (depth_raster != nullptr)
        h = depth_raster->nearest_value(p);
      else if (!prm.depth_attribute.empty())
        h = area_depth[region];
      else
        {
          const double value = depth_function->value(p);
          h                  = prm.surface.empty() ? value : value - elevation.value(p);
        }
      if (prm.depth_normal_to_slope)
        h *= std::sqrt(1. + elevation.gradient(p).norm_square());
      return h;
    }



    std::pair<std::string, std::string>
    Release::depth_source() const
    {
      if (!prm.depth_raster.empty())
        return {"Depth raster", prm.depth_raster};
      if (!prm.depth_attribute.empty())
        return {"Depth attribute", prm.depth_attribute};
      if (!prm.surface.empty())
        return {"Surface", prm.surface};
      return {"Depth", prm.depth};
    }
  } // namespace depth_averaged
} // namespace slidewave
