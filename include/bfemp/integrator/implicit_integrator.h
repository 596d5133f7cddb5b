#ifndef bfemp_integrator_implicit_integrator_h
#define bfemp_integrator_implicit_integrator_h

#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/cmpm/cmpm_inertia_term.h>
#include <bfemp/cmpm/cmpm_regularization_term.h>
#include <bfemp/contact/barrier_term.h>
#include <bfemp/contact/contact_geometry.h>
#include <bfemp/contact/contact_parameters.h>
#include <bfemp/contact/contact_statistics.h>
#include <bfemp/contact/friction_term.h>
#include <bfemp/fem/fem_body.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/integrator/substepped_mpm.h>
#include <bfemp/integrator/time_integrator.h>
#include <bfemp/integrator/time_parameters.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/fem_elasticity_term.h>
#include <bfemp/solver/incremental_potential.h>
#include <bfemp/solver/inertia_term.h>
#include <bfemp/solver/mpm_elasticity_term.h>
#include <bfemp/solver/newton_solver.h>
#include <bfemp/solver/particle_load_term.h>
#include <bfemp/solver/relative_energy_term.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * Implicit time integration of MPM bodies and FEM bodies in one
   * incremental potential (BFEMP Sections 2.2, 3, 4 and 5, Algorithm 1):
   * backward Euler or midpoint Newmark through the (alpha, beta, gamma)
   * family of eq. 21, with barrier contact between particles and FEM
   * boundaries and lagged friction, minimized by projected Newton
   * (Algorithm 2).
   *
   * One step, as step() spells it out:
   *   P2G (Tables 1-3) -> unified DoFs of FEM nodes and active grid nodes
   *      (kinematic FEM bodies have none: they are moving obstacles)
   *   -> constraints (prescribed FEM nodes, grid boundaries)
   *   -> predictor x^ = x^n + dt v^n + alpha (1 - 2 beta) dt^2 a^n
   *   -> friction lagged at x^n (Algorithm 1 line 5)
   *   -> repeat: minimize 1/2 ||x - x^||_M^2 + 2 alpha beta dt^2
   *      (Psi + B + D)(x) (eq. 38), re-lag friction, until the Newton
   *      tolerance holds with the updated friction (lines 6-10)
   *   -> v^{n+1} = v^n + dt ((1 - gamma) a^n + gamma a^{n+1}) (eq. 21)
   *   -> FEM nodes move; G2P of x~, v~ and F (Tables 1-3).
   *
   * With @p substepped_mpm the MPM bodies are not part of the potential's
   * elasticity: their S explicit substeps run first, and the reconstructed
   * macro-step grid velocity v*_k (seed 003 eq. 5) is the grid nodes' start
   * velocity, with gravity and elastic forces already in it. The MPM
   * elasticity enters the potential only relative to its linearization at
   * the substeps' prediction u* (RelativeEnergyTerm): without contact the
   * solve returns u*, with contact the bodies resist the correction with
   * their stiffness. The contact force acts on the grid nodes as a force
   * constant over the substeps: their mass enters the potential as m_k / c
   * and their velocity changes by (u - u^) / (c dt), c =
   * SubsteppedMPM::constant_force_ratio(S). The macro step is backward
   * Euler (doc/substepping.md).
   *
   * With @p cmpm the MPM bodies are discretized by cMPM (seed 002): the
   * unknowns are coarse nodes, P2G and G2P go through the matrix-valued
   * shape functions, which are rebuilt from the particles at the start of
   * every step (doc/cmpm.md); the rest of the step is the same.
   */
  template <int dim>
  class ImplicitIntegrator : public TimeIntegrator<dim>
  {
  public:
    ImplicitIntegrator(
      const BackgroundGrid<dim>                         &grid,
      ParticleSystem<dim>                               &particles,
      const ParticleGridTransfer<dim>                   &transfer,
      const std::vector<std::unique_ptr<Material<dim>>> &materials,
      std::vector<std::unique_ptr<FemBody<dim>>>        &fem_bodies,
      const GridBoundaries<dim>                         &boundaries,
      const Tensor<1, dim>                              &gravity,
      const TimeParameters::ImplicitScheme              &scheme,
      const SolverParameters                            &solver,
      const ContactParameters                           &contact,
      std::unique_ptr<SubsteppedMPM<dim>> substepped_mpm = nullptr,
      CmpmDiscretization<dim>            *cmpm           = nullptr,
      ParticleLoads<dim>                 *loads          = nullptr);

    /**
     * Advances from step.time to step.time + step.dt; throws
     * SimulationError. With substepped MPM bodies, they take step.substeps
     * explicit substeps.
     */
    void
    step(const TimeStep &step) override;

    /** The grid fields of the last step (for output). */
    const GridState<dim> &
    grid_state() const override;

    /** Newton statistics of the last step (never nullptr). */
    const NewtonStatistics *
    newton_statistics() const override;

    /** Unknowns of the last step. */
    unsigned int
    n_dofs() const override;

    /**
     * Continues the friction dissipation accumulated over the steps of a
     * checkpointed run (ContactStatistics::accumulated_dissipation).
     */
    void
    resume_friction_dissipation(const double accumulated) override;

    /** Contact state at the end of the last step (never nullptr;
     *  ContactStatistics::active says whether the scene has contact). */
    const ContactStatistics<dim> *
    contact_statistics() const override;

    /**
     * Particles inside an FEM element or at distance 0 from an FEM
     * boundary now (the check at t = 0: bodies must not overlap). If there
     * are none, also measures the barrier at the start, so that
     * contact_statistics() describes t = 0 until the first step.
     */
    unsigned int
    particles_touching_fem();

    /**
     * After particles_touching_fem(): the (MPM body, FEM body) pairs with a
     * particle of the first inside the second, for the message.
     */
    std::set<std::pair<unsigned int, unsigned int>>
    bodies_overlapping_fem() const;

  private:
    /**
     * P2G of mass and momentum (Algorithm 1 line 2); v = (m v) / m. With
     * cMPM, the shape functions are rebuilt first: at the step's start, or
     * given @p coarse_displacement, by the full-Newton local solve there.
     */
    void
    particles_to_grid(
      const std::vector<Tensor<1, dim>> *coarse_displacement = nullptr);

    /** Numbers FEM nodes and active grid nodes; gathers m and v^n. */
    void
    number_unknowns();

    /** Prescribed FEM nodes and grid boundary conditions at t + dt. */
    void
    constrain(const double dt, const double end_time);

    /** The contact terms' weight relative to the elastic ones'. */
    double
    contact_factor() const
    {
      return scheme.contact_weight() / scheme.potential_weight();
    }

    /** a^n = -M^-1 grad Psi(x^n) + g (Newmark's start acceleration). */
    Vector<double>
    start_acceleration() const;

    /**
     * u^ = dt v^n + alpha (1 - 2 beta) dt^2 a^n + 2 alpha beta dt^2 g; grid
     * nodes of substepped MPM bodies advance by their substeps' dt v*_k
     * instead of dt v^n.
     */
    Vector<double>
    predictor(const Vector<double> &acceleration, const double dt) const;

    /**
     * v^{n+1} of eq. 21 with a^{n+1} = (u - u^) / (2 alpha beta dt^2) + g;
     * constrained nodes take their prescribed velocity in the constrained
     * directions.
     */
    Vector<double>
    end_velocity(const Vector<double> &u,
                 const Vector<double> &predicted,
                 const Vector<double> &acceleration,
                 const double          dt) const;

    /** x^{n+1} = x^n + u, v^{n+1} for the FEM nodes (Algorithm 1 line 11). */
    void
    update_fem_bodies(const Vector<double> &u,
                      const Vector<double> &velocity,
                      const double          end_time);

    /** G2P of x~, v~ and F (Algorithm 1 line 12). */
    void
    grid_to_particles(const Vector<double> &u, const Vector<double> &velocity);

    /**
     * Algorithm 1 lines 4-10: minimizations alternating with friction
     * updates until the friction is converged (or the limit is reached).
     */
    void
    minimize_with_friction(Vector<double>    &u,
                           const double       dt,
                           const std::string &label);

    /**
     * `solver/Newton increment = material points`: the increment @p p
     * measured on what the step hands on, the largest of |p_a| over FEM
     * nodes and, over particles, |sum_i w_ip p_i| and h |dF_p(p)|.
     */
    double
    material_increment(const Vector<double> &p) const;

    /**
     * The acceleration the predictor and eq. 21 add for @p node: gravity,
     * except for grid nodes of substepped MPM bodies, whose start velocity
     * v*_k already holds it.
     */
    Tensor<1, dim>
    node_gravity(const unsigned int node) const;

    /** c for @p node: constant_force_ratio for substepped grid nodes. */
    double
    node_force_ratio(const unsigned int node) const;

    /** dt v^n, or the substeps' dt v*_k for their grid nodes. */
    Tensor<1, dim>
    free_advance(const unsigned int node, const double dt) const;

    /** The barrier's pairs, distances, energy and forces at @p u into
     *  the contact statistics. */
    void
    measure_barrier(const Vector<double> &u);

    /** Records the contact state at the step's solution u. */
    void
    measure_contact(const Vector<double> &u);

    const BackgroundGrid<dim>                         &grid;
    ParticleSystem<dim>                               &particles;
    const ParticleGridTransfer<dim>                   &transfer;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    std::vector<std::unique_ptr<FemBody<dim>>>        &fem_bodies;
    const GridBoundaries<dim>                         &boundaries;
    const Tensor<1, dim>                               gravity;
    const TimeParameters::ImplicitScheme               scheme;
    const bool                                         with_mpm;
    /** The substepped integrator of the MPM bodies, owned here. */
    std::unique_ptr<SubsteppedMPM<dim>> owned_substepped_mpm;
    SubsteppedMPM<dim>                 *substepped_mpm;
    CmpmDiscretization<dim>            *cmpm;

    DofSpace<dim>           dofs;
    const ContactParameters contact_parameters;
    const bool              with_contact;
    const bool              with_friction;
    InertiaTerm<dim>        inertia;
    /** The hold on weakly seen coarse-node combinations (cMPM, r > 0). */
    std::unique_ptr<CmpmRegularizationTerm<dim>> cmpm_regularization;
    /** The bodies' surface loads (only if a body has one). */
    std::unique_ptr<ParticleLoadTerm<dim>> particle_loads;
    /** The consistent inertia of cMPM bodies (replaces inertia). */
    std::unique_ptr<CmpmInertiaTerm<dim>> cmpm_inertia;
    FemElasticityTerm<dim>                fem_elasticity;
    MpmElasticityTerm<dim>                mpm_elasticity;
    /** MPM elasticity relative to the substeps' prediction (substepped). */
    RelativeEnergyTerm<dim>               mpm_correction_elasticity;
    std::unique_ptr<ContactGeometry<dim>> contact_geometry;
    std::unique_ptr<BarrierTerm<dim>>     barrier;
    std::unique_ptr<FrictionTerm<dim>>    friction;
    IncrementalPotential<dim>             potential;
    NewtonSolver<dim>                     newton;

    /**
     * One energy term of the step's potential and what the step does with
     * it: the term list of the potential, the per-step scale and Newmark's
     * start acceleration all come from this one list, so that a new term
     * is registered in one place (register_term()) and cannot drop out of
     * one of them silently.
     */
    struct RegisteredTerm
    {
      const EnergyTerm<dim> *term;
      /** Sets the term's weight for the step (w dt^2, dt); may be empty. */
      std::function<void(double scale, double dt)> set_time_step;
      /** Whether the term's gradient at x^n is a force of the state at
       *  t^n, which a^n = M^-1 (f^n) + g of Newmark includes. */
      bool force_at_start;
    };
    std::vector<RegisteredTerm> registered_terms;

    /** Adds @p term to the potential (in registration order). */
    void
    register_term(const EnergyTerm<dim>                       &term,
                  std::function<void(double scale, double dt)> set_time_step,
                  const bool                                   force_at_start);

    GridState<dim>      state;
    std::vector<double> node_mass;
    /** v^n; for grid nodes of substepped MPM bodies their v~_k. */
    Vector<double> start_velocity;
    /** Velocity of each constraint's target, by constraint index. */
    std::vector<Tensor<1, dim>> constraint_velocity;
    double                      scale = 0.;
    /** c of the substepped grid nodes in this step (1 otherwise). */
    double                 constant_force_ratio = 1.;
    NewtonStatistics       last_statistics;
    ContactStatistics<dim> last_contact;
  };
} // namespace bfemp

#endif
