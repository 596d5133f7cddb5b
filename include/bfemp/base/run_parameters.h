#ifndef bfemp_base_run_parameters_h
#define bfemp_base_run_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "run": what the run is called and how long it lasts. */
  struct RunParameters
  {
    std::string  name      = "default";
    double       end_time  = 1.;
    bool         test_mode = false;
    bool         quiet     = false;
    unsigned int threads   = 0;
    /** `run/BLAS threads`: 0 for `auto` (BlasThreads decides), else the
     *  BLAS threads of every call. */
    unsigned int blas_threads = 0;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace bfemp

#endif
