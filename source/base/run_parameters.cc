#include <bfemp/base/input_error.h>
#include <bfemp/base/run_parameters.h>

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
    prm.leave_subsection();
  }



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("run");
    name      = prm.get("name");
    end_time  = prm.get_double("end time");
    test_mode = prm.get_bool("test mode");
    quiet     = prm.get_bool("quiet");
    threads   = prm.get_integer("threads");
    prm.leave_subsection();

    require_input(!name.empty() && name.find('/') == std::string::npos,
                  "run",
                  "name",
                  "'" + name + "'",
                  "a non-empty name without '/'");
    require_input(end_time > 0.,
                  "run",
                  "end time",
                  to_input_string(end_time),
                  "must be > 0 [s]");
  }
} // namespace bfemp
