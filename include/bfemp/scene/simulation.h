#ifndef bfemp_scene_simulation_h
#define bfemp_scene_simulation_h

#include <bfemp/fem/fem_body.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/integrator/explicit_mpm.h>
#include <bfemp/integrator/implicit_integrator.h>
#include <bfemp/integrator/substepped_mpm.h>
#include <bfemp/io/body_diagnostics_writer.h>
#include <bfemp/io/checkpoint_file.h>
#include <bfemp/io/coarse_grid_output.h>
#include <bfemp/io/diagnostics_writer.h>
#include <bfemp/io/fem_output.h>
#include <bfemp/io/grid_output.h>
#include <bfemp/io/particle_output.h>
#include <bfemp/io/progress_reporter.h>
#include <bfemp/io/step_diagnostics.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_loads.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <memory>
#include <optional>
#include <ostream>
#include <vector>

namespace bfemp
{
  /**
   * A scene built from its parameters and run to the end time. The
   * constructor builds and checks everything (bodies inside the grid, not
   * empty, not overlapping) before run() creates the output folder, so bad
   * input never leaves output behind.
   */
  template <int dim>
  class Simulation
  {
  public:
    Simulation(const SceneParameters<dim> &parameters,
               const std::string          &parameter_file,
               std::ostream               &console);

    /**
     * Runs to the end time and returns true; throws SimulationError on
     * failure. Returns false if a StopSignals object recorded a signal: the
     * run then stopped after the step in progress and left a checkpoint
     * (also when the prm asks for none) that 'checkpoint/resume' continues.
     */
    bool
    run();

    const ParticleSystem<dim> &
    particles() const;

    /** The time integrator, e.g. to inspect the last step's grid fields. */
    const TimeIntegrator<dim> &
    integrator() const;

    /** Write access, e.g. to set a non-uniform initial state before run(). */
    ParticleSystem<dim> &
    particles();

    /** The FEM bodies, e.g. to inspect or set their state before run(). */
    std::vector<std::unique_ptr<FemBody<dim>>> &
    fem_bodies();

    /** The diagnostics of the current state. */
    StepDiagnostics<dim>
    diagnostics() const;

    /** The row of bodies.csv: the current state of each body. */
    void
    write_body_diagnostics(BodyDiagnosticsWriter<dim> &writer) const;

    /** u(X) of body @p b's 'initial displacement' at rest position @p X
     *  (InputError if not finite). */
    Tensor<1, dim>
    initial_displacement_at(const unsigned int b, const Point<dim> &X) const;

    /** F = I + grad u(X) of body @p b (InputError if det F <= 0). */
    Tensor<2, dim>
    initial_deformation_gradient(const unsigned int b,
                                 const Point<dim>  &X) const;

  private:
    /** Samples every body into particles and checks the scene at t = 0. */
    void
    create_bodies();

    /** Builds the FEM bodies' meshes and elements. */
    void
    create_fem_bodies();

    /**
     * dx / (c_p + max |v_p|): the explicit CFL time scale; implicit steps
     * have no wave-speed limit, and their scale is dx / max |v|.
     */
    double
    cfl_time_scale(const double max_speed) const;

    /** dx / (c_p + max |v_p|), the stability time scale of explicit MPM. */
    double
    explicit_time_scale(const double max_speed) const;

    /**
     * S of the substepped integrator's next macro step of size @p dt:
     * 'substeps', or the least S that keeps 'substep CFL number'. Throws if
     * a fixed S makes the substep unstable.
     */
    unsigned int
    substeps_for(const double dt, const double max_speed) const;

    /** One step of the chosen integrator. */
    void
    advance(const double dt, const double time, const double max_speed);

    /**
     * Builds the integrator the parameters choose: the one place that maps
     * 'time/integrator' and the scene (FEM bodies, cMPM) to a class.
     */
    void
    create_integrator();

    /** Throws InputError naming the bodies if particles start inside or on
     *  an FEM body (BFEMP eq. 15 needs a positive distance). */
    void
    check_bodies_apart(ImplicitIntegrator<dim> &implicit) const;

    /**
     * The next dt, 0 once the end time is reached; throws if a fixed dt
     * breaks the CFL limit.
     */
    double
    next_time_step(const double time, const double max_speed) const;

    /** Whether t is within round-off (1e-6 dt) of `run/end time`. */
    bool
    end_reached(const double time, const double dt) const;

    /** Throws SimulationError unless the state is finite and uninverted. */
    void
    check_state(const StepDiagnostics<dim> &d) const;

    /**
     * Creates <directory>/<run name>/; a new run clears bfemp files of
     * older runs there, a continued one keeps them.
     */
    void
    prepare_output_folder(const bool resuming);

    /** <directory>/<run name>/checkpoint.h5. */
    std::string
    checkpoint_path() const;

    /**
     * If 'checkpoint/resume' asks for it: restores the state saved in the
     * checkpoint and returns where the run stood; throws InputError naming
     * the prm entry and the file if that is impossible.
     */
    std::optional<typename CheckpointFile<dim>::Progress>
    resume_from_checkpoint();

    /**
     * Tells which columns of @p file_name a continued run added (the earlier
     * rows hold nan there), if any.
     */
    void
    report_added_columns(const std::string              &file_name,
                         const std::vector<std::string> &columns) const;

    /** Saves the state after the current step. */
    void
    write_checkpoint(const double next_output, const double wall_time) const;

    /** Tells where a run stopped by @p signal stands and how to go on. */
    void
    report_stop(const int signal, const double time) const;

    void
    write_snapshot(const double time);

    /** "N particles, M grid nodes[, K FEM bodies (...)]". */
    std::string
    scene_summary() const;

    void
    print_test_summary(const double time, const StepDiagnostics<dim> &d) const;

    const SceneParameters<dim> parameters;
    const std::string          parameter_file;
    std::ostream              &console;
    BackgroundGrid<dim>        grid;
    /** Every body's materials, its own then its regions' (a particle's
     *  material id indexes this list), with their densities. */
    std::vector<std::unique_ptr<Material<dim>>> materials;
    std::vector<double>                         material_densities;
    /** Index in materials of body b's own material. */
    std::vector<unsigned int> first_material;
    ParticleSystem<dim>       particle_system;
    ParticleGridTransfer<dim> transfer;
    /** The substepped integrator's own macro-step transfer, if it has one. */
    std::unique_ptr<ParticleGridTransfer<dim>> macro_transfer;
    /** cMPM's coarse nodes and shape functions (cmpm/enabled). */
    std::unique_ptr<CmpmDiscretization<dim>> cmpm;
    /** The bodies' surface loads, if any body has one. */
    std::unique_ptr<ParticleLoads<dim>>        particle_loads;
    std::vector<std::unique_ptr<FemBody<dim>>> fem_body_list;
    /** The integrator 'time/integrator' chooses (create_integrator()). */
    std::unique_ptr<TimeIntegrator<dim>> time_integrator;
    /** Substeps of the last macro step (substepped integrator). */
    unsigned int last_substeps = 0;
    /** Newton statistics since the last diagnostics row. */
    NewtonStatistics                       newton_since_row;
    std::string                            output_folder;
    std::unique_ptr<ParticleOutput<dim>>   particle_output;
    std::unique_ptr<GridOutput<dim>>       grid_output;
    std::unique_ptr<CoarseGridOutput<dim>> coarse_grid_output;
    std::unique_ptr<FemOutput<dim>>        fem_output;
    unsigned int                           step         = 0;
    double                                 current_time = 0.;
    unsigned int                           snapshot     = 0;
  };
} // namespace bfemp

#endif
