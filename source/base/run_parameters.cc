#include <bfemp/base/input_error.h>
#include <bfemp/base/run_parameters.h>

#include <cstdlib>

namespace bfemp
{
  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("run");
    prm.declare_entry("name",
                      "default",
                      Patterns::Anything(),
                      "[-] Name of the run; output goes to "
                      "<output/directory>/<name>/.");
    prm.declare_entry("end time",
                      "1",
                      Patterns::Double(),
                      "[s] Simulated time at which the run stops (> 0).");
    prm.declare_entry("test mode",
                      "false",
                      Patterns::Bool(),
                      "[-] Print a fixed-precision summary and no timings "
                      "instead of progress lines (used by the ctest scenes).");
    prm.declare_entry("quiet",
                      "false",
                      Patterns::Bool(),
                      "[-] Suppress the per-step progress line.");
    prm.declare_entry("threads",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number of threads; 0 uses all cores (or "
                      "DEAL_II_NUM_THREADS).");
    prm.declare_entry(
      "BLAS threads",
      "auto",
      Patterns::Anything(),
      "[-] Threads of the BLAS (OpenBLAS) inside CHOLMOD's factorization: "
      "'auto' uses one, and 'threads' in factorizations above 1e9 flops and "
      "triangular solves above 1e8 flops if 'threads' is set above 1 (the "
      "cores are the run's own); a number N uses N in every BLAS call. More BLAS threads gain 1.1-1.7 times in "
      "large factorizations on a quiet machine, but their spinning made a "
      "3D step 9 times slower next to other busy processes "
      "(doc/performance.md).");
    prm.leave_subsection();
  }



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("run");
    name                   = prm.get("name");
    end_time               = prm.get_double("end time");
    test_mode              = prm.get_bool("test mode");
    quiet                  = prm.get_bool("quiet");
    threads                = prm.get_integer("threads");
    const std::string blas = prm.get("BLAS threads");
    prm.leave_subsection();

    require_input(!name.empty() && name.find('/') == std::string::npos,
                  "run",
                  "name",
                  "'" + name + "'",
                  "a non-empty name without '/'");
    char      *end = nullptr;
    const long n   = blas == "auto" ? 0 : std::strtol(blas.c_str(), &end, 10);
    require_input(blas == "auto" || (end != blas.c_str() && *end == '\0' &&
                                     n >= 1 && n <= 1024),
                  "run",
                  "BLAS threads",
                  "'" + blas + "'",
                  "'auto' or a number of threads in [1, 1024]");
    blas_threads = static_cast<unsigned int>(n);
    require_input(end_time > 0.,
                  "run",
                  "end time",
                  to_input_string(end_time),
                  "must be > 0 [s]");
  }
} // namespace bfemp
