#ifndef slidewave_core_output_locations_h
#define slidewave_core_output_locations_h

#include <string>
#include <vector>

namespace slidewave
{
  namespace core
  {
    /** A folder a scene writes into: its path relative to the output directory and what
     *  writes there (with the parameter that asks for it), for messages. */
    struct OutputFolder
    {
      std::string folder;
      std::string what;
    };

    /**
     * Creates the output directory @p directory and the @p folders in it, and checks before
     * the run that a file can be written in each: no part of a path is a file, the folder
     * can be created, access() allows writing and a probe file can be written and removed
     * (root passes access() everywhere; the probe does not). Rank 0 checks, every rank
     * takes its verdict, so all refuse together: an InputError naming 'Output directory',
     * the path and what is wrong with it. Collective.
     */
    void
    prepare_output_locations(const std::string               &directory,
                             const std::vector<OutputFolder> &folders);

    /** What is wrong with writing into the folder @p path (empty: nothing), on this rank:
     *  a part of it is a file, it cannot be created, it is not writable. */
    std::string
    problem_writing_into(const std::string &path);
  } // namespace core
} // namespace slidewave

#endif
