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
      char        *unit_name = nullptr;
      const double metres    = OSRGetLinearUnits(crs, &unit_name);
      if (metres != 1.)
        {
          const std::string unit = unit_name != nullptr ? unit_name : "?";
          OSRDestroySpatialReference(crs);
          throw InputError(parameter,
                           text,
                           "a projected CRS in metres that GDAL knows (e.g. 'EPSG:32616'), or "
                           "empty (this one's unit is the "
                             + unit + ", " + to_string(metres)
                             + " m: the model's coordinates are metres; use its metric twin, "
                             + metric_twin(text) + ")");
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



    std::string
    metric_twin(const std::string &text)
    {
      OGRSpatialReferenceH crs = from_wkt(text);
      if (crs == nullptr)
        return "none";
      char *wkt = nullptr;
      OSRExportToWkt(crs, &wkt);
      const std::string own = wkt != nullptr ? wkt : "";
      CPLFree(wkt);
      OSRDestroySpatialReference(crs);
      double metres = 1.;
      return crs_name(in_metres(own, metres));
    }



    std::string
    in_metres(const std::string &wkt, double &metres)
    {
      metres                   = 1.;
      OGRSpatialReferenceH crs = from_wkt(wkt);
      if (crs == nullptr || !OSRIsProjected(crs))
        {
          if (crs != nullptr)
            OSRDestroySpatialReference(crs);
          return wkt;
        }
      if (OSRIsCompound(crs))
        OSRStripVertical(crs);
      const double unit = OSRGetLinearUnits(crs, nullptr);
      if (unit == 1. || !(unit > 0.))
        {
          OSRDestroySpatialReference(crs);
          return wkt;
        }
      metres                 = unit;
      const std::string name = OSRGetName(crs) != nullptr ? OSRGetName(crs) : "unnamed";
      OSRSetLinearUnitsAndUpdateParameters(crs, SRS_UL_METER, 1.);
      // Its EPSG twin in metres, if GDAL knows one (EPSG:26943 for EPSG:2227): maps then
      // carry its code. The old name ("... (ftUS)") would lower GDAL's confidence in it.
      OSRSetProjCS(crs, "unnamed");
      int                   n_matches  = 0;
      int                  *confidence = nullptr;
      OGRSpatialReferenceH *matches    = OSRFindMatches(crs, nullptr, &n_matches, &confidence);
      OGRSpatialReferenceH  twin       = nullptr;
      for (int i = 0; i < n_matches && twin == nullptr; ++i)
        if (confidence[i] >= 90 && OSRIsSame(matches[i], crs))
          twin = OSRClone(matches[i]);
      OSRFreeSRSArray(matches);
      CPLFree(confidence);
      if (twin != nullptr)
        {
          OSRDestroySpatialReference(crs);
          crs = twin;
        }
      else
        OSRSetProjCS(crs, (name + ", in metres").c_str());
      char *text = nullptr;
      OSRExportToWkt(crs, &text);
      const std::string result = text;
      CPLFree(text);
      OSRDestroySpatialReference(crs);
      return result;
    }
  } // namespace terrain
} // namespace slidewave
