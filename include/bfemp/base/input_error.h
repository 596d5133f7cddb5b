#ifndef bfemp_base_input_error_h
#define bfemp_base_input_error_h

#include <deal.II/base/point.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace bfemp
{
  /**
   * A problem with what the user asked for: a prm entry, a mesh file, a scene
   * that cannot be set up. The message names where (file, subsection, entry)
   * and what is allowed; main() prints it and exits non-zero before any
   * output is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message);
  };

  /**
   * Throws an InputError "subsection S, entry E = V: what is allowed" unless
   * @p condition holds.
   */
  void
  require_input(const bool         condition,
                const std::string &subsection,
                const std::string &entry,
                const std::string &value,
                const std::string &what_is_allowed);

  /** A number as the user wrote it, for messages. */
  std::string
  to_input_string(const double value);

  template <int dim>
  std::string
  to_input_string(const dealii::Point<dim> &point)
  {
    std::ostringstream out;
    for (unsigned int d = 0; d < dim; ++d)
      out << (d > 0 ? ", " : "") << point[d];
    return out.str();
  }

  /**
   * A run-time failure of the simulation itself (a diverging step, a NaN, a
   * particle leaving the grid). Output up to the last good step stays valid.
   */
  class SimulationError : public std::runtime_error
  {
  public:
    explicit SimulationError(const std::string &message);
  };
} // namespace bfemp

#endif
