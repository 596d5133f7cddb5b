#ifndef bfemp_io_checkpoint_parameters_h
#define bfemp_io_checkpoint_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "checkpoint": when the run state is saved to
   * <output directory>/<run name>/checkpoint.h5 and whether a run continues
   * from it.
   */
  struct CheckpointParameters
  {
    /** Whether the run starts at t = 0 or from the saved state. */
    enum class Resume
    {
      never,
      always,
      if_present
    };

    /** 'interval' [s]: simulated time between checkpoints; 0: none. */
    double interval = 0.;
    /** 'wall time interval' [s]: wall-clock time between checkpoints. */
    double wall_time_interval = 0.;
    /** 'resume': false, true or auto. */
    Resume resume = Resume::never;

    /** Whether any checkpoint is written (then also one at the end). */
    bool
    enabled() const;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace bfemp

#endif
