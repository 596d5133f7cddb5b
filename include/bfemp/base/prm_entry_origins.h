#ifndef bfemp_base_prm_entry_origins_h
#define bfemp_base_prm_entry_origins_h

#include <map>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * Which file of a prm file and its 'include's set each entry last.
   *
   * deal.II's ParameterHandler merges included files into one set of values
   * and forgets where a value came from. A relative path written in a prm
   * file (a mesh 'file') means a path next to that file, also when the file
   * is included from a wrapper elsewhere; this scan recovers the file so
   * that such paths can be resolved against the right directory.
   *
   * The scan follows the syntax deal.II reads: comments from '#', lines
   * continued by a trailing backslash, 'subsection', 'end', 'set' and
   * 'include' (resolved as parse_prm_file resolves it: next to the
   * including file, else as written; resolve_prm_include()). Files that
   * cannot be opened are skipped: the parse reports them.
   */
  class PrmEntryOrigins
  {
  public:
    explicit PrmEntryOrigins(const std::string &file);

    /**
     * Directory of the file that set @p entry in the subsection path
     * @p subsections last; the top file's directory if no file set it.
     */
    std::string
    directory_of(const std::vector<std::string> &subsections,
                 const std::string              &entry) const;

    /** Whether the files set any entry at all. */
    bool
    sets_any_entry() const;

    /**
     * Whether the files set an entry at the top level named @p entry or in a
     * subsection whose outermost name starts with @p subsection_prefix.
     */
    bool
    sets_entry(const std::string &entry,
               const std::string &subsection_prefix) const;

  private:
    void
    scan(const std::string &file, unsigned int depth);

    static std::string
    key(const std::vector<std::string> &subsections, const std::string &entry);

    std::string                        top_directory;
    std::vector<std::string>           open_subsections;
    std::map<std::string, std::string> directory_by_entry;
  };
} // namespace bfemp

#endif
