#include <bfemp/base/parallel_sum.h>
#include <bfemp/solver/inertia_term.h>

namespace bfemp
{
  template <int dim>
  void
  InertiaTerm<dim>::reinit(const std::vector<double> &node_mass,
                           const Vector<double>      &predictor)
  {
    mass   = node_mass;
    target = predictor;
    size   = 0.;
    for (unsigned int i = 0; i < mass.size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        size += 0.5 * mass[i] * target[dim * i + c] * target[dim * i + c];
  }



  template <int dim>
  std::string
  InertiaTerm<dim>::name() const
  {
    return "inertia";
  }



  template <int dim>
  void
  InertiaTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    for (unsigned int i = 0; i < mass.size(); ++i)
      sparsity.add_clique(&i, 1);
  }



  template <int dim>
  double
  InertiaTerm<dim>::value(const Vector<double> &u) const
  {
    return chunked_sum<double>(mass.size(), [&](const std::size_t i) {
      double norm_square = 0.;
      for (unsigned int c = 0; c < dim; ++c)
        {
          const double d = u[dim * i + c] - target[dim * i + c];
          norm_square += d * d;
        }
      return 0.5 * mass[i] * norm_square;
    });
  }



  template <int dim>
  double
  InertiaTerm<dim>::magnitude() const
  {
    return size;
  }



  template <int dim>
  void
  InertiaTerm<dim>::add_gradient(const Vector<double> &u,
                                 Vector<double>       &gradient) const
  {
    for (unsigned int i = 0; i < mass.size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        gradient[dim * i + c] +=
          mass[i] * (u[dim * i + c] - target[dim * i + c]);
  }



  template <int dim>
  void
  InertiaTerm<dim>::add_hessian(const Vector<double> &,
                                SparseMatrix<double> &hessian,
                                const HessianKind /*kind*/) const
  {
    for (unsigned int i = 0; i < mass.size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        hessian.diag_element(dim * i + c) += mass[i];
  }



  template class InertiaTerm<2>;
  template class InertiaTerm<3>;
} // namespace bfemp
