#ifndef bfemp_material_material_h
#define bfemp_material_material_h

#include <bfemp/material/tangent_projection.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <memory>
#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * Lamé parameters of an isotropic elastic solid. In 2D the plane-strain
   * relations are used, as in the BFEMP paper (its Hertz comparison, Section
   * 6.3, uses E / (1 - nu^2)).
   */
  struct ElasticModuli
  {
    double lambda = 0.;
    double mu     = 0.;

    /** From Young's modulus E [Pa] and Poisson's ratio nu [-]. */
    static ElasticModuli
    from_young_poisson(const double youngs_modulus, const double poisson_ratio);
  };

  /**
   * An isotropic hyperelastic energy density psi(F) per unit rest volume, its
   * first Piola-Kirchhoff stress P = dpsi/dF and the fourth-order tangent
   * dP/dF. Every consumer (explicit MPM forces, the implicit incremental
   * potential, FEM elements) goes through this interface, so a material is
   * written once for all integrators.
   */
  template <int dim>
  class Material
  {
  public:
    explicit Material(const ElasticModuli &moduli);

    virtual ~Material() = default;

    /** psi(F) [J/m^dim]. */
    virtual double
    energy_density(const Tensor<2, dim> &F) const = 0;

    /** P(F) = dpsi/dF [Pa]. */
    virtual Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const = 0;

    /** dP/dF with index order (i, j, k, l) = dP_ij / dF_kl. */
    virtual Tensor<4, dim>
    first_piola_kirchhoff_derivative(const Tensor<2, dim> &F) const = 0;

    /**
     * The positive semi-definite projection of dP/dF at F (projected
     * Newton, BFEMP Section 5): the nearest PSD tensor in the Frobenius
     * norm: filtered_first_piola_kirchhoff_derivative() with
     * EigenvalueFilter::clamp.
     */
    Tensor<4, dim>
    projected_first_piola_kirchhoff_derivative(const Tensor<2, dim> &F) const;

    /**
     * dP/dF at F with its negative eigenvalues replaced as @p filter says
     * (clamp: projected_first_piola_kirchhoff_derivative(); absolute: their
     * absolute values). The default eigen-decomposes dP/dF numerically
     * (TangentProjection); materials with a known eigen-system override it.
     */
    virtual Tensor<4, dim>
    filtered_first_piola_kirchhoff_derivative(
      const Tensor<2, dim>  &F,
      const EigenvalueFilter filter) const;

    /**
     * dP/dF at F, or its positive semi-definite projection if @p projected:
     * what the Hessian of the kind an energy term assembles needs.
     */
    Tensor<4, dim>
    tangent(const Tensor<2, dim> &F, const bool projected) const;

    /** dP/dF at F after @p filter (none: dP/dF itself). */
    Tensor<4, dim>
    tangent(const Tensor<2, dim> &F, const EigenvalueFilter filter) const;

    /**
     * dim (2 mu + |lambda|) [Pa]: the size of the terms an energy density
     * near F = I is the small difference of, for round-off estimates.
     */
    double
    energy_scale() const
    {
      return dim * (2. * elastic_moduli.mu + std::abs(elastic_moduli.lambda));
    }

    /** Name used in messages and output. */
    virtual std::string
    name() const = 0;

    /** Cauchy stress sigma = P F^T / det F. */
    Tensor<2, dim>
    cauchy_stress(const Tensor<2, dim> &F) const;

    /**
     * Small-strain P-wave speed sqrt((lambda + 2 mu) / rho) [m/s], the signal
     * speed the explicit CFL condition is built on.
     */
    double
    p_wave_speed(const double density) const;

    const ElasticModuli &
    moduli() const;

  protected:
    ElasticModuli elastic_moduli;
  };

  /**
   * The von Mises equivalent stress sqrt(3/2 s:s) of the deviator s of
   * @p sigma. In 2D the out-of-plane stress is not tracked and the in-plane
   * deviator is used, consistently across runs and outputs.
   */
  template <int dim>
  double
  von_mises_stress(const Tensor<2, dim> &sigma)
  {
    const Tensor<2, dim> deviator =
      sigma - trace(sigma) / dim * Tensor<2, dim>(unit_symmetric_tensor<dim>());
    return std::sqrt(1.5 * scalar_product(deviator, deviator));
  }

  /**
   * Creates the material named by the prm entry `material/model`:
   * "neo-Hookean", "linear elastic" or "fixed corotated".
   */
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &model, const ElasticModuli &moduli);
} // namespace bfemp

#endif
