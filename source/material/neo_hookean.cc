#include <bfemp/material/neo_hookean.h>
#include <bfemp/material/singular_value_decomposition.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <limits>

namespace bfemp
{
  template <int dim>
  NeoHookean<dim>::NeoHookean(const ElasticModuli &moduli)
    : Material<dim>(moduli)
  {}



  template <int dim>
  double
  NeoHookean<dim>::energy_density(const Tensor<2, dim> &F) const
  {
    const double J = determinant(F);
    // An inverted or collapsed state has infinite energy, which any
    // energy-decreasing line search rejects.
    if (!(J > 0.))
      return std::numeric_limits<double>::infinity();

    const double mu     = this->elastic_moduli.mu;
    const double lambda = this->elastic_moduli.lambda;
    const double log_J  = std::log(J);
    return 0.5 * mu * (scalar_product(F, F) - dim) - mu * log_J +
           0.5 * lambda * log_J * log_J;
  }



  template <int dim>
  Tensor<2, dim>
  NeoHookean<dim>::first_piola_kirchhoff(const Tensor<2, dim> &F) const
  {
    const double J = determinant(F);
    Assert(J > 0., ExcMessage("neo-Hookean stress requires det F > 0"));

    const double         mu      = this->elastic_moduli.mu;
    const double         lambda  = this->elastic_moduli.lambda;
    const Tensor<2, dim> F_inv_T = transpose(invert(F));
    return mu * F + (lambda * std::log(J) - mu) * F_inv_T;
  }



  template <int dim>
  Tensor<4, dim>
  NeoHookean<dim>::first_piola_kirchhoff_derivative(
    const Tensor<2, dim> &F) const
  {
    const double J = determinant(F);
    Assert(J > 0., ExcMessage("neo-Hookean tangent requires det F > 0"));

    const double         mu      = this->elastic_moduli.mu;
    const double         lambda  = this->elastic_moduli.lambda;
    const double         c       = mu - lambda * std::log(J);
    const Tensor<2, dim> F_inv_T = transpose(invert(F));

    Tensor<4, dim> dP_dF = lambda * outer_product(F_inv_T, F_inv_T);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            dP_dF[i][j][k][l] +=
              c * F_inv_T[i][l] * F_inv_T[k][j] + (i == k && j == l ? mu : 0.);
    return dP_dF;
  }



  template <int dim>
  Tensor<4, dim>
  NeoHookean<dim>::filtered_first_piola_kirchhoff_derivative(
    const Tensor<2, dim>  &F,
    const EigenvalueFilter filter) const
  {
    const SingularValueDecomposition<dim> svd =
      signed_singular_value_decomposition(F);
    const Tensor<1, dim> &sigma = svd.sigma;
    Assert(sigma[dim - 1] > 0.,
           ExcMessage("neo-Hookean tangent requires det F > 0"));

    const double mu     = this->elastic_moduli.mu;
    const double lambda = this->elastic_moduli.lambda;
    // A product of the singular values keeps full relative accuracy (no
    // cancellation), so ln J stays accurate for J -> 0.
    double J = 1.;
    for (unsigned int i = 0; i < dim; ++i)
      J *= sigma[i];
    const double c = lambda * std::log(J) - mu;

    SymmetricTensor<2, dim> hessian, twist, flip;
    for (unsigned int i = 0; i < dim; ++i)
      {
        hessian[i][i] = mu + (lambda - c) / (sigma[i] * sigma[i]);
        for (unsigned int j = i + 1; j < dim; ++j)
          {
            const double inverse_product = 1. / (sigma[i] * sigma[j]);
            hessian[i][j]                = lambda * inverse_product;
            twist[i][j]                  = mu + c * inverse_product;
            flip[i][j]                   = mu - c * inverse_product;
          }
      }
    return project_isotropic_tangent(svd, hessian, twist, flip, filter);
  }



  template <int dim>
  std::string
  NeoHookean<dim>::name() const
  {
    return "neo-Hookean";
  }



  template class NeoHookean<2>;
  template class NeoHookean<3>;
} // namespace bfemp
