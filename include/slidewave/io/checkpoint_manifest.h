#ifndef slidewave_io_checkpoint_manifest_h
#define slidewave_io_checkpoint_manifest_h

#include <string>

namespace slidewave
{
  namespace io
  {
    /**
     * The manifest of a checkpoint folder, `manifest.txt`: written last, when every other
     * file of the folder is complete, it lists each of them with its size in bytes and its
     * CRC-32 (zlib's polynomial, through Boost.CRC), and the number of MPI ranks that wrote
     * the checkpoint:
     *
     *     SlideWave checkpoint manifest 1
     *     ranks 2
     *     file record.txt 1534 9f3c12ab
     *     file state 3196 0c1d2e3f
     *     ...
     *     end 8
     *
     * A checkpoint whose files do not match its manifest (missing, truncated, emptied,
     * changed) is damaged and is never handed to deal.II or p4est.
     */
    class CheckpointManifest
    {
    public:
      /** The file name of the manifest inside a checkpoint folder. */
      static const std::string file_name;

      /** Writes the manifest of every regular file in @p folder (but itself) (one process). */
      static void
      write(const std::string &folder, unsigned int n_ranks);

      /** What is wrong with @p folder's files against its manifest, in words naming the
       *  file; empty when every listed file is there with its size and checksum (one
       *  process). */
      static std::string
      check(const std::string &folder);

      /** The CRC-32 of the file @p path (throws std::runtime_error when unreadable). */
      static unsigned long
      checksum(const std::string &path);
    };
  } // namespace io
} // namespace slidewave

#endif
