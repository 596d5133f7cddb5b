// smallest_positive_root() and determinant_step_bound(), the kernel of the
// line search's det F > 0 step bound: polynomials built from known roots
// (simple, double and triple roots, roots near 0, huge and tiny scalings, a
// leading coefficient 1e-20 relative to the others, complex pairs, no
// positive root, linear and constant cases), random polynomials against the
// smallest positive root they were built from, and random 2x2 / 3x3 pairs
// A, B: det(A + t* B) = 0 at the bound and det(A + t B) > 0 on a dense
// sample of (0, t*).

#include <bfemp/solver/determinant_bound.h>
#include <bfemp/solver/polynomial_roots.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  const double infinity = std::numeric_limits<double>::infinity();

  bfemp_tests::RandomNumbers random_numbers(20240701);

  /** scale * prod_i (t - r_i), expanded. */
  PolynomialCoefficients
  from_roots(const double scale, const std::vector<double> &roots)
  {
    PolynomialCoefficients c = {{scale, 0., 0., 0.}};
    for (unsigned int k = 0; k < roots.size(); ++k)
      {
        // multiply by (t - r): shift up, subtract r times the old
        for (unsigned int i = k + 1; i-- > 0;)
          c[i + 1] += c[i], c[i] *= -roots[k];
      }
    return c;
  }

  /** scale (t^2 - 2 re t + |z|^2) (t - r): a complex pair and a real root. */
  PolynomialCoefficients
  complex_pair(const double scale, const std::complex<double> z, const double r)
  {
    const double a = -2. * z.real(), b = std::norm(z);
    return {{-scale * b * r, scale * (b - a * r), scale * (a - r), scale}};
  }

  double
  relative_error(const double computed, const double expected)
  {
    if (std::isinf(expected) || std::isinf(computed))
      return computed == expected ? 0. : infinity;
    if (expected == 0.)
      return std::abs(computed);
    return std::abs(computed - expected) / std::abs(expected);
  }

  void
  check_root(const std::string            &name,
             const PolynomialCoefficients &c,
             const unsigned int            degree,
             const double                  expected,
             const double                  tolerance = 1e-12)
  {
    const double t = smallest_positive_root(c, degree);
    if (std::isinf(expected))
      bfemp_tests::check(relative_error(t, expected) <= tolerance,
                         name + ": no positive root: t* = " +
                           bfemp_tests::format("%.1e", t));
    else
      bfemp_tests::check_below(relative_error(t, expected),
                               tolerance,
                               name + ": root found: relative error");
  }

  /** sum |c_i| t^i, the scale of rounding errors of p(t). */
  double
  magnitude(const PolynomialCoefficients &c,
            const unsigned int            degree,
            const double                  t)
  {
    double result = 0.;
    for (unsigned int i = 0; i <= degree; ++i)
      result += std::abs(c[i]) * std::pow(t, i);
    return result;
  }

  /** p(t*) = 0 to rounding, and p changes sign across t*. */
  void
  check_residual(const std::string            &name,
                 const PolynomialCoefficients &c,
                 const unsigned int            degree)
  {
    const double t = smallest_positive_root(c, degree);
    const double residual =
      std::abs(evaluate_polynomial(c, degree, t)) / magnitude(c, degree, t);
    bfemp_tests::check(std::isfinite(t) && t > 0. && residual <= 1e-14 &&
                         evaluate_polynomial(c, degree, t * (1. - 1e-9)) *
                             evaluate_polynomial(c, degree, t * (1. + 1e-9)) <
                           0.,
                       name + ": p(t*) = 0 and p changes sign there: t* = " +
                         bfemp_tests::format("%.1e", t) +
                         ", |p(t*)| / sum_i |c_i| t*^i " +
                         bfemp_tests::measured(residual, 1e-14));
  }

  void
  known_roots()
  {
    // simple roots
    check_root("roots 1, 2, 3", from_roots(1., {1., 2., 3.}), 3, 1.);
    check_root("roots -1, 0.5, 4", from_roots(-2., {-1., 0.5, 4.}), 3, 0.5);
    check_root("roots -3, -1, 2", from_roots(0.7, {-3., -1., 2.}), 3, 2.);
    check_root("quadratic roots -1, 3", from_roots(1., {-1., 3.}), 2, 3.);

    // multiple roots: p touches zero (det F reaches 0) or crosses it flat
    check_root("double root 2 (touching), root -1",
               from_roots(1., {2., 2., -1.}),
               3,
               2.,
               1e-7);
    check_root("double root 2 (touching, p < 0 around it), root -1",
               from_roots(-1., {2., 2., -1.}),
               3,
               2.,
               1e-7);
    check_root("root 1, double root 3", from_roots(1., {1., 3., 3.}), 3, 1.);
    check_root("double root 0.5 of a quadratic",
               from_roots(3., {0.5, 0.5}),
               2,
               0.5,
               1e-7);
    check_root("double root 1 before root 4",
               from_roots(1., {4., 1., 1.}),
               3,
               1.,
               1e-7);
    check_root("triple root 1", from_roots(1., {1., 1., 1.}), 3, 1., 1e-5);

    // roots near zero and the cancellation in the quadratic formula
    check_root("roots 1e-12, 3, -2",
               from_roots(1., {1e-12, 3., -2.}),
               3,
               1e-12);
    check_root("quadratic roots 1e-12, 1 (cancellation)",
               from_roots(1., {1e-12, 1.}),
               2,
               1e-12);
    check_root("quadratic roots 1, 1e12 (cancellation)",
               from_roots(1., {1e12, 1.}),
               2,
               1.);
    check_root("double root 1e-12, root -1",
               from_roots(1., {1e-12, 1e-12, -1.}),
               3,
               1e-12,
               1e-6);
    check_root("roots 1e-300, 1, 2",
               from_roots(1., {1e-300, 1., 2.}),
               3,
               1e-300);

    // scale invariance: of the coefficients and of the roots
    for (const std::string scale : {"1e-300", "1e-30", "1e30", "1e300"})
      check_root("roots 1, 2, 3, coefficients times " + scale,
                 from_roots(std::stod(scale), {1., 2., 3.}),
                 3,
                 1.);
    check_root("roots 1e-8, 2e-8, -3e-8",
               from_roots(1., {1e-8, 2e-8, -3e-8}),
               3,
               1e-8);
    check_root("roots 1e8, 2e8, -3e8",
               from_roots(1., {1e8, 2e8, -3e8}),
               3,
               1e8);
    check_root("roots 1e-8, 1e8, 1e16",
               from_roots(1., {1e16, 1e8, 1e-8}),
               3,
               1e-8);

    // tiny and vanishing leading coefficients
    {
      PolynomialCoefficients c = from_roots(1., {1., 2.});
      c[3]                     = 1e-20;
      check_root("(t-1)(t-2) + 1e-20 t^3", c, 3, 1.);
      c[3] = -1e-20;
      check_root("(t-1)(t-2) - 1e-20 t^3", c, 3, 1.);
      c[3] = 0.;
      check_root("(t-1)(t-2) + 0 t^3 (degree 3 given)", c, 3, 1.);
      check_residual("1 + t - 1e-20 t^3 (only root near 1e10)",
                     {{1., 1., 0., -1e-20}},
                     3);
      check_root("1 + t + 1e-20 t^3", {{1., 1., 0., 1e-20}}, 3, infinity);
      check_residual("1 + t - 1e-20 t^2 (only root near 1e20)",
                     {{1., 1., -1e-20, 0.}},
                     2);
      check_root("1 - 2t + 1e-20 t^2", {{1., -2., 1e-20, 0.}}, 2, 0.5);
      check_root("2 - 3t + 1e-300 t^2 + 1e-300 t^3",
                 {{2., -3., 1e-300, 1e-300}},
                 3,
                 2. / 3.);
      check_root("1 + t + 0 t^2 + 0 t^3", {{1., 1., 0., 0.}}, 3, infinity);
      check_root("1 - t, c3 = -1e20 ignored (degree 2 given)",
                 {{1., -1., 0., -1e20}},
                 2,
                 1.);
    }

    // no positive root
    check_root("roots -1, -2, -3",
               from_roots(1., {-1., -2., -3.}),
               3,
               infinity);
    check_root("roots -1e-12, -1, -1e12",
               from_roots(-1., {-1e-12, -1., -1e12}),
               3,
               infinity);
    check_root("roots +-i, -1", complex_pair(1., {0., 1.}, -1.), 3, infinity);
    check_root("roots 1 +- i, -2",
               complex_pair(1., {1., 1.}, -2.),
               3,
               infinity);
    check_root("roots 1 +- 1e-3 i, -2 (near double root, no touching)",
               complex_pair(1., {1., 1e-3}, -2.),
               3,
               infinity);
    check_root("roots 1 +- i, 5", complex_pair(2., {1., 1.}, 5.), 3, 5.);
    check_root("t^2 + 1", {{1., 0., 1., 0.}}, 2, infinity);

    // low degrees and roots at zero
    check_root("linear 1 - 2t", {{1., -2., 0., 0.}}, 1, 0.5);
    check_root("linear 1 + 2t", {{1., 2., 0., 0.}}, 1, infinity);
    check_root("linear 1e-30 - 1e30 t", {{1e-30, -1e30, 0., 0.}}, 1, 1e-60);
    check_root("constant 5", {{5., 0., 0., 0.}}, 0, infinity);
    check_root("constant 5 (degree 3 given)", {{5., 0., 0., 0.}}, 3, infinity);
    check_root("zero polynomial (every t is a root)",
               {{0., 0., 0., 0.}},
               3,
               0.);
    check_root("t (t - 1): the root 0 is not positive",
               from_roots(1., {0., 1.}),
               2,
               1.);
    check_root("t^2 (t + 1)", from_roots(1., {0., 0., -1.}), 3, infinity);
  }

  /** Random roots of random signs and magnitudes (some double) against
   *  the smallest positive root they were built from. */
  void
  random_polynomials()
  {
    unsigned int n_cases = 0, n_failed = 0;
    double       worst_simple = 0., worst_double = 0.;
    for (unsigned int k = 0; k < 3000; ++k)
      {
        const unsigned int  degree = 2 + k % 2;
        std::vector<double> roots(degree);
        for (double &r : roots)
          r = (random_numbers.uniform(0., 1.) < 0.6 ? 1. : -1.) *
              std::pow(10., random_numbers.uniform(-6., 6.));
        const bool double_root = k % 5 == 0;
        if (double_root)
          roots[1] = roots[0];
        double expected = infinity;
        for (const double r : roots)
          if (r > 0.)
            expected = std::min(expected, r);
        const double scale = std::pow(10., random_numbers.uniform(-20., 20.));
        const double t =
          smallest_positive_root(from_roots(scale, roots), degree);
        ++n_cases;
        const double error = relative_error(t, expected);
        double      &worst = double_root ? worst_double : worst_simple;
        worst              = std::max(worst, error);
        if (!(error <= (double_root ? 1e-6 : 1e-10)))
          {
            ++n_failed;
            deallog << "  degree " << degree << " roots";
            for (const double r : roots)
              deallog << ' ' << r;
            deallog << " -> " << t << std::endl;
          }
      }
    bfemp_tests::check(n_failed == 0,
                       "random polynomials: smallest positive root of " +
                         std::to_string(n_cases) +
                         " cases: largest relative error with simple roots " +
                         bfemp_tests::measured(worst_simple, 1e-10) +
                         ", with a double root " +
                         bfemp_tests::measured(worst_double, 1e-6));
  }

  template <int dim>
  double
  norm(const Tensor<2, dim> &A)
  {
    return A.norm();
  }

  /**
   * det(A + t* B) = 0 relative to (|A| + t* |B|)^dim, and det(A + t B) > 0
   * for t = t* k / 1000, k = 1..999 (or on a log grid of (0, 1e6] when
   * t* = infinity). With @p known_root > 0, B was built so that
   * det(A + known_root B) = 0, and t* <= known_root is also checked.
   * Returns whether t* > 0, t* <= known_root and the signs hold, and sets
   * @p residual to |det(A + t* B)| / (|A| + t* |B|)^dim (0 if t* is
   * infinite), which the caller checks against 1e-12.
   */
  template <int dim>
  bool
  check_bound(const Tensor<2, dim> &A,
              const Tensor<2, dim> &B,
              double               &residual,
              const double          known_root = 0.)
  {
    residual            = 0.;
    const double t_star = determinant_step_bound(A, B);
    if (!(t_star > 0.))
      return false;
    if (known_root > 0. && !(t_star <= known_root * (1. + 1e-8)))
      return false;
    if (std::isfinite(t_star))
      {
        const double scale = std::pow(norm(A) + t_star * norm(B), dim);
        residual =
          std::abs(determinant(Tensor<2, dim>(A + t_star * B))) / scale;
        for (unsigned int k = 1; k < 1000; ++k)
          if (!(determinant(Tensor<2, dim>(A + (t_star * k / 1000.) * B)) > 0.))
            return false;
      }
    else
      for (double t = 1e-6; t <= 1e6; t *= 1.01)
        if (!(determinant(Tensor<2, dim>(A + t * B)) > 0.))
          return false;
    return true;
  }

  /** The failures and the largest residual of a group of check_bound()
   *  calls. */
  struct BoundCases
  {
    unsigned int n_cases = 0, n_failed = 0;
    double       worst_residual = 0.;

    template <int dim>
    void
    add(const Tensor<2, dim> &A,
        const Tensor<2, dim> &B,
        const double          known_root = 0.)
    {
      double residual = 0.;
      ++n_cases;
      n_failed += !check_bound(A, B, residual, known_root);
      // a NaN sticks (std::max could drop it)
      if (std::isnan(residual) || residual > worst_residual)
        worst_residual = residual;
    }

    void
    report(const std::string &what) const
    {
      bfemp_tests::check(n_failed == 0 && worst_residual <= 1e-12,
                         what + " (" + std::to_string(n_cases) +
                           " cases): " + std::to_string(n_failed) +
                           " failed, largest |det(A + t* B)| / (|A| + t* "
                           "|B|)^dim " +
                           bfemp_tests::measured(worst_residual, 1e-12));
    }
  };

  template <int dim>
  Tensor<2, dim>
  random_positive_determinant(const double amplitude)
  {
    while (true)
      {
        const Tensor<2, dim> A =
          unit_symmetric_tensor<dim>() + random_numbers.tensor<dim>(amplitude);
        if (determinant(A) > 0.05)
          return A;
      }
  }

  template <int dim>
  void
  random_tensors()
  {
    const std::string name = std::to_string(dim) + "D determinant bound";

    // generic random directions of several sizes, A at several scales
    BoundCases generic;
    for (const double a_scale : {1e-3, 1., 1e3})
      for (const double b_amplitude : {0.01, 0.3, 1., 10., 1e4})
        for (unsigned int k = 0; k < 100; ++k)
          {
            const Tensor<2, dim> A =
              a_scale * random_positive_determinant<dim>(0.5);
            const Tensor<2, dim> B =
              a_scale * random_numbers.tensor<dim>(b_amplitude);
            generic.add(A, B);
          }
    generic.report(name + ": random A, B");

    // singular directions (rank one, as from a single moving node, and in
    // 3D rank two): det B and the other vanishing coefficients are rounding
    // noise that must not create roots
    for (unsigned int rank = 1; rank < dim; ++rank)
      {
        BoundCases singular;
        for (unsigned int k = 0; k < 500; ++k)
          {
            const Tensor<2, dim> A = random_positive_determinant<dim>(0.5);
            Tensor<2, dim>       B;
            for (unsigned int r = 0; r < rank; ++r)
              B += outer_product(random_numbers.vector<dim>(3.),
                                 random_numbers.vector<dim>(1.));
            singular.add(A, B);
          }
        singular.report(name + ": rank-" + std::to_string(rank) + " B");
      }

    // B = (S - A) / t0 with a singular S, so det(A + t0 B) = 0: the bound is
    // at most t0, for t0 from 1e-12 to 1e6
    BoundCases through_singular;
    for (const double t0 : {1e-12, 1e-6, 1e-2, 1., 1e6})
      for (unsigned int k = 0; k < 100; ++k)
        {
          const Tensor<2, dim> A = random_positive_determinant<dim>(0.5);
          Tensor<2, dim>       S = random_numbers.tensor<dim>(1.);
          // make the last column a combination of the others
          for (unsigned int i = 0; i < dim; ++i)
            S[i][dim - 1] = 0.3 * S[i][0] - 0.7 * S[i][dim - 2];
          const Tensor<2, dim> B = (S - A) / t0;
          through_singular.add(A, B, t0);
        }
    through_singular.report(name +
                            ": direction through a singular matrix at t0");

    // directions that only shrink or shear (no root): B = -s A has its root at
    // 1/s, and B = 0 has none
    double worst_error = 0.;
    for (const double s : {1e-9, 0.5, 2., 1e9})
      {
        const Tensor<2, dim> A = random_positive_determinant<dim>(0.5);
        // a root of multiplicity dim: accurate to about eps^(1/dim)
        const double error =
          relative_error(determinant_step_bound<dim>(A, -s * A), 1. / s);
        if (std::isnan(error) || error > worst_error)
          worst_error = error;
      }
    const Tensor<2, dim> A = random_positive_determinant<dim>(0.5);
    const double t_none    = determinant_step_bound<dim>(A, Tensor<2, dim>());
    bfemp_tests::check(worst_error <= 1e-4 && std::isinf(t_none),
                       name + ": B = -s A gives 1/s (a root of multiplicity " +
                         std::to_string(dim) +
                         "), B = 0 gives none: largest relative error " +
                         bfemp_tests::measured(worst_error, 1e-4) +
                         ", t* for B = 0: " +
                         bfemp_tests::format("%.1e", t_none));
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  known_roots();
  random_polynomials();
  random_tensors<2>();
  random_tensors<3>();
}
