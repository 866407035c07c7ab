#include <cmath>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/polygon.h>
#include <slidewave/particles/material_region.h>
#include <sstream>

namespace slidewave
{
  namespace particles
  {
    void
    MaterialRegion::declare_parameters(dealii::ParameterHandler &prm,
                                       const bool                with_material,
                                       const bool                with_vector_file)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Shape",
                        "none",
                        Selection(with_vector_file ? "none|rectangle|polygon|vector file" :
                                                     "none|rectangle|polygon"),
                        std::string("'none': this region is not used. 'rectangle': "
                                    "'Rectangle'. 'polygon': 'Polygon'. ")
                          + (with_vector_file ?
                               "'vector file': the polygons (holes and multipolygons "
                               "included) of 'Vector file'. " :
                               "")
                          + "Regions may overlap: a point (placed at the sub-cell centres) "
                            "belongs to the lowest-numbered region containing it, so a later "
                            "region fills only what earlier ones left.");
      if (with_vector_file)
        {
          prm.declare_entry("Vector file",
                            "",
                            Anything(),
                            "A vector file OGR reads (shapefile, GeoJSON, GeoPackage, ...; a "
                            "path relative to the scene file's directory) whose polygon "
                            "features are the area. Reprojected to the model's CRS (the "
                            "terrain raster's) when both have one; without a CRS its "
                            "coordinates are taken as the model's.");
          prm.declare_entry("Layer",
                            "",
                            Anything(),
                            "The layer of 'Vector file' to read; empty: its first layer.");
        }
      prm.declare_entry("Rectangle", "0, 0, 1, 1", Anything(), "x_min, y_min, x_max, y_max [m].");
      prm.declare_entry("Polygon",
                        "",
                        Anything(),
                        "Vertices 'x1, y1; x2, y2; ...' [m], at least three, in order "
                        "around the polygon.");
      if (with_material)
        prm.declare_entry("Material",
                          "",
                          Anything(),
                          "Name of the material filling the region (a 'Material N/Name').");
      prm.declare_entry("Initial velocity",
                        "0; 0",
                        Anything(),
                        "Initial velocity of the region's material points [m/s]: two "
                        "expressions of x and y separated by ';', e.g. '0.1*sin(pi*x/50); 0'.");
    }



    bool
    MaterialRegion::parse_parameters(dealii::ParameterHandler &prm,
                                     const std::string        &path,
                                     const bool                with_material)
    {
      shape = prm.get("Shape");
      if (shape == "none")
        return false;
      if (shape == "vector file")
        {
          vector_file  = dealii::Utilities::trim(prm.get("Vector file"));
          vector_layer = dealii::Utilities::trim(prm.get("Layer"));
          if (vector_file.empty())
            throw InputError(path + "/Vector file",
                             "",
                             "the name of a vector file OGR reads ('Shape = vector file')");
        }
      else if (shape == "rectangle")
        {
          const auto r = parse_number_list(path + "/Rectangle",
                                           prm.get("Rectangle"),
                                           "four numbers x_min, y_min, x_max, y_max");
          if (r.size() != 4 || !(r[2] > r[0]) || !(r[3] > r[1]))
            throw InputError(path + "/Rectangle",
                             prm.get("Rectangle"),
                             "four numbers x_min, y_min, x_max, y_max with x_min < x_max "
                             "and y_min < y_max");
          polygon = {dealii::Point<2>(r[0], r[1]),
                     dealii::Point<2>(r[2], r[1]),
                     dealii::Point<2>(r[2], r[3]),
                     dealii::Point<2>(r[0], r[3])};
        }
      else
        {
          polygon = core::parse_polygon(path + "/Polygon", prm.get("Polygon"), "");
          if (polygon.size() < 3)
            throw InputError(path + "/Polygon", prm.get("Polygon"), "at least three vertices");
        }
      if (with_material)
        {
          material_name = dealii::Utilities::trim(prm.get("Material"));
          if (material_name.empty())
            throw InputError(path + "/Material", "", "the name of a declared material");
        }
      const std::string velocity = prm.get("Initial velocity");
      const auto        parts    = dealii::Utilities::split_string_list(velocity, ';');
      // deal.II prints muparser's diagnosis to std::cerr before it throws: keep it quiet,
      // the InputError says what is wrong.
      std::ostringstream diagnosis;
      std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
      try
        {
          if (parts.size() != 2)
            throw std::invalid_argument("two components");
          velocity_function = std::make_shared<dealii::FunctionParser<2>>(2);
          velocity_function->initialize("x,y", velocity, {{"pi", M_PI}});
          velocity_function->value(dealii::Point<2>(), 0);
          std::cerr.rdbuf(cerr_buffer);
        }
      catch (...)
        {
          std::cerr.rdbuf(cerr_buffer);
          throw InputError(path + "/Initial velocity",
                           velocity,
                           "two expressions of x and y separated by ';' (muparser syntax)");
        }
      return true;
    }



    namespace
    {
      /** Where @p p lies with respect to the closed ring @p ring: on an edge when on its
       *  line to a relative 1e-12 (core::EdgeTest::collinear), else by the even-odd rule. */
      core::PolygonSide
      side_of(const std::vector<dealii::Point<2>> &ring, const dealii::Point<2> &p)
      {
        return core::side_of(ring, p, core::EdgeTest::collinear, 1e-12);
      }
    } // namespace



    bool
    MaterialRegion::contains(const dealii::Point<2> &p) const
    {
      // Points on an edge, the holes' included, count as inside.
      const core::PolygonSide side = side_of(polygon, p);
      if (side != core::PolygonSide::inside)
        return side == core::PolygonSide::on_edge;
      for (const auto &hole : holes)
        if (side_of(hole, p) == core::PolygonSide::inside)
          return false;
      return true;
    }



    dealii::Tensor<1, 2>
    MaterialRegion::initial_velocity(const dealii::Point<2> &p) const
    {
      dealii::Tensor<1, 2> v;
      v[0] = velocity_function->value(p, 0);
      v[1] = velocity_function->value(p, 1);
      return v;
    }



    std::pair<dealii::Point<2>, dealii::Point<2>>
    MaterialRegion::bounding_box() const
    {
      return core::bounding_box(polygon);
    }
  } // namespace particles
} // namespace slidewave
