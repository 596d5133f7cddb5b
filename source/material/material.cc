#include <bfemp/material/fixed_corotated.h>
#include <bfemp/material/linear_elastic.h>
#include <bfemp/material/material.h>
#include <bfemp/material/neo_hookean.h>
#include <bfemp/material/tangent_projection.h>

#include <deal.II/base/exceptions.h>

namespace bfemp
{
  ElasticModuli
  ElasticModuli::from_young_poisson(const double youngs_modulus,
                                    const double poisson_ratio)
  {
    ElasticModuli moduli;
    moduli.mu     = youngs_modulus / (2. * (1. + poisson_ratio));
    moduli.lambda = youngs_modulus * poisson_ratio /
                    ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return moduli;
  }



  template <int dim>
  Material<dim>::Material(const ElasticModuli &moduli)
    : elastic_moduli(moduli)
  {}



  template <int dim>
  Tensor<4, dim>
  Material<dim>::tangent(const Tensor<2, dim> &F, const bool projected) const
  {
    return tangent(F,
                   projected ? EigenvalueFilter::clamp
                             : EigenvalueFilter::none);
  }



  template <int dim>
  Tensor<4, dim>
  Material<dim>::tangent(const Tensor<2, dim>  &F,
                         const EigenvalueFilter filter) const
  {
    return filter == EigenvalueFilter::none
             ? first_piola_kirchhoff_derivative(F)
             : filtered_first_piola_kirchhoff_derivative(F, filter);
  }



  template <int dim>
  Tensor<4, dim>
  Material<dim>::projected_first_piola_kirchhoff_derivative(
    const Tensor<2, dim> &F) const
  {
    return filtered_first_piola_kirchhoff_derivative(F,
                                                     EigenvalueFilter::clamp);
  }



  template <int dim>
  Tensor<4, dim>
  Material<dim>::filtered_first_piola_kirchhoff_derivative(
    const Tensor<2, dim>  &F,
    const EigenvalueFilter filter) const
  {
    return TangentProjection<dim>(first_piola_kirchhoff_derivative(F))
      .filtered(filter);
  }



  template <int dim>
  Tensor<2, dim>
  Material<dim>::cauchy_stress(const Tensor<2, dim> &F) const
  {
    return first_piola_kirchhoff(F) * transpose(F) / determinant(F);
  }



  template <int dim>
  double
  Material<dim>::p_wave_speed(const double density) const
  {
    return std::sqrt((elastic_moduli.lambda + 2. * elastic_moduli.mu) /
                     density);
  }



  template <int dim>
  const ElasticModuli &
  Material<dim>::moduli() const
  {
    return elastic_moduli;
  }



  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &model, const ElasticModuli &moduli)
  {
    if (model == "neo-Hookean")
      return std::make_unique<NeoHookean<dim>>(moduli);
    if (model == "linear elastic")
      return std::make_unique<LinearElastic<dim>>(moduli);
    if (model == "fixed corotated")
      return std::make_unique<FixedCorotated<dim>>(moduli);
    AssertThrow(false,
                ExcMessage("material model '" + model +
                           "' is unknown; allowed: neo-Hookean, linear "
                           "elastic, fixed corotated"));
    return nullptr;
  }



  template class Material<2>;
  template class Material<3>;
  template std::unique_ptr<Material<2>>
  create_material<2>(const std::string &, const ElasticModuli &);
  template std::unique_ptr<Material<3>>
  create_material<3>(const std::string &, const ElasticModuli &);
} // namespace bfemp
