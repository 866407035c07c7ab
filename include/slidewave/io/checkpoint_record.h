#ifndef slidewave_io_checkpoint_record_h
#define slidewave_io_checkpoint_record_h

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace io
  {
    /**
     * The text part of a checkpoint: named numbers, lists of numbers and words, written with
     * 17 significant digits so that every double comes back bit for bit. Each component of a
     * scene puts what decides its future under names of its own ("water/depth", "run/time");
     * a missing or malformed entry on reading is a damaged checkpoint.
     */
    class CheckpointRecord
    {
    public:
      void
      put(const std::string &name, double value);

      void
      put(const std::string &name, const std::vector<double> &values);

      void
      put_text(const std::string &name, const std::string &text);

      /** A list of (time, file name) pairs, as a .pvd record keeps them (names without
       *  '|' and line breaks). */
      void
      put_files(const std::string &name, const std::vector<std::pair<double, std::string>> &files);

      double
      get(const std::string &name) const;

      unsigned int
      get_unsigned(const std::string &name) const;

      const std::vector<double> &
      get_vector(const std::string &name) const;

      const std::string &
      get_text(const std::string &name) const;

      std::vector<std::pair<double, std::string>>
      get_files(const std::string &name) const;

      /** One entry per line: "name n v1 ... vn" or "name = text". */
      void
      write(const std::string &file_name) const;

      /** Reads what write() wrote; throws InputError naming @p file_name if it is damaged. */
      void
      read(const std::string &file_name);

    private:
      /** The entry @p name; throws InputError (a damaged checkpoint) when there is none. */
      template <typename Value>
      const Value &
      find_entry(const std::map<std::string, Value> &entries, const std::string &name) const;

      std::string                                file_name;
      std::map<std::string, std::vector<double>> numbers;
      std::map<std::string, std::string>         texts;
    };
  } // namespace io
} // namespace slidewave

#endif
