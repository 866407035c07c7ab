#include <cpl_conv.h>
#include <cpl_error.h>
#include <ogr_srs_api.h>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/crs.h>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** The CRS of @p wkt, or nullptr when it is empty or GDAL cannot read it (owned by
       *  the caller: OSRDestroySpatialReference). */
      OGRSpatialReferenceH
      from_wkt(const std::string &wkt)
      {
        if (wkt.empty())
          return nullptr;
        OGRSpatialReferenceH crs = OSRNewSpatialReference(nullptr);
        CPLPushErrorHandler(CPLQuietErrorHandler);
        const bool ok = OSRSetFromUserInput(crs, wkt.c_str()) == OGRERR_NONE;
        CPLPopErrorHandler();
        if (!ok)
          {
            OSRDestroySpatialReference(crs);
            return nullptr;
          }
        return crs;
      }
    } // namespace



    std::string
    projected_crs_wkt(const std::string &parameter, const std::string &text)
    {
      if (text.empty())
        return "";
      OGRSpatialReferenceH crs = from_wkt(text);
      if (crs == nullptr || !OSRIsProjected(crs))
        {
          if (crs != nullptr)
            OSRDestroySpatialReference(crs);
          throw InputError(parameter,
                           text,
                           "a projected CRS in metres that GDAL knows (e.g. 'EPSG:32616'), or "
                           "empty");
        }
      OSRAutoIdentifyEPSG(crs);
      char *wkt = nullptr;
      OSRExportToWkt(crs, &wkt);
      const std::string result = wkt;
      CPLFree(wkt);
      OSRDestroySpatialReference(crs);
      return result;
    }



    std::string
    crs_name(const std::string &wkt)
    {
      if (wkt.empty())
        return "none";
      OGRSpatialReferenceH crs = from_wkt(wkt);
      if (crs == nullptr)
        return "a CRS GDAL cannot read";
      std::string name      = OSRGetName(crs) != nullptr ? OSRGetName(crs) : "unnamed CRS";
      const char *authority = OSRGetAuthorityName(crs, nullptr);
      const char *code      = OSRGetAuthorityCode(crs, nullptr);
      if (authority != nullptr && code != nullptr)
        name += std::string(" (") + authority + ":" + code + ")";
      OSRDestroySpatialReference(crs);
      return name;
    }



    bool
    same_crs(const std::string &a, const std::string &b)
    {
      if (a.empty() || b.empty())
        return a.empty() && b.empty();
      OGRSpatialReferenceH ca = from_wkt(a), cb = from_wkt(b);
      const bool           same = ca != nullptr && cb != nullptr && OSRIsSame(ca, cb);
      if (ca != nullptr)
        OSRDestroySpatialReference(ca);
      if (cb != nullptr)
        OSRDestroySpatialReference(cb);
      return same;
    }
  } // namespace terrain
} // namespace slidewave
