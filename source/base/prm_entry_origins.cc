#include <bfemp/base/prm_entry_origins.h>
#include <bfemp/base/prm_include.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace bfemp
{
  namespace
  {
    std::string
    trimmed(const std::string &text)
    {
      const auto is_space = [](const unsigned char c) {
        return std::isspace(c) != 0;
      };
      const auto begin = std::find_if_not(text.begin(), text.end(), is_space);
      const auto end =
        std::find_if_not(text.rbegin(), text.rend(), is_space).base();
      return begin < end ? std::string(begin, end) : std::string();
    }

    /** @p line without @p keyword and what follows it, if it starts so. */
    bool
    strip_keyword(std::string &line, const std::string &keyword)
    {
      std::string upper = keyword;
      std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
      if (line.size() <= keyword.size() ||
          (line.compare(0, keyword.size(), keyword) != 0 &&
           line.compare(0, keyword.size(), upper) != 0) ||
          !std::isspace(static_cast<unsigned char>(line[keyword.size()])))
        return false;
      line = trimmed(line.substr(keyword.size()));
      return true;
    }

    std::string
    directory_of_file(const std::string &file)
    {
      const std::string directory =
        std::filesystem::path(file).parent_path().string();
      return directory.empty() ? "." : directory;
    }
  } // namespace



  PrmEntryOrigins::PrmEntryOrigins(const std::string &file)
    : top_directory(directory_of_file(file))
  {
    scan(file, 0);
  }



  std::string
  PrmEntryOrigins::directory_of(const std::vector<std::string> &subsections,
                                const std::string              &entry) const
  {
    const auto found = directory_by_entry.find(key(subsections, entry));
    return found == directory_by_entry.end() ? top_directory : found->second;
  }



  void
  PrmEntryOrigins::scan(const std::string &file, const unsigned int depth)
  {
    // deal.II would recurse forever on an include cycle; stop quietly and
    // leave the report to it.
    std::ifstream input(file);
    if (!input || depth > 32)
      return;
    const std::string directory = directory_of_file(file);
    std::string       line, joined;
    while (std::getline(input, line))
      {
        line                   = line.substr(0, line.find('#'));
        const std::string text = trimmed(line);
        if (!text.empty() && text.back() == '\\')
          {
            joined += text.substr(0, text.size() - 1);
            continue;
          }
        std::string statement = trimmed(joined + text);
        joined.clear();

        if (strip_keyword(statement, "subsection"))
          open_subsections.push_back(statement);
        else if ((statement == "end" || statement == "END") &&
                 !open_subsections.empty())
          open_subsections.pop_back();
        else if (strip_keyword(statement, "set"))
          {
            const auto equals = statement.find('=');
            if (equals != std::string::npos)
              directory_by_entry[key(open_subsections,
                                     trimmed(statement.substr(0, equals)))] =
                directory;
          }
        else if (strip_keyword(statement, "include"))
          scan(resolve_prm_include(statement, file), depth + 1);
      }
  }



  bool
  PrmEntryOrigins::sets_any_entry() const
  {
    return !directory_by_entry.empty();
  }



  bool
  PrmEntryOrigins::sets_entry(const std::string &entry,
                              const std::string &subsection_prefix) const
  {
    for (const auto &[key, directory] : directory_by_entry)
      if (key == entry ||
          (key.find('\n') != std::string::npos &&
           key.compare(0, subsection_prefix.size(), subsection_prefix) == 0))
        return true;
    return false;
  }



  std::string
  PrmEntryOrigins::key(const std::vector<std::string> &subsections,
                       const std::string              &entry)
  {
    std::string path;
    for (const std::string &subsection : subsections)
      path += subsection + '\n';
    return path + entry;
  }
} // namespace bfemp
