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
    double         mass                 = 0.;
    double         kinetic_energy       = 0.;
    double         elastic_energy       = 0.;
    double         gravitational_energy = 0.;
    Tensor<1, dim> linear_momentum;
    /** z-component only in 2D. */
    Tensor<1, 3> angular_momentum;
    double       min_J     = std::numeric_limits<double>::infinity();
    double       max_speed = 0.;
    bool         finite    = true;

    /** Combines partial sums (min and max for min_J and max_speed). */
    StepDiagnostics &
    operator+=(const StepDiagnostics &other);

    double
    total_energy() const;

    /** Measures the particle state. */
    static StepDiagnostics
    measure(const ParticleSystem<dim>                         &particles,
            const std::vector<std::unique_ptr<Material<dim>>> &materials,
            const ParticleGridTransfer<dim>                   &transfer,
            const Tensor<1, dim>                              &gravity);

    /**
     * Measures the FEM bodies: lumped-mass kinetic energy and momentum, the
     * element energies sum_e V_e psi(F_e), -m g.x and min det F_e.
     */
    static StepDiagnostics
    measure(const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
            const Tensor<1, dim>                             &gravity);

    /** max_p |v_p| alone, for the CFL check between diagnosed steps. */
    static double
    measure_max_speed(const ParticleSystem<dim> &particles);

    /** max |v| over the nodes of the FEM bodies alone. */
    static double
    measure_max_speed(const std::vector<std::unique_ptr<FemBody<dim>>> &bodies);
  };
} // namespace bfemp

#endif
