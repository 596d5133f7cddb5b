#include <bfemp/material/linear_elastic.h>

#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>

namespace bfemp
{
  namespace
  {
    template <int dim>
    SymmetricTensor<2, dim>
    small_strain(const Tensor<2, dim> &F)
    {
      return symmetrize(F) - unit_symmetric_tensor<dim>();
    }
  } // namespace



  template <int dim>
  LinearElastic<dim>::LinearElastic(const ElasticModuli &moduli)
    : Material<dim>(moduli)
  {
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            tangent[i][j][k][l] =
              moduli.mu * ((i == k && j == l) + (i == l && j == k)) +
              moduli.lambda * (i == j && k == l);

    // Spectral decomposition of the class documentation: the tangent is
    // 2 mu sym + dim lambda vec(I) vec(I)^T / dim with sym = (I + T) / 2,
    // i.e. 2 mu on sym - spherical and 2 mu + dim lambda on spherical.
    const double shear_eigenvalue = 2. * moduli.mu;
    const double bulk_eigenvalue  = 2. * moduli.mu + dim * moduli.lambda;
    const auto   spectral         = [&](const EigenvalueFilter filter) {
      Tensor<4, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              {
                const double sym =
                  0.5 * ((i == k && j == l) + (i == l && j == k));
                const double spherical = (i == j && k == l) / double(dim);
                result[i][j][k][l] =
                  filtered_eigenvalue(shear_eigenvalue, filter) *
                    (sym - spherical) +
                  filtered_eigenvalue(bulk_eigenvalue, filter) * spherical;
              }
      return result;
    };
    if (shear_eigenvalue >= 0. && bulk_eigenvalue >= 0.)
      projected_tangent = absolute_tangent = tangent;
    else
      {
        projected_tangent = spectral(EigenvalueFilter::clamp);
        absolute_tangent  = spectral(EigenvalueFilter::absolute);
      }
  }



  template <int dim>
  double
  LinearElastic<dim>::energy_density(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> eps = small_strain(F);
    return this->elastic_moduli.mu * (eps * eps) +
           0.5 * this->elastic_moduli.lambda * trace(eps) * trace(eps);
  }



  template <int dim>
  Tensor<2, dim>
  LinearElastic<dim>::first_piola_kirchhoff(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> eps = small_strain(F);
    return Tensor<2, dim>(2. * this->elastic_moduli.mu * eps +
                          this->elastic_moduli.lambda * trace(eps) *
                            unit_symmetric_tensor<dim>());
  }



  template <int dim>
  Tensor<4, dim>
  LinearElastic<dim>::first_piola_kirchhoff_derivative(
    const Tensor<2, dim> &) const
  {
    return tangent;
  }



  template <int dim>
  Tensor<4, dim>
  LinearElastic<dim>::filtered_first_piola_kirchhoff_derivative(
    const Tensor<2, dim> &,
    const EigenvalueFilter filter) const
  {
    switch (filter)
      {
        case EigenvalueFilter::none:
          return tangent;
        case EigenvalueFilter::clamp:
          return projected_tangent;
        case EigenvalueFilter::absolute:
          return absolute_tangent;
      }
    return projected_tangent;
  }



  template <int dim>
  std::string
  LinearElastic<dim>::name() const
  {
    return "linear elastic";
  }



  template class LinearElastic<2>;
  template class LinearElastic<3>;
} // namespace bfemp
