// What deal.II's parameter reader would crash on or accept silently in a scene file,
// checked by core::check_scene_file before it reads the file (issue 29). The test writes
// small scene files into a fresh directory and checks each outcome:
//  - a file that includes itself, and two files that include each other: refused (deal.II
//    recursed until the stack overflowed: SIGSEGV);
//  - 'set Physics' twice, and a parameter set twice in a subsection given twice: refused,
//    naming both lines (the second value silently won);
//  - a UTF-8 byte-order mark at the start: refused, saying what it is;
//  - what stays allowed: a file that includes another and sets again what that one set
//    (the override of the test scenes), the same parameter name in two different
//    subsections, a value continued over two lines with '\', a set inside a comment;
//  - a value of 10^6 characters in a message: shown by its start and its length.
// Each refusal prints what the error says is allowed; a check that fails prints "no".
#include "unit_check.h"

#include <cstdio>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/scene_file_check.h>
#include <string>

using namespace unit_check;

namespace
{
  std::string directory;

  /** Writes @p text to @p name in the test's directory; returns the full path. */
  std::string
  write(const std::string &name, const std::string &text)
  {
    const std::string path = directory + "/" + name;
    std::ofstream(path) << text;
    return path;
  }

  /** Whether check_scene_file refuses @p path; prints the message's parameter and value
   *  with the directory replaced by "DIR" (the same on every machine). */
  bool
  refuses(const std::string &path)
  {
    try
      {
        slidewave::core::check_scene_file(path);
      }
    catch (const slidewave::InputError &e)
      {
        std::string message = e.what();
        for (std::size_t at = message.find(directory); at != std::string::npos;
             at             = message.find(directory))
          message.replace(at, directory.size(), "DIR");
        std::printf("    %s\n", message.c_str());
        return true;
      }
    return false;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  directory = std::filesystem::absolute("scene_files").string();
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);

  const std::string self = directory + "/self.prm";
  write("self.prm", "set Physics = depth averaged\ninclude " + self + "\n");
  check(refuses(self), "a file that includes itself is refused");

  write("a.prm", "include " + directory + "/b.prm\n");
  write("b.prm", "set Physics = water\ninclude " + directory + "/a.prm\n");
  check(refuses(directory + "/a.prm"), "two files that include each other are refused");

  check(refuses(
          write("twice.prm", "set Physics = depth averaged\n# a comment\nset Physics = water\n")),
        "'set Physics' twice is refused, naming lines 1 and 3");
  check(refuses(write("subsection_twice.prm",
                      "subsection Time\n  set End time = 1\nend\n"
                      "subsection Time\n  set End time = 2\nend\n")),
        "a parameter set in a subsection given twice is refused, naming lines 2 and 5");
  check(refuses(write("bom.prm", "\xEF\xBB\xBFset Physics = water\n")),
        "a UTF-8 byte-order mark is refused, saying what it is");

  const std::string base = write("base.prm",
                                 "set Physics = water\nsubsection Time\n"
                                 "  set End time = 1\nend\n");
  check(!refuses(write("override.prm",
                       "include " + base + "\nsubsection Time\n  set End time = 2\nend\n")),
        "setting again what an included file set is allowed (an override)");
  check(!refuses(write("same_name.prm",
                       "subsection Time\n  set End time = 1\nend\n"
                       "subsection Depth averaged\n  subsection Grid\n"
                       "    set Cell size = 1\n  end\nend\n"
                       "subsection Material points\n  subsection Grid\n"
                       "    set Cell size = 1\n  end\nend\n")),
        "the same name in two subsections is allowed");
  check(!refuses(write("continued.prm",
                       "subsection Depth averaged\n  subsection Terrain\n"
                       "    set Elevation = 1 + \\\n      x\n  end\nend\n"
                       "# set Physics = water\nset Physics = depth averaged\n")),
        "a value continued with '\\' and a set inside a comment are allowed");
  check(!refuses(directory + "/missing.prm"),
        "a missing file is left to deal.II's reader (which names it)");

  try
    {
      throw slidewave::InputError("Depth averaged/Terrain/Elevation",
                                  std::string(1000000, 'x'),
                                  "an expression");
    }
  catch (const slidewave::InputError &e)
    {
      const std::string message = e.what();
      std::printf("    message of %zu characters, ends '%s'\n",
                  message.size(),
                  message.substr(message.size() - 50).c_str());
      check(message.size() < 300 && e.value.size() == 1000000,
            "a value of 10^6 characters is shown by its start and its length");
    }

  std::filesystem::remove_all(directory);
  std::printf("%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
