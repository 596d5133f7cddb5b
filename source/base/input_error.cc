#include <bfemp/base/input_error.h>

namespace bfemp
{
  InputError::InputError(const std::string &message)
    : std::runtime_error(message)
  {}



  void
  require_input(const bool         condition,
                const std::string &subsection,
                const std::string &entry,
                const std::string &value,
                const std::string &what_is_allowed)
  {
    if (!condition)
      throw InputError("subsection '" + subsection + "', entry '" + entry +
                       "' = " + value + ": " + what_is_allowed);
  }



  std::string
  to_input_string(const double value)
  {
    std::ostringstream out;
    out << value;
    return out.str();
  }



  SimulationError::SimulationError(const std::string &message)
    : std::runtime_error(message)
  {}
} // namespace bfemp
