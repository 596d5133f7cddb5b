#ifndef bfemp_transfer_particle_grid_transfer_h
#define bfemp_transfer_particle_grid_transfer_h

#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/transfer_parameters.h>

#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * Particle-to-grid and grid-to-particle transfers of BFEMP Tables 1 (APIC),
   * 2 (PIC) and 3 (FLIP), shared by every integrator. The grid-to-particle
   * side is written in terms of the grid's end-of-step velocity v~_i and
   * displacement u_i = x~_i - x_i, so explicit (u_i = dt v~_i) and implicit
   * (u_i from the incremental potential) steps use the same code.
   */
  template <int dim>
  class ParticleGridTransfer
  {
  public:
    ParticleGridTransfer(
      const BackgroundGrid<dim>                         &grid,
      const TransferParameters                          &parameters,
      const std::vector<std::unique_ptr<Material<dim>>> &materials);

    /**
     * m_i = sum_p w_ip m_p and m_i v_i = sum_p w_ip m_p (v_p + C_p (x_i -
     * x_p)), C_p = 0 unless APIC. With @p with_stress also the internal force
     * f_i = -sum_p V_p^0 P(F_p) F_p^T grad w_ip. The grid state must be zero.
     * Leaves momentum in GridState::velocity; the caller divides by mass.
     */
    void
    particles_to_grid(ParticleSystem<dim> &particles,
                      GridState<dim>      &grid_state,
                      const bool           with_stress) const;

    /** Internal force only, f_i = -sum_p V_p^0 P F^T grad w_ip. */
    void
    stress_to_grid(ParticleSystem<dim> &particles,
                   GridState<dim>      &grid_state) const;

    /**
     * Velocity (PIC, FLIP with PIC blend, or APIC), position x_p^{n+1} =
     * sum_i x~_i w_ip, affine velocity (APIC) and, if requested, F_p^{n+1} =
     * sum_i x~_i grad w_ip^T F_p^n, from the grid's new_velocity,
     * displacement and (FLIP) velocity. With @p explicit_dt > 0 the
     * displacement is u_i = explicit_dt v~_i, formed on the fly instead of
     * read from the grid state (the explicit integrators' case).
     */
    void
    grid_to_particles(ParticleSystem<dim>  &particles,
                      const GridState<dim> &grid_state,
                      const bool            update_deformation_gradient,
                      const double          explicit_dt = 0.) const;

    /** F_p <- (I + sum_i u_i grad w_ip^T) F_p (USF's early stress update). */
    void
    update_deformation_gradient(
      ParticleSystem<dim>               &particles,
      const std::vector<Tensor<1, dim>> &grid_displacement) const;

    /**
     * The APIC inertia-like matrix D_p = sum_i w_ip (x_i - x_p)(x_i - x_p)^T
     * (Table 1) at x: dx^2/4 I (quadratic), dx^2/3 I (cubic), position
     * dependent for the linear kernel.
     */
    Tensor<2, dim>
    apic_inertia(const Point<dim> &x) const;

    /** The scheme and blend this transfer was built with. */
    const TransferParameters &
    parameters() const;

  private:
    template <int degree>
    void
    scatter(ParticleSystem<dim> &particles,
            GridState<dim>      &grid_state,
            const bool           with_momentum,
            const bool           with_stress) const;

    template <int degree, bool explicit_step>
    void
    gather(ParticleSystem<dim>  &particles,
           const GridState<dim> &grid_state,
           const bool            update_deformation_gradient,
           const double          explicit_dt) const;

    const BackgroundGrid<dim>                         &grid;
    const TransferParameters                           transfer_parameters;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
  };
} // namespace bfemp

#endif
