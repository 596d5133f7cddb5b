#ifndef bfemp_base_muparser_tools_h
#define bfemp_base_muparser_tools_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * What every prm entry that holds muParser expressions (prescribed
   * displacements, initial velocities, surface tractions) needs to split
   * its components and to report a bad expression as an InputError of its
   * own.
   */
  namespace muparser_tools
  {
    /**
     * Collects what is written to std::cerr while it lives: deal.II 9.4
     * prints muParser's error report there before throwing, and bfemp
     * reports the error itself, as an InputError. Used only while the
     * parameters are read (one thread).
     */
    class CerrCapture
    {
    public:
      CerrCapture()
        : previous(std::cerr.rdbuf(captured.rdbuf()))
      {}

      ~CerrCapture()
      {
        std::cerr.rdbuf(previous);
      }

    private:
      std::ostringstream captured;
      std::streambuf    *previous;
    };

    /** "The parser said: ..." of deal.II's ExcParseError, or all of the
     *  exception's description for other exceptions. */
    inline std::string
    parser_message(const dealii::ExceptionBase &exception)
    {
      std::ostringstream info;
      exception.print_info(info);
      std::string       message = dealii::Utilities::trim(info.str());
      const std::string marker  = "The parser said: ";
      const std::size_t start   = message.find(marker);
      if (start != std::string::npos)
        message = message.substr(start + marker.size());
      return dealii::Utilities::trim(message);
    }

    /** Whether every ')' in @p text closes an earlier '('. */
    inline bool
    parentheses_balanced(const std::string &text)
    {
      int depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (depth < 0)
            return false;
        }
      return depth == 0;
    }

    /**
     * @p text split at the separators outside parentheses, each piece
     * trimmed: "0, -1000*min(t/0.1, 1)" gives two pieces. The prm entries
     * that hold one muParser expression per component separate them with
     * commas, and muParser's functions of several arguments (min, max, sum,
     * avg) use commas too, so a plain split at every comma would cut
     * through their argument lists.
     */
    inline std::vector<std::string>
    split_top_level(const std::string &text, const char separator)
    {
      std::vector<std::string> pieces(1);
      int                      depth = 0;
      for (const char c : text)
        {
          if (c == '(')
            ++depth;
          else if (c == ')')
            --depth;
          if (c == separator && depth == 0)
            pieces.emplace_back();
          else
            pieces.back() += c;
        }
      for (std::string &piece : pieces)
        piece = dealii::Utilities::trim(piece);
      return pieces;
    }
  } // namespace muparser_tools
} // namespace bfemp

#endif
