#include <bfemp/solver/positive_semidefinite.h>

#include <cmath>
#include <vector>

namespace bfemp
{
  void
  project_to_positive_semidefinite(FullMatrix<double> &matrix)
  {
    filter_eigenvalues(matrix, EigenvalueFilter::clamp);
  }



  void
  filter_eigenvalues(FullMatrix<double> &matrix, const EigenvalueFilter filter)
  {
    if (filter == EigenvalueFilter::none)
      return;
    // Cyclic Jacobi: robust for the small, often rank-deficient and
    // clustered matrices of contact stencils (LAPACK's bisection-based
    // syevx failed on some), deterministic, and O(n^3) per sweep for n of
    // at most a few dozen.
    const unsigned int n = matrix.m();
    if (n == 0)
      return;
    FullMatrix<double> a(n, n), q(n, n);
    double             scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          a(i, j) = 0.5 * (matrix(i, j) + matrix(j, i));
          scale += a(i, j) * a(i, j);
        }
    if (scale == 0.)
      return;
    for (unsigned int i = 0; i < n; ++i)
      q(i, i) = 1.;

    for (unsigned int sweep = 0; sweep < 100; ++sweep)
      {
        double off = 0.;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i + 1; j < n; ++j)
            off += a(i, j) * a(i, j);
        if (off <= 1e-32 * scale)
          break;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int r = p + 1; r < n; ++r)
            {
              if (a(p, r) == 0.)
                continue;
              const double theta = (a(r, r) - a(p, p)) / (2. * a(p, r));
              const double t =
                (theta >= 0. ? 1. : -1.) /
                (std::abs(theta) + std::sqrt(theta * theta + 1.));
              const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double akp = a(k, p), akr = a(k, r);
                  a(k, p) = c * akp - s * akr;
                  a(k, r) = s * akp + c * akr;
                }
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double apk = a(p, k), ark = a(r, k);
                  a(p, k) = c * apk - s * ark;
                  a(r, k) = s * apk + c * ark;
                }
              for (unsigned int k = 0; k < n; ++k)
                {
                  const double qkp = q(k, p), qkr = q(k, r);
                  q(k, p) = c * qkp - s * qkr;
                  q(k, r) = s * qkp + c * qkr;
                }
            }
      }

    matrix = 0.;
    for (unsigned int k = 0; k < n; ++k)
      if (const double weight = filtered_eigenvalue(a(k, k), filter);
          weight > 0.)
        for (unsigned int i = 0; i < n; ++i)
          {
            const double vi = weight * q(i, k);
            for (unsigned int j = 0; j < n; ++j)
              matrix(i, j) += vi * q(j, k);
          }
  }
} // namespace bfemp
