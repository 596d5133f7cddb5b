#ifndef bfemp_solver_relative_energy_term_h
#define bfemp_solver_relative_energy_term_h

#include <bfemp/solver/energy_term.h>

namespace bfemp
{
  /**
   * An energy term measured relative to its linearization at a reference
   * state u* (its Bregman divergence):
   *
   *   R(u) = E(u) - E(u*) - grad E(u*) . (u - u*),
   *
   * with the Hessian, step bound and couplings of E. R and its gradient
   * vanish at u*, so a potential gains nothing from R where u stays at u*,
   * but any departure from u* costs what the curvature of E says.
   *
   * Substepped MPM coupled with FEM uses it for the MPM elasticity: the
   * substeps already applied the elastic forces along their path to u*,
   * so the macro contact solve must not apply them again, yet it must feel
   * the bodies' stiffness when contact moves their grid nodes away from u*
   * (doc/substepping.md). Translation invariance of E carries over to R, so
   * R exerts no net force.
   */
  template <int dim>
  class RelativeEnergyTerm : public EnergyTerm<dim>
  {
  public:
    explicit RelativeEnergyTerm(const EnergyTerm<dim> &term);

    /**
     * Sets u* and evaluates E(u*) and grad E(u*); throws SimulationError if
     * E(u*) is not finite (an inverted reference state).
     */
    void
    set_reference(const Vector<double> &reference);

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

    double
    step_bound(const Vector<double> &u, const Vector<double> &p) const override;

    double
    magnitude() const override;

    double
    minimum_determinant(const Vector<double> &u) const override;

  private:
    const EnergyTerm<dim> &term;
    Vector<double>         reference;
    Vector<double>         reference_gradient;
    double                 reference_value = 0.;
  };
} // namespace bfemp

#endif
