#ifndef bfemp_fem_simplex_element_h
#define bfemp_fem_simplex_element_h

#include <bfemp/material/material.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>

namespace bfemp
{
  /**
   * One linear simplex (a triangle in 2D, a tetrahedron in 3D) of the FEM
   * domain, BFEMP paper Section 3.1. With linear hat functions N_a the
   * deformation gradient is constant in the element and given by eq. 24,
   * @f[
   *   F_e(x) = T_e(x) B_e^{-1},
   * @f]
   * with the current basis T_e = [x_1 - x_0, ..., x_dim - x_0] and the rest
   * basis B_e = [X_1 - X_0, ..., X_dim - X_0] (edge vectors as columns).
   *
   * The element energy is E(x) = V_e psi(F_e(x)). Since F_e is linear in x,
   * dF_ij/dx_{a,k} = delta_ik gradN_a[j] with the constant rest-configuration
   * shape gradients gradN_a (the rows of B_e^{-T} for a = 1..dim, and
   * gradN_0 = -sum of the others). The chain rule then gives the gradient
   * and Hessian from P = dpsi/dF and dP/dF.
   *
   * The node vectors (gradient, Hessian rows and columns) are node-major:
   * entry a*dim + i belongs to component i of node a.
   */
  template <int dim>
  class SimplexElement
  {
  public:
    static constexpr unsigned int n_nodes = dim + 1;
    static constexpr unsigned int n_dofs  = n_nodes * dim;

    using NodePositions = std::array<Point<dim>, n_nodes>;

    /**
     * Stores B_e^{-1}, the rest volume and the shape gradients of the
     * element with rest node positions @p rest_positions. Throws if the
     * element is degenerate or inverted at rest (det B_e <= 0).
     */
    explicit SimplexElement(const NodePositions &rest_positions);

    /** F_e = T_e B_e^{-1} (eq. 24) at current node positions @p x. */
    Tensor<2, dim>
    deformation_gradient(const NodePositions &x) const;

    /** E = V_e psi(F_e). */
    double
    energy(const NodePositions &x, const Material<dim> &material) const;

    /**
     * dE/dx by the chain rule: dE/dx_a = V_e P(F_e) gradN_a, stored
     * node-major in a vector of size (dim+1)*dim.
     */
    Vector<double>
    gradient(const NodePositions &x, const Material<dim> &material) const;

    /** d2E/dx2 with the material tangent dP/dF at F_e(x). */
    FullMatrix<double>
    hessian(const NodePositions &x, const Material<dim> &material) const;

    /**
     * d2E/dx2 by the chain rule from a given tangent @p dP_dF
     * ((i,j,k,l) = dP_ij/dF_kl), e.g. a positive semi-definite projection:
     * H_{ai,bk} = V_e sum_{j,l} dP_ij/dF_kl gradN_a[j] gradN_b[l].
     * F is constant on the element, so the positions enter only through
     * the tangent.
     */
    FullMatrix<double>
    hessian(const Tensor<4, dim> &dP_dF) const;

    /** V_e, the rest area (2D) or volume (3D). */
    double
    rest_volume() const;

    /** Rest-configuration gradients gradN_a, a = 0..dim. */
    const std::array<Tensor<1, dim>, n_nodes> &
    shape_gradients() const;

  private:
    /** B_e^{-1}. */
    Tensor<2, dim> rest_basis_inverse;

    /** V_e = det B_e / dim!. */
    double volume;

    std::array<Tensor<1, dim>, n_nodes> shape_grads;
  };
} // namespace bfemp

#endif
