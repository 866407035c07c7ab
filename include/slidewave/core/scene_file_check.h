#ifndef slidewave_core_scene_file_check_h
#define slidewave_core_scene_file_check_h

#include <string>
#include <vector>

namespace slidewave
{
  namespace core
  {
    /**
     * What deal.II's parameter reader does not catch in a scene file, checked before it
     * reads the file (it would crash or silently pick one of two values):
     *
     * - an `include` of the file itself, or a loop of includes (deal.II recurses until the
     *   stack overflows): refused, naming the chain of files;
     * - a parameter set twice in one file (`set Physics` twice, or a subsection given
     *   twice with different values: the second would silently win): refused, naming both
     *   lines. Setting again in a file what an included file set is the way to override
     *   it, and `--set` overrides from the command line: both stay allowed;
     * - a UTF-8 byte-order mark at the start of a file (deal.II cannot parse line 1):
     *   refused, saying what it is.
     *
     * Included files are checked the same way, each for itself. Paths of included files are
     * taken as deal.II takes them (as written: relative to the working directory).
     * Throws an InputError naming the file and the line.
     */
    void
    check_scene_file(const std::string &filename);
  } // namespace core
} // namespace slidewave

#endif
