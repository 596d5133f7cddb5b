#ifndef bfemp_solver_particle_load_term_h
#define bfemp_solver_particle_load_term_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/particles/particle_loads.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

namespace bfemp
{
  /**
   * The work of the particles' surface loads in the incremental potential,
   * E(u) = -s sum_p f_p(t^{n+1}) . u_p(u) with s = 2 alpha beta dt^2 the
   * weight of the forces (BFEMP eq. 22; backward Euler s = dt^2), and u_p
   * the particle's displacement through the particle-to-unknowns map of
   * the elasticity: u_p = sum_i w_ip u_i on the B-spline grid, or
   * u_p = sum_k B_kp q_k with q = p Q on a cMPM element's fine patch. E is
   * linear in u: its gradient is the constant -s sum_p N_p^T f_p and its
   * Hessian is zero.
   */
  template <int dim>
  class ParticleLoadTerm : public EnergyTerm<dim>
  {
  public:
    ParticleLoadTerm(const BackgroundGrid<dim>     &grid,
                     ParticleSystem<dim>           &particles,
                     ParticleLoads<dim>            &loads,
                     const DofSpace<dim>           &dofs,
                     const CmpmDiscretization<dim> *cmpm = nullptr);

    /** s, the weight of the forces in the potential. */
    void
    set_scale(const double scale);

    /** The loads at time @p t: t^n for Newmark's a^n, t^{n+1} for the
     *  step's potential. */
    void
    set_time(const double t);

    std::string
    name() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

    double
    value(const Vector<double> &u) const override;

    void
    add_gradient(const Vector<double> &u,
                 Vector<double>       &gradient) const override;

    void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const override;

  private:
    const BackgroundGrid<dim>     &grid;
    ParticleSystem<dim>           &particles;
    ParticleLoads<dim>            &loads;
    const DofSpace<dim>           &dofs;
    const CmpmDiscretization<dim> *cmpm;
    double                         scale = 1.;
  };
} // namespace bfemp

#endif
