#ifndef slidewave_terrain_gdal_diagnostics_h
#define slidewave_terrain_gdal_diagnostics_h

#include <string>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    /**
     * While it lives, what GDAL says on this thread (errors and warnings, e.g. "File short,
     * can't read line 3" or "Unable to open x.shx") is collected here instead of printed to
     * stderr, so that the InputError a caller throws can quote it. Scopes nest: GDAL's
     * handlers are a stack (CPLPushErrorHandlerEx / CPLPopErrorHandler).
     */
    class GdalDiagnostics
    {
    public:
      GdalDiagnostics();
      ~GdalDiagnostics();

      GdalDiagnostics(const GdalDiagnostics &) = delete;
      GdalDiagnostics &
      operator=(const GdalDiagnostics &)
        = delete;

      /** What GDAL said so far: its first three messages (each cut at 500 characters),
       *  joined by "; "; "" when it said nothing. */
      std::string
      text() const;

      /** " (GDAL: <text()>)", or "" when GDAL said nothing: to append to a message. */
      std::string
      note() const;

      /** Called by GDAL's error handler: keeps @p message. */
      void
      add(const char *message);

    private:
      std::vector<std::string> messages;
    };
  } // namespace terrain
} // namespace slidewave

#endif
