#include <bfemp/base/input_error.h>
#include <bfemp/base/prm_include.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bfemp
{
  namespace
  {
    std::string
    trimmed(const std::string &text)
    {
      const auto begin = text.find_first_not_of(" \t\r\n");
      if (begin == std::string::npos)
        return "";
      return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
    }

    /** The path of an `include` statement on @p line, or "" if the line is
     *  none (deal.II's keyword test: `include` or `INCLUDE`, then a
     *  space). */
    std::string
    include_path(const std::string &line)
    {
      const std::string statement = trimmed(line.substr(0, line.find('#')));
      for (const char *keyword : {"include", "INCLUDE"})
        if (statement.size() > 7 && statement.compare(0, 7, keyword) == 0 &&
            std::isspace(static_cast<unsigned char>(statement[7])))
          return trimmed(statement.substr(7));
      return "";
    }

    /** Refuses a line with a control byte other than white space: the
     *  file is binary (an executable, an image, a checkpoint), not a
     *  parameter file, and deal.II's message would quote its bytes. */
    void
    require_text(const std::string &line,
                 const std::string &file,
                 const unsigned int number)
    {
      for (std::size_t column = 0; column < line.size(); ++column)
        {
          const unsigned char byte = static_cast<unsigned char>(line[column]);
          if ((byte < 0x20 && !std::isspace(byte)) || byte == 0x7f)
            {
              char code[8];
              std::snprintf(code, sizeof(code), "0x%02x", byte);
              throw InputError(file + ": line " + std::to_string(number) +
                               ", column " + std::to_string(column + 1) +
                               ": byte " + code +
                               " is not text; a parameter file is plain text "
                               "(is this the file you meant?)");
            }
        }
    }

    void
    expand(const std::string &file, const unsigned int depth, ExpandedPrm &out)
    {
      std::ifstream input(file);
      std::string   line;
      bool          continued = false;
      for (unsigned int number = 1; std::getline(input, line); ++number)
        {
          require_text(line, file, number);
          const std::string path = continued ? "" : include_path(line);
          const std::string code = trimmed(line.substr(0, line.find('#')));
          continued              = !code.empty() && code.back() == '\\';
          if (path.empty())
            {
              out.text += line + '\n';
              out.origins.emplace_back(file, number);
              continue;
            }
          const std::string where = file + ": line " + std::to_string(number);
          if (depth == 32)
            throw InputError(where + ": include '" + path +
                             "': includes nested deeper than 32 (does a "
                             "file include itself?)");
          const std::string included = resolve_prm_include(path, file);
          if (!std::filesystem::is_regular_file(included))
            throw InputError(where + ": include '" + path +
                             "': no such file next to " + file +
                             " or in the working directory (" +
                             std::filesystem::current_path().string() + ")");
          expand(included, depth + 1, out);
        }
    }
  } // namespace



  std::string
  resolve_prm_include(const std::string &path,
                      const std::string &including_file)
  {
    const std::filesystem::path written(path);
    if (written.is_absolute())
      return path;
    const std::filesystem::path next_to =
      std::filesystem::path(including_file).parent_path() / written;
    return std::filesystem::is_regular_file(next_to) ? next_to.string() : path;
  }



  ExpandedPrm
  expand_prm_includes(const std::string &file)
  {
    ExpandedPrm expanded;
    expand(file, 0, expanded);
    return expanded;
  }
} // namespace bfemp
