#ifndef slidewave_io_checkpoint_h
#define slidewave_io_checkpoint_h

#include <functional>
#include <slidewave/io/checkpoint_record.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace io
  {
    /**
     * Checkpoints of every kind of scene, in one directory layout: OUTPUT/checkpoint holds
     * the newest, OUTPUT/checkpoint.previous the one before. A checkpoint is written into
     * OUTPUT/checkpoint.tmp, its manifest last, and renamed when complete, so a run killed
     * while writing leaves both earlier ones intact; resuming takes the newest intact one.
     *
     * Each checkpoint holds:
     * - `scene.txt`: the signature of the scene that wrote it (its physics and whatever a
     *   resumed run must share with it), then the CheckpointRecord of the run;
     * - the binary files a component writes under data_prefix() (material points: deal.II's
     *   triangulation and particle archive, readable on any number of ranks);
     * - copies of the output files that grow during a run (statistics.csv, gauges), taken
     *   back on resume so that they continue from the checkpoint's step;
     * - `manifest.txt`, written last: every other file with its size and CRC-32
     *   (CheckpointManifest).
     */
    class CheckpointDirectory
    {
    public:
      explicit CheckpointDirectory(const std::string &output_directory);

      /**
       * Writes a checkpoint (collective): creates the temporary directory, calls
       * @p write_data(data prefix) on every rank for the binary parts, then on rank 0
       * writes @p signature and @p record, copies @p growing_files (paths relative to the
       * output directory, those that exist), writes the manifest of it all and renames the
       * directory into place.
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
       * Finds the newest intact checkpoint, checks that @p signature is the one it was
       * written with, reads its record and puts its copies of @p growing_files back into
       * the output directory (collective). Returns the prefix of its binary data.
       *
       * Before anything of it is read, rank 0 verifies the newest checkpoint: its files
       * against its manifest (CheckpointManifest: present, sizes, CRC-32), its record
       * readable (counts that match the numbers, every number finite) and what
       * @p check_record says of the record (empty: acceptable; or what is wrong, or an
       * InputError). A damaged newest one is reported on the error stream and the
       * previous one is taken if intact; every rank takes rank 0's verdict. Throws
       * InputError (parameter Checkpoint/Resume) when there is none, when both are
       * damaged (naming both and what is wrong with each) and when the one taken belongs
       * to another scene.
       */
      std::string
      read(const std::string                                          &signature,
           CheckpointRecord                                           &record,
           const std::vector<std::string>                             &growing_files,
           const std::function<std::string(const CheckpointRecord &)> &check_record) const;

    private:
      /** The folder of the checkpoint to resume from (collective; rank 0 decides). */
      std::string
      choose(const std::function<std::string(const CheckpointRecord &)> &check_record) const;

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
