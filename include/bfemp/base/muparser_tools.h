#ifndef bfemp_base_muparser_tools_h
#define bfemp_base_muparser_tools_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <iostream>
#include <sstream>
#include <string>

namespace bfemp
{
  /**
   * What every prm entry that holds muParser expressions (prescribed
   * displacements, initial velocities) needs to report a bad expression as
   * an InputError of its own.
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
  } // namespace muparser_tools
} // namespace bfemp

#endif
