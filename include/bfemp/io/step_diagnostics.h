#ifndef bfemp_io_step_diagnostics_h
#define bfemp_io_step_diagnostics_h

#include <bfemp/fem/fem_body.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <limits>
#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * Global quantities of the particle state and the FEM bodies, the row of
   * diagnostics.csv.
   * Angular momentum about the origin includes APIC's affine part,
   * m_p eps : (C_p D_p), so that it is the quantity APIC conserves.
   */
  template <int dim>
  struct StepDiagnostics
  {
    double mass                 = 0.;
    double kinetic_energy       = 0.;
    double elastic_energy       = 0.;
    double gravitational_energy = 0.;
    /**
     * APIC only: sum 1/2 m_p C_p : (C_p D_p), the kinetic energy of the
     * particles' affine velocity fields. P2G hands it to the grid along
     * with 1/2 m_p |v_p|^2 (grid kinetic energy <= both together), so
     * energy moving between the two shows up in kinetic_energy alone as a
     * loss or a gain. Not part of total_energy(), which is the quantity
     * the BFEMP paper plots.
     */
    double         affine_kinetic_energy = 0.;
    Tensor<1, dim> linear_momentum;
    /** sum m x: the centre of mass is first_moment / mass. */
    Tensor<1, dim> first_moment;
    /** z-component only in 2D. */
    Tensor<1, 3> angular_momentum;
    double       min_J     = std::numeric_limits<double>::infinity();
    double       max_speed = 0.;
    bool         finite    = true;
    /**
     * Particles strictly inside a level-set obstacle (set by the
     * Simulation, which knows the boundaries and the time).
     */
    unsigned int particles_in_level_sets = 0;

    /** Combines partial sums (min and max for min_J and max_speed). */
    StepDiagnostics &
    operator+=(const StepDiagnostics &other);

    double
    total_energy() const;

    /** first_moment / mass (0 for no mass). */
    Point<dim>
    center_of_mass() const;

    /** linear_momentum / mass (0 for no mass). */
    Tensor<1, dim>
    center_of_mass_velocity() const;

    /**
     * Measures the particle state: all particles, or those of MPM body
     * @p body alone.
     */
    static StepDiagnostics
    measure(const ParticleSystem<dim>                         &particles,
            const std::vector<std::unique_ptr<Material<dim>>> &materials,
            const ParticleGridTransfer<dim>                   &transfer,
            const Tensor<1, dim>                              &gravity,
            const unsigned int body = numbers::invalid_unsigned_int);

    /**
     * Measures the FEM bodies: lumped-mass kinetic energy and momentum, the
     * element energies sum_e V_e psi(F_e), -m g.x and min det F_e.
     */
    static StepDiagnostics
    measure(const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
            const Tensor<1, dim>                             &gravity);

    /** The same for one FEM body. */
    static StepDiagnostics
    measure(const FemBody<dim> &body, const Tensor<1, dim> &gravity);

    /** max_p |v_p| alone, for the CFL check between diagnosed steps. */
    static double
    measure_max_speed(const ParticleSystem<dim> &particles);

    /** max |v| over the nodes of the FEM bodies alone. */
    static double
    measure_max_speed(const std::vector<std::unique_ptr<FemBody<dim>>> &bodies);
  };
} // namespace bfemp

#endif
