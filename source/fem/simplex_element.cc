#include <bfemp/fem/simplex_element.h>

#include <deal.II/base/exceptions.h>

namespace bfemp
{
  namespace
  {
    /** [p_1 - p_0, ..., p_dim - p_0] with the edge vectors as columns. */
    template <int dim>
    Tensor<2, dim>
    edge_basis(const typename SimplexElement<dim>::NodePositions &p)
    {
      Tensor<2, dim> basis;
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int r = 0; r < dim; ++r)
          basis[r][c] = p[c + 1][r] - p[0][r];
      return basis;
    }



    constexpr double
    factorial(const int n)
    {
      return n <= 1 ? 1. : n * factorial(n - 1);
    }
  } // namespace



  template <int dim>
  SimplexElement<dim>::SimplexElement(const NodePositions &rest_positions)
  {
    const Tensor<2, dim> B     = edge_basis<dim>(rest_positions);
    const double         det_B = determinant(B);
    AssertThrow(det_B > 0.,
                ExcMessage("SimplexElement: element has non-positive rest "
                           "volume (det B_e = " +
                           std::to_string(det_B) +
                           "); it is degenerate or inverted"));

    rest_basis_inverse = invert(B);
    volume             = det_B / factorial(dim);

    // gradN_a for a >= 1 is row a-1 of B^-1 (column of B^-T).
    shape_grads[0] = Tensor<1, dim>();
    for (unsigned int a = 1; a < n_nodes; ++a)
      {
        shape_grads[a] = rest_basis_inverse[a - 1];
        shape_grads[0] -= shape_grads[a];
      }
  }



  template <int dim>
  Tensor<2, dim>
  SimplexElement<dim>::deformation_gradient(const NodePositions &x) const
  {
    return edge_basis<dim>(x) * rest_basis_inverse;
  }



  template <int dim>
  double
  SimplexElement<dim>::energy(const NodePositions &x,
                              const Material<dim> &material) const
  {
    return volume * material.energy_density(deformation_gradient(x));
  }



  template <int dim>
  Vector<double>
  SimplexElement<dim>::gradient(const NodePositions &x,
                                const Material<dim> &material) const
  {
    const Tensor<2, dim> P =
      material.first_piola_kirchhoff(deformation_gradient(x));

    Vector<double> g(n_dofs);
    for (unsigned int a = 0; a < n_nodes; ++a)
      {
        const Tensor<1, dim> force = volume * P * shape_grads[a];
        for (unsigned int i = 0; i < dim; ++i)
          g[a * dim + i] = force[i];
      }
    return g;
  }



  template <int dim>
  FullMatrix<double>
  SimplexElement<dim>::hessian(const NodePositions &x,
                               const Material<dim> &material) const
  {
    return hessian(
      material.first_piola_kirchhoff_derivative(deformation_gradient(x)));
  }



  template <int dim>
  FullMatrix<double>
  SimplexElement<dim>::hessian(const Tensor<4, dim> &dP_dF) const
  {
    FullMatrix<double> H(n_dofs, n_dofs);
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int b = 0; b < n_nodes; ++b)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            {
              double sum = 0.;
              for (unsigned int j = 0; j < dim; ++j)
                for (unsigned int l = 0; l < dim; ++l)
                  sum +=
                    dP_dF[i][j][k][l] * shape_grads[a][j] * shape_grads[b][l];
              H(a * dim + i, b * dim + k) = volume * sum;
            }
    return H;
  }



  template <int dim>
  double
  SimplexElement<dim>::rest_volume() const
  {
    return volume;
  }



  template <int dim>
  const std::array<Tensor<1, dim>, SimplexElement<dim>::n_nodes> &
  SimplexElement<dim>::shape_gradients() const
  {
    return shape_grads;
  }



  template class SimplexElement<2>;
  template class SimplexElement<3>;
} // namespace bfemp
