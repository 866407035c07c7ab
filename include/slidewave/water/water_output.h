#ifndef slidewave_water_water_output_h
#define slidewave_water_water_output_h

#include <memory>
#include <ostream>
#include <slidewave/water/shallow_water_1d.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace water
  {
    /**
     * Writes the water column at @p time to the CSV file @p file_name: a '# time = T' line,
     * then x,h,u,hu,bed,eta per cell (call on the writing rank only).
     */
    void
    write_profile(const ShallowWater1D &water, const std::string &file_name, double time);



    /**
     * The free-surface gauges of a scene (subsection "Gauges"): positions where eta is
     * recorded every step into a CSV file (time, then one column per gauge).
     */
    class GaugeRecorder
    {
    public:
      /**
       * Reads the comma-separated list @p text of positions; each must lie in
       * [@p left, @p right]. @p parameter names the entry in error messages.
       */
      void
      parse_positions(const std::string &parameter,
                      const std::string &text,
                      double             left,
                      double             right);

      /** Opens @p file_name and writes the header (only where @p is_writer, and only when
       *  there are gauges); with @p append, continues the file a resumed run put back. */
      void
      open(const std::string &file_name, bool is_writer, bool append = false);

      /** One row: @p time and eta at every gauge. */
      void
      record(double time, const ShallowWater1D &water);

      void
      flush();

    private:
      std::vector<double>           gauge_positions;
      std::unique_ptr<std::ostream> file;
      /** The file's name, for the message of a failed write. */
      std::string name;
    };
  } // namespace water
} // namespace slidewave

#endif
