#include <cpl_error.h>
#include <slidewave/terrain/gdal_diagnostics.h>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** GDAL's error handler while a GdalDiagnostics lives: hands the message to it. */
      void CPL_STDCALL
      collect(CPLErr, CPLErrorNum, const char *message)
      {
        if (auto *diagnostics = static_cast<GdalDiagnostics *>(CPLGetErrorHandlerUserData()))
          diagnostics->add(message);
      }
    } // namespace



    GdalDiagnostics::GdalDiagnostics()
    {
      CPLPushErrorHandlerEx(collect, this);
    }



    GdalDiagnostics::~GdalDiagnostics()
    {
      CPLPopErrorHandler();
    }



    void
    GdalDiagnostics::add(const char *message)
    {
      if (message == nullptr || messages.size() >= 3)
        return;
      std::string text = message;
      if (text.size() > 500)
        text = text.substr(0, 500) + "...";
      messages.push_back(text);
    }



    std::string
    GdalDiagnostics::text() const
    {
      std::string joined;
      for (const auto &message : messages)
        joined += (joined.empty() ? "" : "; ") + message;
      return joined;
    }



    std::string
    GdalDiagnostics::note() const
    {
      return messages.empty() ? std::string() : " (GDAL: " + text() + ")";
    }
  } // namespace terrain
} // namespace slidewave
