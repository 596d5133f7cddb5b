#include <bfemp/base/input_error.h>
#include <bfemp/io/checkpoint_parameters.h>

namespace bfemp
{
  bool
  CheckpointParameters::enabled() const
  {
    return interval > 0. || wall_time_interval > 0.;
  }



  void
  CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    prm.declare_entry("interval",
                      "0",
                      Patterns::Double(0.),
                      "[s] Simulated time between checkpoints "
                      "(<output directory>/<run name>/checkpoint.h5, "
                      "replaced each time, written complete or not at all); "
                      "0: none. A checkpoint is only taken at a step that "
                      "writes a diagnostics row. When any checkpoint is "
                      "enabled, the run also saves one at its end, so that a "
                      "later run with a larger end time can continue it.");
    prm.declare_entry("wall time interval",
                      "0",
                      Patterns::Double(0.),
                      "[s] Wall-clock time between checkpoints, for runs "
                      "longer than a job's time limit; 0: none. Independent "
                      "of it, SIGTERM, SIGINT or SIGUSR1 stop a run after "
                      "the step in progress with a checkpoint.");
    prm.declare_entry("resume",
                      "false",
                      Patterns::Selection("false|true|auto"),
                      "[-] false: start at t = 0 (and clear the run's earlier "
                      "output). true: continue from the checkpoint, which "
                      "must exist and belong to this scene; the output "
                      "written after the checkpoint (diagnostics rows, "
                      "snapshots) is replaced. auto: continue if a "
                      "checkpoint exists, else start at t = 0. Entries may "
                      "change between the runs (end time, output, solver); "
                      "the bodies, grid and meshes must not.");
    prm.leave_subsection();
  }



  void
  CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    interval                       = prm.get_double("interval");
    wall_time_interval             = prm.get_double("wall time interval");
    const std::string resume_entry = prm.get("resume");
    resume                         = resume_entry == "true"   ? Resume::always
                                     : resume_entry == "auto" ? Resume::if_present
                                                              : Resume::never;
    prm.leave_subsection();
  }
} // namespace bfemp
