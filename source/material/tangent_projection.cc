#include <bfemp/material/tangent_projection.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bfemp
{
  template <int dim>
  TangentProjection<dim>::TangentProjection(const Tensor<4, dim> &tangent)
  {
    // (i, j) -> row i * dim + j; symmetrise to remove round-off asymmetry.
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = 0; c < n; ++c)
        {
          a[r][c] = 0.5 * (tangent[r / dim][r % dim][c / dim][c % dim] +
                           tangent[c / dim][c % dim][r / dim][r % dim]);
          q[r][c] = (r == c);
        }
    diagonalize();
    sort_eigenpairs();
  }



  template <int dim>
  void
  TangentProjection<dim>::diagonalize()
  {
    // Cyclic Jacobi: rotate away each off-diagonal entry in turn until they
    // are negligible against the diagonal; converges quadratically.
    for (unsigned int sweep = 0; sweep < 50; ++sweep)
      {
        double off = 0., scale = 0.;
        for (unsigned int r = 0; r < n; ++r)
          {
            scale += a[r][r] * a[r][r];
            for (unsigned int c = r + 1; c < n; ++c)
              off += a[r][c] * a[r][c];
          }
        if (off <= 1e-30 * scale || off == 0.)
          break;

        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int s = p + 1; s < n; ++s)
            {
              if (a[p][s] == 0.)
                continue;
              const double theta = (a[s][s] - a[p][p]) / (2. * a[p][s]);
              const double t =
                (theta >= 0. ? 1. : -1.) /
                (std::abs(theta) + std::sqrt(theta * theta + 1.));
              const double cos = 1. / std::sqrt(t * t + 1.), sin = t * cos;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double akp = a[k][p], aks = a[k][s];
                  a[k][p] = cos * akp - sin * aks;
                  a[k][s] = sin * akp + cos * aks;
                }
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double apk = a[p][k], ask = a[s][k];
                  a[p][k] = cos * apk - sin * ask;
                  a[s][k] = sin * apk + cos * ask;
                }
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double qkp = q[k][p], qks = q[k][s];
                  q[k][p] = cos * qkp - sin * qks;
                  q[k][s] = sin * qkp + cos * qks;
                }
            }
      }
  }



  template <int dim>
  void
  TangentProjection<dim>::sort_eigenpairs()
  {
    std::array<unsigned int, n> order;
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](unsigned int x, unsigned int y) {
      return a[x][x] < a[y][y];
    });
    double sorted[n][n];
    for (unsigned int m = 0; m < n; ++m)
      {
        lambda[m] = a[order[m]][order[m]];
        for (unsigned int k = 0; k < n; ++k)
          sorted[k][m] = q[k][order[m]];
      }
    std::copy(&sorted[0][0], &sorted[0][0] + n * n, &q[0][0]);
  }



  template <int dim>
  Tensor<4, dim>
  TangentProjection<dim>::projected() const
  {
    return filtered(EigenvalueFilter::clamp);
  }



  template <int dim>
  Tensor<4, dim>
  TangentProjection<dim>::filtered(const EigenvalueFilter filter) const
  {
    Tensor<4, dim> result;
    for (unsigned int m = 0; m < n; ++m)
      {
        const double weight = filtered_eigenvalue(lambda[m], filter);
        if (weight != 0.)
          for (unsigned int r = 0; r < n; ++r)
            for (unsigned int c = 0; c < n; ++c)
              result[r / dim][r % dim][c / dim][c % dim] +=
                weight * q[r][m] * q[c][m];
      }
    return result;
  }



  template <int dim>
  const std::array<double, TangentProjection<dim>::n> &
  TangentProjection<dim>::eigenvalues() const
  {
    return lambda;
  }



  template <int dim>
  Tensor<4, dim>
  project_to_positive_semidefinite(const Tensor<4, dim> &tangent)
  {
    return TangentProjection<dim>(tangent).projected();
  }



  template class TangentProjection<2>;
  template class TangentProjection<3>;
  template Tensor<4, 2>
  project_to_positive_semidefinite<2>(const Tensor<4, 2> &);
  template Tensor<4, 3>
  project_to_positive_semidefinite<3>(const Tensor<4, 3> &);
} // namespace bfemp
