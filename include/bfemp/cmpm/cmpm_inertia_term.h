#ifndef bfemp_cmpm_cmpm_inertia_term_h
#define bfemp_cmpm_cmpm_inertia_term_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

#include <deal.II/lac/sparse_matrix.h>

#include <vector>

namespace bfemp
{
  /**
   * The inertia of cMPM bodies in the backward Euler incremental potential
   * (BFEMP eq. 22 with the consistent mass; seed 002 eqs. 5-6), with the
   * particles as quadrature:
   * @f[
   *   E(u) = \frac12 \sum_p m_p \Big|\sum_I \Phi_{Ip} u_I - \hat u_p\Big|^2,
   *   \quad \hat u_p = \Delta t\, v_p + \Delta t^2 g ,
   * @f]
   * whose Hessian is the consistent mass sum_p m_p Phi_Ip^T Phi_Jp. It is
   * formed on each element's fine patch, the scalar fine mass
   * sum_p m_p B_kp B_lp, and condensed with the element's control matrix
   * p (CmpmElementAssembly), so that a particle costs 3^dim fine functions. A
   * lumped mass would need positive row sums, which the coarsened shape
   * functions do not have (they are negative at some coarse nodes outside the
   * body). With this form the step conserves linear momentum exactly: the
   * gradients of the elasticity sum to zero over the coarse nodes (partition
   * of unity), so sum_p m_p u_p = sum_p m_p u^_p at the minimum.
   */
  template <int dim>
  class CmpmInertiaTerm : public EnergyTerm<dim>
  {
  public:
    CmpmInertiaTerm(ParticleSystem<dim>           &particles,
                    const CmpmDiscretization<dim> &cmpm,
                    const DofSpace<dim>           &dofs);

    /** u^_p = dt v_p + @p gravity_weight g (gravity_weight = dt^2). */
    void
    reinit(const double          dt,
           const double          gravity_weight,
           const Tensor<1, dim> &gravity);

    std::string
    name() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

    double
    value(const Vector<double> &u) const override;

    double
    magnitude() const override;

    void
    add_gradient(const Vector<double> &u,
                 Vector<double>       &gradient) const override;

    void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const override;

  private:
    /** u^_p = dt v_p + gravity_weight g of a particle. */
    template <typename ParticleAccessor>
    Tensor<1, dim>
    target(const ParticleAccessor &particle) const;

    /** r_p = u_p - u^_p with u_p = sum_k B_k q_k, the fine functions
     *  @p B at the particle and the element's fine control values q. */
    template <typename ParticleAccessor>
    Tensor<1, dim>
    residual(const ParticleAccessor                      &particle,
             const typename CoarseGrid<dim>::FineStencil &B,
             const std::vector<Tensor<1, dim>>           &q) const;

    ParticleSystem<dim>           &particles;
    const CmpmDiscretization<dim> &cmpm;
    const DofSpace<dim>           &dofs;
    double                         dt             = 0.;
    double                         gravity_weight = 0.;
    Tensor<1, dim>                 gravity;

    /** Assembles the consistent mass into @p hessian (one p^T M p per
     *  element). */
    void
    assemble_mass(SparseMatrix<double> &hessian) const;

    /**
     * The consistent mass depends on the particles' positions at t^n and
     * the step's control matrices only, not on u: it is assembled once per
     * reinit() over its own couplings and added to every Newton iteration's
     * Hessian, which saves one condensation per element and iteration. It
     * is kept by rows with the columns ascending (mass_row_start indexes
     * mass_columns and mass_values), the form in which a row is added to
     * the Hessian in one walk; having its own couplings keeps it valid when
     * contact rebuilds the Hessian's pattern.
     */
    mutable std::vector<std::size_t>             mass_row_start;
    mutable std::vector<types::global_dof_index> mass_columns;
    mutable std::vector<double>                  mass_values;
    mutable bool                                 mass_assembled = false;
  };
} // namespace bfemp

#endif
