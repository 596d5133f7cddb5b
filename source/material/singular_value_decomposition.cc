#include <bfemp/material/singular_value_decomposition.h>

#include <cmath>
#include <limits>
#include <utility>

namespace bfemp
{
  namespace
  {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();

    /**
     * tan(theta) of the Jacobi rotation [c s; -s c] that diagonalises the
     * symmetric 2 x 2 matrix [alpha gamma; gamma beta] (gamma != 0): the root
     * of t^2 + 2 zeta t - 1 = 0 with |t| <= 1, zeta = (beta - alpha) /
     * (2 gamma), written without cancellation (Golub, Van Loan, Algorithm
     * 8.5.1); for huge |zeta| (nearly diagonal) t = 1 / (2 zeta).
     */
    inline double
    jacobi_tangent(const double alpha, const double beta, const double gamma)
    {
      const double zeta = (beta - alpha) / (2. * gamma);
      if (std::abs(zeta) > 1e150)
        return 0.5 / zeta;
      return (zeta >= 0. ? 1. : -1.) /
             (std::abs(zeta) + std::sqrt(1. + zeta * zeta));
    }



    /**
     * Cyclic Jacobi for the symmetric dim x dim matrix @p a: on return a is
     * diagonal (its eigenvalues) and the columns of @p q are the
     * eigenvectors. An off-diagonal entry is treated as zero once it is below
     * round-off of its two diagonal entries, which keeps the small
     * eigenvalues of a strongly graded matrix (compression, J -> 0) accurate.
     */
    template <int dim>
    void
    symmetric_eigen_decomposition(double (&a)[dim][dim], double (&q)[dim][dim])
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          q[i][j] = (i == j);
      for (unsigned int sweep = 0; sweep < 30; ++sweep)
        {
          bool rotated = false;
          for (unsigned int p = 0; p < dim; ++p)
            for (unsigned int s = p + 1; s < dim; ++s)
              {
                if (!(std::abs(a[p][s]) >
                      0.5 * epsilon * (std::abs(a[p][p]) + std::abs(a[s][s]))))
                  continue;
                rotated          = true;
                const double t   = jacobi_tangent(a[p][p], a[s][s], a[p][s]);
                const double cos = 1. / std::sqrt(1. + t * t);
                const double sin = t * cos;
                for (unsigned int k = 0; k < dim; ++k)
                  {
                    const double akp = a[k][p], aks = a[k][s];
                    a[k][p] = cos * akp - sin * aks;
                    a[k][s] = sin * akp + cos * aks;
                  }
                for (unsigned int k = 0; k < dim; ++k)
                  {
                    const double apk = a[p][k], ask = a[s][k];
                    a[p][k] = cos * apk - sin * ask;
                    a[s][k] = sin * apk + cos * ask;
                  }
                for (unsigned int k = 0; k < dim; ++k)
                  {
                    const double qkp = q[k][p], qks = q[k][s];
                    q[k][p] = cos * qkp - sin * qks;
                    q[k][s] = sin * qkp + cos * qks;
                  }
              }
          if (!rotated)
            break;
        }
    }



    /**
     * The Cholesky factor L (lower triangular, H = L L^T) of the symmetric
     * dim x dim matrix @p h; false if a pivot is not positive, i.e. h is not
     * positive definite (to round-off).
     */
    template <int dim>
    bool
    cholesky_factor(const double (&h)[dim][dim], double (&l)[dim][dim])
    {
      for (unsigned int j = 0; j < dim; ++j)
        {
          double pivot = h[j][j];
          for (unsigned int k = 0; k < j; ++k)
            pivot -= l[j][k] * l[j][k];
          if (!(pivot > 0.))
            return false;
          l[j][j] = std::sqrt(pivot);
          for (unsigned int i = j + 1; i < dim; ++i)
            {
              double entry = h[i][j];
              for (unsigned int k = 0; k < j; ++k)
                entry -= l[i][k] * l[j][k];
              l[i][j] = entry / l[j][j];
              l[j][i] = 0.;
            }
        }
      return true;
    }



    template <int dim>
    void
    swap_columns(Tensor<2, dim> &A, const unsigned int p, const unsigned int s)
    {
      for (unsigned int k = 0; k < dim; ++k)
        std::swap(A[k][p], A[k][s]);
    }



    /**
     * A unit vector orthogonal to the unit vector @p u: Gram-Schmidt on the
     * coordinate axis least aligned with u, which is never close to u.
     */
    Tensor<1, 3>
    unit_normal(const Tensor<1, 3> &u)
    {
      unsigned int k = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(u[d]) < std::abs(u[k]))
          k = d;
      Tensor<1, 3> w = -u[k] * u;
      w[k] += 1.;
      return w / w.norm();
    }
  } // namespace



  template <int dim>
  SingularValueDecomposition<dim>
  signed_singular_value_decomposition(const Tensor<2, dim> &F)
  {
    SingularValueDecomposition<dim> svd;
    Tensor<2, dim>                  G = F; // becomes F V = U diag(sigma)
    Tensor<2, dim>                  V = unit_symmetric_tensor<dim>();

    // One-sided Jacobi: rotate columns p, s of G (and of V) so that they
    // become orthogonal; stop when every pair is orthogonal to round-off.
    for (unsigned int sweep = 0; sweep < 30; ++sweep)
      {
        bool rotated = false;
        for (unsigned int p = 0; p < dim; ++p)
          for (unsigned int s = p + 1; s < dim; ++s)
            {
              double alpha = 0., beta = 0., gamma = 0.;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  alpha += G[k][p] * G[k][p];
                  beta += G[k][s] * G[k][s];
                  gamma += G[k][p] * G[k][s];
                }
              // |gamma| <= epsilon sqrt(alpha beta), without a square root.
              if (!(gamma * gamma > epsilon * epsilon * alpha * beta))
                continue;
              rotated          = true;
              const double t   = jacobi_tangent(alpha, beta, gamma);
              const double cos = 1. / std::sqrt(1. + t * t);
              const double sin = t * cos;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  const double gkp = G[k][p], gks = G[k][s];
                  G[k][p]          = cos * gkp - sin * gks;
                  G[k][s]          = sin * gkp + cos * gks;
                  const double vkp = V[k][p], vks = V[k][s];
                  V[k][p] = cos * vkp - sin * vks;
                  V[k][s] = sin * vkp + cos * vks;
                }
            }
        if (!rotated)
          break;
      }

    // Order by decreasing column norm (the magnitudes of the singular
    // values), then make V a proper rotation; which column is flipped does
    // not matter, the sign is recovered below from u_last . F v_last.
    double norms[dim];
    for (unsigned int i = 0; i < dim; ++i)
      {
        double norm_squared = 0.;
        for (unsigned int k = 0; k < dim; ++k)
          norm_squared += G[k][i] * G[k][i];
        norms[i] = std::sqrt(norm_squared);
      }
    for (unsigned int i = 1; i < dim; ++i)
      for (unsigned int j = i; j > 0 && norms[j] > norms[j - 1]; --j)
        {
          std::swap(norms[j], norms[j - 1]);
          swap_columns(G, j, j - 1);
          swap_columns(V, j, j - 1);
        }
    if (determinant(V) < 0.)
      for (unsigned int k = 0; k < dim; ++k)
        {
          V[k][dim - 1] = -V[k][dim - 1];
          G[k][dim - 1] = -G[k][dim - 1];
        }

    Tensor<1, dim> u[dim];
    if (norms[0] > 0.)
      for (unsigned int k = 0; k < dim; ++k)
        u[0][k] = G[k][0] / norms[0];
    else
      u[0][0] = 1.; // F = 0: any rotations do

    if constexpr (dim == 2)
      {
        u[1][0] = -u[0][1];
        u[1][1] = u[0][0];
      }
    else
      {
        // Gram-Schmidt removes the O(epsilon) overlap that the Jacobi
        // tolerance leaves; a vanishing second column (rank <= 1) is
        // completed by any unit normal.
        Tensor<1, dim> w;
        for (unsigned int k = 0; k < dim; ++k)
          w[k] = G[k][1];
        w -= (u[0] * w) * u[0];
        const double w_norm = w.norm();
        u[1]                = (w_norm > 0. ? w / w_norm : unit_normal(u[0]));
        u[2]                = cross_product_3d(u[0], u[1]);
      }

    svd.sigma[0] = norms[0];
    for (unsigned int i = 1; i < dim; ++i)
      {
        double projection = 0.;
        for (unsigned int k = 0; k < dim; ++k)
          projection += u[i][k] * G[k][i];
        // For repeated singular values the projection can exceed the
        // previous one by an ulp; keep the documented ordering exact.
        svd.sigma[i] = std::abs(projection) > svd.sigma[i - 1]
                         ? std::copysign(svd.sigma[i - 1], projection)
                         : projection;
      }
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        svd.U[k][i] = u[i][k];
    svd.V = V;
    return svd;
  }



  template <int dim>
  Tensor<4, dim>
  project_isotropic_tangent(
    const SingularValueDecomposition<dim> &svd,
    const SymmetricTensor<2, dim>         &singular_value_hessian,
    const SymmetricTensor<2, dim>         &twist_eigenvalues,
    const SymmetricTensor<2, dim>         &flip_eigenvalues,
    const EigenvalueFilter                 filter)
  {
    // The dim^2 x dim^2 matrix with row (i, j) -> i * dim + j, as in
    // TangentProjection; only its upper triangle is accumulated, and the
    // lower one is mirrored, so the result is exactly symmetric.
    constexpr unsigned int n            = dim * dim;
    double                 matrix[n][n] = {};
    double                 q[n];
    const auto             add_mode = [&](const double weight) {
      for (unsigned int r = 0; r < n; ++r)
        {
          const double weighted = weight * q[r];
          for (unsigned int c = r; c < n; ++c)
            matrix[r][c] += weighted * q[c];
        }
    };
    const Tensor<2, dim> &U = svd.U;
    const Tensor<2, dim> &V = svd.V;

    // The scaling block sum_ij H+_ij D_i D_j^T, H+ the PSD projection of
    // the singular-value Hessian H, written as sum_m w_m q_m q_m^T with
    // q_m = sum_i c_im D_i. If H is positive definite (the common case)
    // H+ = H = L L^T, and the Cholesky columns (c = L, w = 1) are much
    // cheaper than eigenvectors; otherwise c holds the eigenvectors of H
    // and w its eigenvalues, clamped below.
    double hessian[dim][dim], c[dim][dim], w[dim];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        hessian[i][j] = singular_value_hessian[i][j];
    if (cholesky_factor<dim>(hessian, c))
      for (unsigned int m = 0; m < dim; ++m)
        w[m] = 1.;
    else
      {
        symmetric_eigen_decomposition<dim>(hessian, c);
        for (unsigned int m = 0; m < dim; ++m)
          w[m] = filtered_eigenvalue(hessian[m][m], filter);
      }
    for (unsigned int m = 0; m < dim; ++m)
      if (w[m] > 0.)
        {
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                double entry = 0.;
                for (unsigned int i = 0; i < dim; ++i)
                  entry += c[i][m] * U[a][i] * V[b][i];
                q[a * dim + b] = entry;
              }
          add_mode(w[m]);
        }

    // Twist and flip modes (u_i v_j^T -/+ u_j v_i^T) / sqrt(2); the 1/2 of
    // q q^T goes into the weight.
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i + 1; j < dim; ++j)
        {
          const double twist =
            filtered_eigenvalue(twist_eigenvalues[i][j], filter);
          const double flip =
            filtered_eigenvalue(flip_eigenvalues[i][j], filter);
          if (twist > 0.)
            {
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  q[a * dim + b] = U[a][i] * V[b][j] - U[a][j] * V[b][i];
              add_mode(0.5 * twist);
            }
          if (flip > 0.)
            {
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  q[a * dim + b] = U[a][i] * V[b][j] + U[a][j] * V[b][i];
              add_mode(0.5 * flip);
            }
        }

    Tensor<4, dim> result;
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = r; c < n; ++c)
        {
          result[r / dim][r % dim][c / dim][c % dim] = matrix[r][c];
          result[c / dim][c % dim][r / dim][r % dim] = matrix[r][c];
        }
    return result;
  }



  template SingularValueDecomposition<2>
  signed_singular_value_decomposition<2>(const Tensor<2, 2> &);
  template SingularValueDecomposition<3>
  signed_singular_value_decomposition<3>(const Tensor<2, 3> &);
  template Tensor<4, 2>
  project_isotropic_tangent<2>(const SingularValueDecomposition<2> &,
                               const SymmetricTensor<2, 2> &,
                               const SymmetricTensor<2, 2> &,
                               const SymmetricTensor<2, 2> &,
                               const EigenvalueFilter);
  template Tensor<4, 3>
  project_isotropic_tangent<3>(const SingularValueDecomposition<3> &,
                               const SymmetricTensor<2, 3> &,
                               const SymmetricTensor<2, 3> &,
                               const SymmetricTensor<2, 3> &,
                               const EigenvalueFilter);
} // namespace bfemp
