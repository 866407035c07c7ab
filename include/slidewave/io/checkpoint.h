#ifndef slidewave_io_checkpoint_h
#define slidewave_io_checkpoint_h

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



    /**
     * Checkpoints of every kind of scene, in one directory layout: OUTPUT/checkpoint holds
     * the newest, OUTPUT/checkpoint.previous the one before. A checkpoint is written into
     * OUTPUT/checkpoint.tmp and renamed when complete, so a run killed while writing leaves
     * both earlier ones intact; resuming takes the newest complete one.
     *
     * Each checkpoint holds:
     * - `scene.txt`: the signature of the scene that wrote it (its physics and whatever a
     *   resumed run must share with it), then the CheckpointRecord of the run;
     * - the binary files a component writes under data_prefix() (material points: deal.II's
     *   triangulation and particle archive, readable on any number of ranks);
     * - copies of the output files that grow during a run (statistics.csv, gauges), taken
     *   back on resume so that they continue from the checkpoint's step.
     */
    class CheckpointDirectory
    {
    public:
      explicit CheckpointDirectory(const std::string &output_directory);

      /**
       * Writes a checkpoint (collective): creates the temporary directory, calls
       * @p write_data(data prefix) on every rank for the binary parts, then on rank 0
       * writes @p signature and @p record, copies @p growing_files (paths relative to the
       * output directory, those that exist) and renames the directory into place.
       */
      template <typename Function>
      void
      write(const std::string              &signature,
            const CheckpointRecord         &record,
            const std::vector<std::string> &growing_files,
            const Function                 &write_data) const
      {
        begin_write();
        write_data(data_prefix(temporary_path()));
        finish_write(signature, record, growing_files);
      }

      /**
       * Finds the newest complete checkpoint, checks that @p signature is the one it was
       * written with, reads its record and puts its copies of @p growing_files back into
       * the output directory (collective). Throws InputError (parameter Checkpoint/Resume)
       * when there is none, when it belongs to another scene or when it is damaged.
       * Returns the prefix of its binary data.
       */
      std::string
      read(const std::string              &signature,
           CheckpointRecord               &record,
           const std::vector<std::string> &growing_files) const;

    private:
      std::string
      temporary_path() const;

      static std::string
      data_prefix(const std::string &checkpoint_path);

      void
      begin_write() const;

      void
      finish_write(const std::string              &signature,
                   const CheckpointRecord         &record,
                   const std::vector<std::string> &growing_files) const;

      std::string output_directory;
    };
  } // namespace io
} // namespace slidewave

#endif
