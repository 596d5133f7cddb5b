#ifndef bfemp_solver_fem_elasticity_term_h
#define bfemp_solver_fem_elasticity_term_h

#include <bfemp/fem/fem_body.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * The elastic energy of the FEM bodies, 2 alpha beta dt^2 sum_e V_e
   * psi(F_e(x)) (BFEMP eq. 22) with F_e = T_e B_e^-1 (eq. 24), x = x^n + u.
   * Element Hessians use the PSD projection of dP/dF before the chain rule,
   * so each is PSD and so is their sum (projected Newton, Section 5).
   */
  template <int dim>
  class FemElasticityTerm : public EnergyTerm<dim>
  {
  public:
    FemElasticityTerm(const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
                      const DofSpace<dim>                              &dofs);

    /** s = 2 alpha beta dt^2, the weight of Psi in eq. 22. */
    void
    set_scale(const double scale);

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

    /** Smallest positive root over elements of det T_e(x + t p) = 0. */
    double
    step_bound(const Vector<double> &u, const Vector<double> &p) const override;

    double
    minimum_determinant(const Vector<double> &u) const override;

  private:
    struct ElementReference
    {
      unsigned int body;
      unsigned int element;
    };

    using NodePositions = typename SimplexElement<dim>::NodePositions;

    /** Unified nodes of an element. */
    std::array<unsigned int, dim + 1>
    unified_nodes(const ElementReference &e) const;

    /** Current node positions x^n + u of an element. */
    NodePositions
    positions(const ElementReference &e, const Vector<double> &u) const;

    /** The node displacements p of an element, as positions. */
    NodePositions
    directions(const ElementReference &e, const Vector<double> &p) const;

    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies;
    const DofSpace<dim>                              &dofs;
    std::vector<ElementReference>                     all_elements;
    double                                            scale = 1.;
  };
} // namespace bfemp

#endif
