#ifndef bfemp_base_prm_include_h
#define bfemp_base_prm_include_h

#include <string>
#include <utility>
#include <vector>

namespace bfemp
{
  /**
   * The file that `include @p path` in @p including_file opens. A relative
   * path means a file next to the including file, so that a scene and the
   * files it includes can be moved together and run from any directory;
   * where no such file exists, the path is taken as written (relative to
   * the working directory, deal.II's own rule), so that wrappers written
   * for that rule keep working.
   */
  std::string
  resolve_prm_include(const std::string &path,
                      const std::string &including_file);

  /**
   * A prm file with every `include` replaced by the (recursively expanded)
   * text of the file it names, and the file and line each line of the text
   * came from, so that a parse error can name the file and line it is in.
   */
  struct ExpandedPrm
  {
    std::string text;
    /** (file, 1-based line) of each line of text. */
    std::vector<std::pair<std::string, unsigned int>> origins;
  };

  /**
   * Expands @p file as deal.II reads it ('#' comments, lines continued by a
   * trailing backslash, `include` or `INCLUDE` followed by a path).
   * Throws InputError naming the including file and line for an include
   * that names no file, and for includes nested deeper than 32 (a cycle).
   */
  ExpandedPrm
  expand_prm_includes(const std::string &file);
} // namespace bfemp

#endif
