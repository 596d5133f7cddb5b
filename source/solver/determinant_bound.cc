#include <bfemp/solver/determinant_bound.h>

#include <cmath>
#include <limits>

namespace bfemp
{
  namespace
  {
    /**
     * The cofactor matrix from 2x2 minors (the cyclic indices carry the
     * signs), and in @p magnitudes the sums of the absolute values of the
     * two products of each minor. deal.II's cofactor() is det(A) A^{-T},
     * which fails for the singular B a search direction often has.
     */
    Tensor<2, 3>
    cofactor_matrix(const Tensor<2, 3> &A, Tensor<2, 3> &magnitudes)
    {
      Tensor<2, 3> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const unsigned int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            const unsigned int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            C[i][j] = A[i1][j1] * A[i2][j2] - A[i1][j2] * A[i2][j1];
            magnitudes[i][j] =
              std::abs(A[i1][j1] * A[i2][j2]) + std::abs(A[i1][j2] * A[i2][j1]);
          }
      return C;
    }

    template <int dim>
    Tensor<2, dim>
    absolute(const Tensor<2, dim> &A)
    {
      Tensor<2, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          result[i][j] = std::abs(A[i][j]);
      return result;
    }

    /**
     * Each coefficient c_k, k >= 1, with the sum m_k of the absolute values
     * of the products it is made of. A c_k that is zero up to rounding
     * (|c_k| <= 32 eps m_k, e.g. det B of a rank-deficient B) is set to
     * exactly zero: its rounding noise would otherwise put a spurious root
     * near t ~ 1/eps.
     */
    PolynomialCoefficients
    without_rounding_noise(PolynomialCoefficients        c,
                           const PolynomialCoefficients &magnitudes)
    {
      for (unsigned int k = 1; k < 4; ++k)
        if (std::abs(c[k]) <=
            32. * std::numeric_limits<double>::epsilon() * magnitudes[k])
          c[k] = 0.;
      return c;
    }

    PolynomialCoefficients
    coefficients(const Tensor<2, 2> &A, const Tensor<2, 2> &B)
    {
      const double products[4] = {A[0][0] * B[1][1],
                                  A[1][1] * B[0][0],
                                  A[0][1] * B[1][0],
                                  A[1][0] * B[0][1]};
      return without_rounding_noise(
        {{determinant(A),
          products[0] + products[1] - products[2] - products[3],
          determinant(B),
          0.}},
        {{0.,
          std::abs(products[0]) + std::abs(products[1]) +
            std::abs(products[2]) + std::abs(products[3]),
          std::abs(B[0][0] * B[1][1]) + std::abs(B[0][1] * B[1][0]),
          0.}});
    }

    PolynomialCoefficients
    coefficients(const Tensor<2, 3> &A, const Tensor<2, 3> &B)
    {
      Tensor<2, 3>       magnitude_A, magnitude_B;
      const Tensor<2, 3> cof_A = cofactor_matrix(A, magnitude_A);
      const Tensor<2, 3> cof_B = cofactor_matrix(B, magnitude_B);
      const Tensor<2, 3> abs_B = absolute(B);
      // det B by the expansion along the first row, with its magnitude
      double det_B = 0., magnitude_det_B = 0.;
      for (unsigned int j = 0; j < 3; ++j)
        {
          det_B += B[0][j] * cof_B[0][j];
          magnitude_det_B += abs_B[0][j] * magnitude_B[0][j];
        }
      return without_rounding_noise({{determinant(A),
                                      scalar_product(cof_A, B),
                                      scalar_product(A, cof_B),
                                      det_B}},
                                    {{0.,
                                      scalar_product(magnitude_A, abs_B),
                                      scalar_product(absolute(A), magnitude_B),
                                      magnitude_det_B}});
    }
  } // namespace



  template <int dim>
  PolynomialCoefficients
  determinant_polynomial(const Tensor<2, dim> &A, const Tensor<2, dim> &B)
  {
    return coefficients(A, B);
  }



  template <int dim>
  double
  determinant_step_bound(const Tensor<2, dim> &A, const Tensor<2, dim> &B)
  {
    return smallest_positive_root(coefficients(A, B), dim);
  }



  template PolynomialCoefficients
  determinant_polynomial<2>(const Tensor<2, 2> &, const Tensor<2, 2> &);
  template PolynomialCoefficients
  determinant_polynomial<3>(const Tensor<2, 3> &, const Tensor<2, 3> &);
  template double
  determinant_step_bound<2>(const Tensor<2, 2> &, const Tensor<2, 2> &);
  template double
  determinant_step_bound<3>(const Tensor<2, 3> &, const Tensor<2, 3> &);
} // namespace bfemp
