#include <bfemp/base/input_error.h>
#include <bfemp/cmpm/boundary_interior_map.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/lapack_full_matrix.h>

namespace bfemp
{
  namespace
  {
    /** (dP/dF)_{abce} = mu (delta_ac delta_be + delta_ae delta_bc) +
     *  lambda delta_ab delta_ce: small-strain isotropic elasticity. */
    template <int dim>
    Tensor<4, dim>
    isotropic_tangent(const double lambda, const double mu)
    {
      Tensor<4, dim> A;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int e = 0; e < dim; ++e)
              A[a][b][c][e] = mu * ((a == c && b == e) + (a == e && b == c)) +
                              lambda * (a == b && c == e);
      return A;
    }

    /** A stiffness scale of a tangent: sum_ab A_abab / (dim (dim + 1)),
     *  which is mu + lambda / (dim + 1) for isotropic elasticity. */
    template <int dim>
    double
    stiffness_scale(const Tensor<4, dim> &A)
    {
      double sum = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          sum += A[a][b][a][b];
      return sum / (dim * (dim + 1.));
    }
  } // namespace



  template <int dim>
  BoundaryInteriorMap<dim>::BoundaryInteriorMap(
    const CoarseGrid<dim>        &grid,
    const CoarseBoundaryMap<dim> &psi)
    : grid(grid)
    , psi(psi)
  {
    const unsigned int n_i = grid.n_interior_fine();
    const unsigned int r   = grid.n_local_nodes();
    fictitious_K_i.reinit(dim * n_i, dim * n_i);
    fictitious_R.reinit(dim * n_i, dim * r);

    // 2 Gauss points per direction integrate grad B_k . grad B_m (piecewise
    // polynomial of degree <= 2 per direction in each knot span) exactly.
    const QGauss<dim>  gauss(2);
    const double       s     = grid.knot_span();
    const unsigned int spans = grid.n_fine_1d() - 2;
    unsigned int       total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= spans;
    LocalQuadraturePoint<dim> point;
    point.deformation_gradient = unit_symmetric_tensor<dim>();
    point.tangent              = isotropic_tangent<dim>(0., 1.);
    for (unsigned int span = 0; span < total; ++span)
      {
        Point<dim>   corner;
        unsigned int rest = span;
        for (unsigned int d = 0; d < dim; ++d)
          {
            corner[d] = (rest % spans) * s;
            rest /= spans;
          }
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            point.position = corner + s * gauss.point(q);
            point.weight   = gauss.weight(q) * std::pow(s, dim);
            add_point(point, fictitious_K_i, fictitious_R);
          }
      }
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::add_point(const LocalQuadraturePoint<dim> &point,
                                      FullMatrix<double>              &K_i,
                                      FullMatrix<double>              &R) const
  {
    constexpr unsigned int n_stencil = CoarseGrid<dim>::n_stencil;
    typename CoarseGrid<dim>::FineStencil stencil;
    grid.fine_stencil(point.position, stencil);
    const unsigned int r = grid.n_local_nodes();

    // g_k = F^T grad B_k: dF/du_k of BFEMP eq. 25 in displacement form
    const Tensor<2, dim> F_T = transpose(point.deformation_gradient);
    Tensor<1, dim>       g[n_stencil];
    for (unsigned int q = 0; q < n_stencil; ++q)
      g[q] = F_T * stencil.gradient[q];

    // The boundary part mapped to the coarse nodes: G_I = sum_l g_l psi_lI.
    std::vector<Tensor<1, dim>> G(r);
    std::vector<bool>           touched(r, false);
    for (unsigned int q = 0; q < n_stencil; ++q)
      for (const auto &[I, weight] : psi.row(stencil.node[q]))
        {
          G[I] += weight * g[q];
          touched[I] = true;
        }

    for (unsigned int q = 0; q < n_stencil; ++q)
      {
        const int i = grid.interior_index(stencil.node[q]);
        if (i < 0)
          continue;
        // T[a][c][e] = w sum_b A_abce g_kb: row block (k, a) of K
        Tensor<3, dim> T;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int e = 0; e < dim; ++e)
                T[a][c][e] +=
                  point.weight * point.tangent[a][b][c][e] * g[q][b];

        for (unsigned int m = 0; m < n_stencil; ++m)
          {
            const int j = grid.interior_index(stencil.node[m]);
            if (j < 0)
              continue;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                K_i(dim * i + a, dim * j + c) += T[a][c] * g[m];
          }
        for (unsigned int I = 0; I < r; ++I)
          if (touched[I])
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                R(dim * i + a, dim * I + c) += T[a][c] * G[I];
      }
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::compute(
    const std::vector<LocalQuadraturePoint<dim>> &points,
    std::vector<Tensor<2, dim>>                  &control) const
  {
    const unsigned int n_i = grid.n_interior_fine();
    const unsigned int r   = grid.n_local_nodes();
    FullMatrix<double> K_i(dim * n_i, dim * n_i), R(dim * n_i, dim * r);

    double volume = 0., stiffness = 0.;
    for (const LocalQuadraturePoint<dim> &point : points)
      {
        add_point(point, K_i, R);
        volume += point.weight;
        stiffness += point.weight * stiffness_scale(point.tangent);
      }
    // the fictitious material: eps times the mean particle stiffness, or
    // alone (unit stiffness) in an element without particles
    const double fictitious =
      volume > 0. ? grid.parameters().empty_span_stiffness * stiffness / volume
                  : 1.;
    K_i.add(fictitious, fictitious_K_i);
    R.add(fictitious, fictitious_R);

    // eq. 30 for every coarse column at once: K_i X = -K_ib Psi_b
    LAPACKFullMatrix<double> K(dim * n_i, dim * n_i);
    K = K_i;
    K.set_property(LAPACKSupport::symmetric);
    try
      {
        K.compute_cholesky_factorization();
      }
    catch (...)
      {
        throw SimulationError(
          "cmpm: the local stiffness K_i of a coarse element (seed 002 eq. "
          "30) is not positive definite; knot spans without particles need "
          "cmpm/empty span stiffness > 0, an indefinite material tangent "
          "cannot be condensed");
      }
    LAPACKFullMatrix<double> X(dim * n_i, dim * r);
    X = R;
    K.solve(X);

    control.resize(n_i * r);
    for (unsigned int i = 0; i < n_i; ++i)
      for (unsigned int I = 0; I < r; ++I)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            control[i * r + I][a][c] = -X(dim * i + a, dim * I + c);
  }



  template class BoundaryInteriorMap<2>;
  template class BoundaryInteriorMap<3>;
} // namespace bfemp
