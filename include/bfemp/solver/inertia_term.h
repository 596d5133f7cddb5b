#ifndef bfemp_solver_inertia_term_h
#define bfemp_solver_inertia_term_h

#include <bfemp/solver/energy_term.h>

#include <vector>

namespace bfemp
{
  /**
   * The inertia part of BFEMP eq. 22, 1/2 ||x - x^_n||_M^2 with the lumped
   * (diagonal) mass M of FEM nodes and MPM grid nodes. In displacements,
   * 1/2 sum_i m_i |u_i - u^_i|^2 with the predictor u^ = x^_n - x^n.
   * Gravity is a linear potential -m g.x; folded into the predictor (u^ +=
   * 2 alpha beta dt^2 g) it changes E only by a constant.
   */
  template <int dim>
  class InertiaTerm : public EnergyTerm<dim>
  {
  public:
    /** @p node_mass per unified node, @p predictor u^ per DoF. */
    void
    reinit(const std::vector<double> &node_mass,
           const Vector<double>      &predictor);

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
    std::vector<double> mass;
    Vector<double>      target;
    double              size = 0.;
  };
} // namespace bfemp

#endif
