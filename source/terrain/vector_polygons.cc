#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <filesystem>
#include <gdal_priv.h>
#include <memory>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/gdal_diagnostics.h>
#include <slidewave/terrain/vector_polygons.h>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** The vertices of @p ring without its repeated closing vertex. */
      std::vector<dealii::Point<2>>
      ring_points(const OGRLinearRing &ring)
      {
        std::vector<dealii::Point<2>> points;
        const int                     n = ring.getNumPoints();
        for (int i = 0; i < n; ++i)
          points.emplace_back(ring.getX(i), ring.getY(i));
        if (points.size() > 1 && points.front() == points.back())
          points.pop_back();
        return points;
      }



      /** Appends the polygon @p polygon to @p out; refuses a degenerate ring. */
      void
      append_polygon(const OGRPolygon           &polygon,
                     const double                attribute,
                     const std::string          &parameter,
                     const std::string          &filename,
                     const GIntBig               fid,
                     std::vector<VectorPolygon> &out)
      {
        if (polygon.IsEmpty())
          return;
        VectorPolygon result;
        result.outer = ring_points(*polygon.getExteriorRing());
        for (int i = 0; i < polygon.getNumInteriorRings(); ++i)
          result.holes.push_back(ring_points(*polygon.getInteriorRing(i)));
        if (result.outer.size() < 3)
          throw InputError(parameter,
                           filename,
                           "polygons with at least three vertices (feature " + std::to_string(fid)
                             + "'s outer ring has " + std::to_string(result.outer.size()) + ")");
        result.attribute = attribute;
        out.push_back(std::move(result));
      }



      /** The files GDAL reads for @p dataset, by name, comma-separated. */
      std::string
      files_of(GDALDataset &dataset)
      {
        std::string names;
        char      **files = dataset.GetFileList();
        for (char **file = files; file != nullptr && *file != nullptr; ++file)
          names += (names.empty() ? "" : ", ") + std::filesystem::path(*file).filename().string();
        CSLDestroy(files);
        return names;
      }



      /** Whether @p dataset is a shapefile whose .dbf (its attributes) GDAL did not find. */
      bool
      missing_dbf(GDALDataset &dataset, const std::string &filename)
      {
        if (dataset.GetDriver() == nullptr
            || !EQUAL(dataset.GetDriver()->GetDescription(), "ESRI Shapefile"))
          return false;
        char **files = dataset.GetFileList();
        bool   found = false;
        for (char **file = files; file != nullptr && *file != nullptr; ++file)
          found = found || EQUAL(CPLGetExtension(*file), "dbf");
        CSLDestroy(files);
        return !found && !std::filesystem::is_directory(filename);
      }



      /** Refuses a @p layer whose CRS @p own is in degrees but whose coordinates cannot be
       *  (outside longitudes [-360, 360] or latitudes [-90, 90]): metres in a file without
       *  its CRS, such as a GeoJSON without a 'crs' member, which RFC 7946 makes WGS 84. */
      void
      require_degrees(OGRLayer                  &layer,
                      const OGRSpatialReference &own,
                      const std::string         &parameter,
                      const std::string         &filename)
      {
        OGREnvelope box;
        if (!own.IsGeographic() || layer.GetExtent(&box, TRUE) != OGRERR_NONE)
          return;
        // The axis order GDAL gives a file's geometries: x is the longitude.
        if (box.MinX >= -360. && box.MaxX <= 360. && box.MinY >= -90. && box.MaxY <= 90.)
          return;
        const std::string name = own.GetName() != nullptr ? own.GetName() : "unnamed";
        throw InputError(parameter,
                         filename,
                         "polygons in degrees, as the file's CRS (" + name
                           + ") says (a GeoJSON without a 'crs' member is in WGS 84, RFC 7946): "
                             "longitudes in [-360, 360] and latitudes in [-90, 90] (this file's "
                             "coordinates span ["
                           + to_string(box.MinX) + ", " + to_string(box.MaxX) + "] x ["
                           + to_string(box.MinY) + ", " + to_string(box.MaxY)
                           + "]: metres? Give the file its CRS, e.g. with ogr2ogr -a_srs "
                             "EPSG:32616, or a 'crs' member)");
      }



      /** The transformation from @p layer's CRS to the model's, or none (nullptr) when
       *  the coordinates are taken as they are. */
      std::unique_ptr<OGRCoordinateTransformation>
      to_model(OGRLayer          &layer,
               const std::string &model_crs_wkt,
               const std::string &parameter,
               const std::string &filename)
      {
        const OGRSpatialReference *own = layer.GetSpatialRef();
        if (own == nullptr)
          return nullptr;
        require_degrees(layer, *own, parameter, filename);
        if (model_crs_wkt.empty())
          {
            // Two sets of coordinates, one with a CRS and one without, cannot be matched:
            // taking the file's as the model's would be a guess.
            const std::string name = own->GetName() != nullptr ? own->GetName() : "unnamed";
            throw InputError(parameter,
                             filename,
                             "polygons in the model's coordinates: this file has a CRS (" + name
                               + (own->IsGeographic() ? ", in degrees" : "")
                               + ") and the terrain has none to reproject it to (set "
                                 "'Terrain/Coordinates CRS' to the CRS of the model's x, y, "
                                 "use a terrain raster with a CRS, or a file without a CRS: a "
                                 "shapefile without .prj)");
          }
        OGRSpatialReference source(*own), target;
        source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        if (target.importFromWkt(model_crs_wkt.c_str()) != OGRERR_NONE)
          throw InputError(parameter, filename, "a model CRS OGR reads (the terrain's)");
        if (source.IsSame(&target))
          return nullptr;
        CPLPushErrorHandler(CPLQuietErrorHandler);
        std::unique_ptr<OGRCoordinateTransformation> transformation(
          OGRCreateCoordinateTransformation(&source, &target));
        CPLPopErrorHandler();
        if (transformation == nullptr)
          throw InputError(parameter,
                           filename,
                           "polygons in a CRS OGR can transform to the terrain's (it cannot "
                           "transform from this file's)");
        return transformation;
      }



      /** The vector file @p filename, opened by OGR (its diagnosis silenced); refuses a file
       *  OGR cannot read or one without vector layers. */
      GDALDatasetUniquePtr
      open_vector_file(const std::string &parameter, const std::string &filename)
      {
        GDALAllRegister();
        const GdalDiagnostics diagnostics;
        GDALDatasetUniquePtr  dataset(
          GDALDataset::Open(filename.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
        if (dataset == nullptr || dataset->GetLayerCount() == 0)
          {
            // What GDAL says of a file that is there (a shapefile without its .shx, ...);
            // of a missing one it would only repeat the path.
            std::error_code error;
            if (std::filesystem::exists(filename, error) && !diagnostics.text().empty())
              throw InputError(parameter,
                               filename,
                               "a vector file OGR reads (shapefile, GeoJSON, GeoPackage, ...; "
                               "GDAL cannot read this one: "
                                 + diagnostics.text() + ")");
            throw InputError(parameter,
                             filename,
                             "a vector file OGR reads (shapefile, GeoJSON, GeoPackage, ...): it "
                             "does not exist or holds no vector layer");
          }
        return dataset;
      }



      /** The layer @p layer_name of @p dataset (empty: its first); refuses an unknown name,
       *  listing the layers there are. */
      OGRLayer &
      find_layer(GDALDataset       &dataset,
                 const std::string &layer_name,
                 const std::string &parameter,
                 const std::string &filename)
      {
        OGRLayer *layer
          = layer_name.empty() ? dataset.GetLayer(0) : dataset.GetLayerByName(layer_name.c_str());
        if (layer == nullptr)
          {
            std::string names;
            for (int i = 0; i < dataset.GetLayerCount(); ++i)
              names += std::string(i > 0 ? ", '" : "'") + dataset.GetLayer(i)->GetName() + "'";
            throw InputError(parameter,
                             filename,
                             "a file with the layer '" + layer_name + "' (its layers: " + names
                               + ")");
          }
        return *layer;
      }



      /** The index of the numeric field @p attribute of @p layer, -1 when @p attribute is
       *  empty; refuses a missing or non-numeric field. */
      int
      numeric_field(GDALDataset       &dataset,
                    OGRLayer          &layer,
                    const std::string &attribute,
                    const std::string &parameter,
                    const std::string &filename)
      {
        int field = -1;
        if (!attribute.empty())
          {
            field = layer.GetLayerDefn()->GetFieldIndex(attribute.c_str());
            if (field < 0 && layer.GetLayerDefn()->GetFieldCount() == 0
                && missing_dbf(dataset, filename))
              throw InputError(parameter,
                               filename,
                               "a shapefile with its attribute table, the .dbf next to it, "
                               "holding the numeric field '"
                                 + attribute + "' (GDAL finds no .dbf: only " + files_of(dataset)
                                 + ")");
            if (field < 0)
              throw InputError(parameter,
                               filename,
                               "a layer with the numeric field '" + attribute
                                 + "' (this one has "
                                   "no such field)");
            const OGRFieldType type = layer.GetLayerDefn()->GetFieldDefn(field)->GetType();
            if (type != OFTReal && type != OFTInteger && type != OFTInteger64)
              throw InputError(parameter,
                               filename,
                               "a layer whose field '" + attribute + "' is numeric");
          }
        return field;
      }



      /** The value of the field @p field (named @p attribute) of @p feature, NaN when
       *  @p field is -1; refuses a feature without a value. */
      double
      field_value(OGRFeature        &feature,
                  const int          field,
                  const std::string &attribute,
                  const std::string &parameter,
                  const std::string &filename)
      {
        double value = std::numeric_limits<double>::quiet_NaN();
        if (field >= 0)
          {
            if (!feature.IsFieldSetAndNotNull(field))
              throw InputError(parameter,
                               filename,
                               "a value of '" + attribute + "' on every polygon (feature "
                                 + std::to_string(feature.GetFID()) + " has none)");
            value = feature.GetFieldAsDouble(field);
          }
        return value;
      }



      /** @p geometry (of the feature @p fid) with its curves made line strings, in the
       *  model's coordinates (@p transformation, none: as it is). */
      std::unique_ptr<OGRGeometry>
      linear_in_model(const OGRGeometry           &geometry,
                      OGRCoordinateTransformation *transformation,
                      const std::string           &parameter,
                      const std::string           &filename,
                      const GIntBig                fid)
      {
        std::unique_ptr<OGRGeometry> linear(geometry.getLinearGeometry());
        if (OGRGeometryFactory::haveGEOS())
          {
            // GEOS says why (self-intersection at or near a point, ...) through GDAL's
            // error handler.
            const GdalDiagnostics diagnostics;
            if (!linear->IsValid())
              throw InputError(parameter,
                               filename,
                               "valid polygons, as OGR's IsValid checks them (feature "
                                 + std::to_string(fid) + " is not"
                                 + (diagnostics.text().empty() ? "" : ": " + diagnostics.text())
                                 + "; a self-intersecting ring, a bow tie, has no inside to "
                                   "release: repair it, e.g. with ogr2ogr -makevalid)");
          }
        const GdalDiagnostics diagnostics;
        if (transformation != nullptr && linear->transform(transformation) != OGRERR_NONE)
          throw InputError(parameter,
                           filename,
                           "polygons OGR can transform to the terrain's CRS (feature "
                             + std::to_string(fid) + " failed" + diagnostics.note() + ")");
        return linear;
      }



      /** Appends the polygon or the parts of the multipolygon @p linear (the feature @p fid,
       *  of value @p value) to @p out; refuses any other geometry. */
      void
      append_polygons(OGRGeometry                &linear,
                      const double                value,
                      const std::string          &parameter,
                      const std::string          &filename,
                      const GIntBig               fid,
                      std::vector<VectorPolygon> &out)
      {
        switch (wkbFlatten(linear.getGeometryType()))
          {
            case wkbPolygon:
              append_polygon(*linear.toPolygon(), value, parameter, filename, fid, out);
              break;
            case wkbMultiPolygon:
              for (const OGRPolygon *part : *linear.toMultiPolygon())
                append_polygon(*part, value, parameter, filename, fid, out);
              break;
            default:
              throw InputError(parameter,
                               filename,
                               "a file of polygons (feature " + std::to_string(fid) + " is a "
                                 + OGRGeometryTypeToName(linear.getGeometryType()) + ")");
          }
      }
    } // namespace



    std::vector<VectorPolygon>
    read_polygons(const std::string &parameter,
                  const std::string &filename,
                  const std::string &layer_name,
                  const std::string &model_crs_wkt,
                  const std::string &attribute)
    {
      const GDALDatasetUniquePtr dataset = open_vector_file(parameter, filename);
      OGRLayer                  &layer   = find_layer(*dataset, layer_name, parameter, filename);
      const auto transformation          = to_model(layer, model_crs_wkt, parameter, filename);
      const int  field = numeric_field(*dataset, layer, attribute, parameter, filename);

      std::vector<VectorPolygon> polygons;
      // What GDAL says while it reads the features (a coordinate that is not a number, a
      // ring not closed) is kept for the message, not printed.
      const GdalDiagnostics diagnostics;
      layer.ResetReading();
      for (const auto &feature : layer)
        {
          const OGRGeometry *geometry = feature->GetGeometryRef();
          if (geometry == nullptr || geometry->IsEmpty())
            continue;
          const GIntBig fid   = feature->GetFID();
          const double  value = field_value(*feature, field, attribute, parameter, filename);
          const std::unique_ptr<OGRGeometry> linear
            = linear_in_model(*geometry, transformation.get(), parameter, filename, fid);
          append_polygons(*linear, value, parameter, filename, fid, polygons);
        }
      if (polygons.empty())
        throw InputError(parameter,
                         filename,
                         "a layer with at least one polygon (it has none" + diagnostics.note()
                           + ")");
      return polygons;
    }



    bool
    write_polygons(const std::string                &filename,
                   const std::vector<VectorPolygon> &polygons,
                   const std::string                &crs_wkt)
    {
      GDALAllRegister();
      GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("GeoJSON");
      if (driver == nullptr)
        return false;
      GDALDatasetUniquePtr dataset(driver->Create(filename.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
      if (dataset == nullptr)
        return false;
      OGRSpatialReference crs;
      if (!crs_wkt.empty())
        {
          crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
          crs.importFromWkt(crs_wkt.c_str());
        }
      OGRLayer *layer
        = dataset->CreateLayer("release", crs_wkt.empty() ? nullptr : &crs, wkbPolygon, nullptr);
      if (layer == nullptr)
        return false;
      OGRFieldDefn field("value", OFTReal);
      layer->CreateField(&field);
      const auto ring_of = [](const std::vector<dealii::Point<2>> &points) {
        OGRLinearRing ring;
        for (const auto &p : points)
          ring.addPoint(p[0], p[1]);
        ring.closeRings();
        return ring;
      };
      for (const auto &polygon : polygons)
        {
          OGRPolygon    geometry;
          OGRLinearRing outer = ring_of(polygon.outer);
          geometry.addRing(&outer);
          for (const auto &hole : polygon.holes)
            {
              OGRLinearRing inner = ring_of(hole);
              geometry.addRing(&inner);
            }
          OGRFeature feature(layer->GetLayerDefn());
          if (std::isfinite(polygon.attribute))
            feature.SetField("value", polygon.attribute);
          feature.SetGeometry(&geometry);
          if (layer->CreateFeature(&feature) != OGRERR_NONE)
            return false;
        }
      return true;
    }
  } // namespace terrain
} // namespace slidewave
