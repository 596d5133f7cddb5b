#include <bfemp/material/linear_elastic.h>

#include <deal.II/base/symmetric_tensor.h>

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
  std::string
  LinearElastic<dim>::name() const
  {
    return "linear elastic";
  }



  template class LinearElastic<2>;
  template class LinearElastic<3>;
} // namespace bfemp
