#ifndef bfemp_io_output_parameters_h
#define bfemp_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "output": what is written where and how often. */
  struct OutputParameters
  {
    std::string  directory            = "output";
    double       interval             = 0.01;
    bool         write_particles      = true;
    bool         write_grid           = false;
    unsigned int diagnostics_interval = 1;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Creates @p folder (a run's folder inside 'directory') if needed and
     * makes sure files can be written into it; throws InputError naming
     * subsection 'output', entry 'directory', if not (a read-only or
     * missing mount, a path through a file).
     */
    void
    create_folder(const std::string &folder) const;
  };
} // namespace bfemp

#endif
