#ifndef bfemp_integrator_substepped_mpm_h
#define bfemp_integrator_substepped_mpm_h

#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/integrator/explicit_mpm.h>
#include <bfemp/integrator/macro_velocity_reconstruction.h>
#include <bfemp/integrator/time_integrator.h>
#include <bfemp/integrator/time_parameters.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <vector>

namespace bfemp
{
  /**
   * Explicit MPM wrapped into a pseudo-implicit macro step (seed 003).
   *
   * One macro step from t^n to t^n + dt:
   *   P2G on the grid of step n: m_k, v_k^n (the macro step's grid)
   *   -> S explicit substeps of dt / S (ExplicitMPM, USL or USF, the
   *      transfer of subsection 'transfer')
   *   -> secant targets dt v*_p = x_p^{n+1,S} - x_p^n and
   *      dt C*_p = F_p^{n+1,S} (F_p^n)^-1 - I (eq. 1)
   *   -> particles back to their state at t^n
   *   -> v*_k on the grid of step n (MacroVelocityReconstruction, eq. 5 or
   *      eq. 4), then the grid boundaries at t^n + dt: the macro-step
   *      displacement u_k = dt v*_k
   *   -> the end velocity v~_k: the same reconstruction of the particles'
   *      end-of-substep velocities (or v*_k itself with 'macro-step
   *      velocity = secant', the seed read literally)
   *   -> G2P with the macro-step transfer, as after an implicit step:
   *      x^{n+1} = x^n + sum w u, F^{n+1} = (I + grad u) F^n, v from v~.
   *
   * The secant velocity v*_p is the mean velocity over the macro step, not
   * its end velocity: under a constant acceleration a it is v^n + dt a
   * (S + 1) / (2 S). Using it as v^{n+1} therefore slows every acceleration
   * by that factor; the default keeps the end velocity separate.
   *
   * With FEM bodies, ImplicitIntegrator calls substep_and_reconstruct()
   * instead of step(): v*_k then enters its barrier contact solve as the
   * grid nodes' start velocity (doc/substepping.md).
   */
  template <int dim>
  class SubsteppedMPM : public TimeIntegrator<dim>
  {
  public:
    SubsteppedMPM(const BackgroundGrid<dim>         &grid,
                  ParticleSystem<dim>               &particles,
                  const ParticleGridTransfer<dim>   &substep_transfer,
                  const ParticleGridTransfer<dim>   &macro_transfer,
                  const GridBoundaries<dim>         &boundaries,
                  const Tensor<1, dim>              &gravity,
                  const TimeParameters::Substepping &parameters,
                  ParticleLoads<dim>                *loads = nullptr);

    /** A macro step of S = step.substeps substeps from step.time to
     *  step.time + step.dt (MPM only). */
    void
    step(const TimeStep &step) override;

    /**
     * Runs S substeps, returns the particles to their state at @p time and
     * writes, for the nodes with mass in macro_grid.mass (the P2G masses at
     * the particles' current positions), the macro-step displacement dt v*_k
     * into macro_grid.displacement and the end velocity v~_k into
     * macro_grid.new_velocity, both boundary-projected at time + dt.
     */
    void
    substep_and_reconstruct(const double       dt,
                            const double       time,
                            const unsigned int substeps,
                            GridState<dim>    &macro_grid);

    /**
     * c(S) = (macro-step displacement) / (dt * velocity change) for a force
     * held constant over the S substeps: (S + 1) / (2 S) for the
     * symplectic substep update x += delta t v^{s+1}; 1 with 'macro-step
     * velocity = secant', where the end velocity is the secant one. The
     * macro contact solve applies its forces to the MPM side with these
     * kinematics (doc/substepping.md).
     */
    double
    constant_force_ratio(const unsigned int substeps) const;

    /** The grid fields of the last macro step (for output). */
    const GridState<dim> &
    grid_state() const override;

  private:
    /** Stores x_p^n, v_p^n, C_p^n and F_p^n by particle id. */
    void
    save_start_state();

    /**
     * The targets of eq. 1 and the end-of-substep velocities (with the APIC
     * affine velocity as their gradient, or C*_p for PIC/FLIP substeps)
     * from the substepped state, then the particles back to their saved
     * state.
     */
    void
    secant_targets_and_restore(const double dt);

    const BackgroundGrid<dim>       &grid;
    ParticleSystem<dim>             &particles;
    const ParticleGridTransfer<dim> &substep_transfer;
    const ParticleGridTransfer<dim> &macro_transfer;
    const GridBoundaries<dim>       &boundaries;
    ExplicitMPM<dim>                 substep_integrator;
    MacroVelocityReconstruction<dim> reconstruction;

    /**
     * Start-of-step particle state by particle id. Serial storage; with
     * distributed particles these become maps over the locally owned ids.
     */
    std::vector<Point<dim>>        start_position;
    std::vector<Tensor<1, dim>>    start_velocity;
    std::vector<Tensor<2, dim>>    start_affine_velocity;
    std::vector<Tensor<2, dim>>    start_deformation_gradient;
    std::vector<SecantTarget<dim>> targets;
    std::vector<SecantTarget<dim>> end_targets;
    const bool                     secant_end_velocity;
    const bool                     affine_substeps;

    GridState<dim> state;
  };
} // namespace bfemp

#endif
