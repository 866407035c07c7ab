#ifndef slidewave_terrain_vector_polygons_h
#define slidewave_terrain_vector_polygons_h

#include <deal.II/base/point.h>
#include <limits>
#include <string>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    /** One polygon of a vector file, in the model's coordinates. */
    struct VectorPolygon
    {
      /** The outer ring, without the repeated closing vertex. */
      std::vector<dealii::Point<2>> outer;
      /** The rings cut out of it. */
      std::vector<std::vector<dealii::Point<2>>> holes;
      /** The feature's numeric attribute asked for; NaN when none was. */
      double attribute = std::numeric_limits<double>::quiet_NaN();
    };

    /**
     * The polygons of a vector file OGR reads (shapefile, GeoJSON, GeoPackage, any vector
     * driver): every feature of @p layer (empty: the first layer) whose geometry is a
     * polygon or a multipolygon (curved ones are linearized; a multipolygon gives one
     * VectorPolygon each), in the model's coordinates:
     * - a file with a CRS is reprojected by OGR to @p model_crs_wkt when that is given
     *   and differs; with no model CRS (a terrain from an expression or a table) a file
     *   in degrees is refused and a projected one is taken as it is;
     * - a file without a CRS is taken as being in the model's coordinates.
     * With @p attribute non-empty, each polygon carries the feature's value of that
     * numeric field (a release thickness per area, as AvaFrame's release files do).
     *
     * Every failure is an InputError naming @p parameter, the file and what is wrong: a
     * missing file or one without vector layers, an unknown layer or field, a feature
     * that is not a polygon, a missing or non-numeric attribute, no polygon at all, a
     * reprojection OGR cannot make.
     */
    std::vector<VectorPolygon>
    read_polygons(const std::string &parameter,
                  const std::string &filename,
                  const std::string &layer,
                  const std::string &model_crs_wkt,
                  const std::string &attribute = "");

    /** Writes @p polygons as a GeoJSON file of one polygon feature each (holes kept, the
     *  attribute as 'value' when it is a number), in the CRS @p crs_wkt ("" for none).
     *  Returns false if GDAL could not write it. */
    bool
    write_polygons(const std::string                &filename,
                   const std::vector<VectorPolygon> &polygons,
                   const std::string                &crs_wkt);
  } // namespace terrain
} // namespace slidewave

#endif
