#include <bfemp/base/input_error.h>
#include <bfemp/solver/relative_energy_term.h>

#include <cmath>

namespace bfemp
{
  template <int dim>
  RelativeEnergyTerm<dim>::RelativeEnergyTerm(const EnergyTerm<dim> &term)
    : term(term)
  {}



  template <int dim>
  void
  RelativeEnergyTerm<dim>::set_reference(const Vector<double> &u)
  {
    reference       = u;
    reference_value = term.value(u);
    if (!std::isfinite(reference_value))
      throw SimulationError(term.name() +
                            ": the reference state of the macro step is "
                            "inverted (det F <= 0 at some particle); the "
                            "substeps' prediction is not usable: reduce the "
                            "macro time step");
    reference_gradient.reinit(u.size());
    term.add_gradient(u, reference_gradient);
  }



  template <int dim>
  std::string
  RelativeEnergyTerm<dim>::name() const
  {
    return term.name() + " (relative to the substeps)";
  }



  template <int dim>
  void
  RelativeEnergyTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    term.add_couplings(sparsity);
  }



  template <int dim>
  double
  RelativeEnergyTerm<dim>::value(const Vector<double> &u) const
  {
    double linear = 0.;
    for (unsigned int i = 0; i < u.size(); ++i)
      linear += reference_gradient[i] * (u[i] - reference[i]);
    return term.value(u) - reference_value - linear;
  }



  template <int dim>
  void
  RelativeEnergyTerm<dim>::add_gradient(const Vector<double> &u,
                                        Vector<double>       &gradient) const
  {
    term.add_gradient(u, gradient);
    gradient -= reference_gradient;
  }



  template <int dim>
  void
  RelativeEnergyTerm<dim>::add_hessian(const Vector<double> &u,
                                       SparseMatrix<double> &hessian,
                                       const HessianKind     kind) const
  {
    term.add_hessian(u, hessian, kind);
  }



  template <int dim>
  double
  RelativeEnergyTerm<dim>::step_bound(const Vector<double> &u,
                                      const Vector<double> &p) const
  {
    return term.step_bound(u, p);
  }



  template <int dim>
  double
  RelativeEnergyTerm<dim>::magnitude() const
  {
    return term.magnitude() + std::abs(reference_value);
  }



  template <int dim>
  double
  RelativeEnergyTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    return term.minimum_determinant(u);
  }



  template class RelativeEnergyTerm<2>;
  template class RelativeEnergyTerm<3>;
} // namespace bfemp
