#ifndef bfemp_solver_determinant_bound_h
#define bfemp_solver_determinant_bound_h

#include <bfemp/solver/polynomial_roots.h>

#include <deal.II/base/tensor.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * The coefficients of the polynomial det(A + t B) in t, built exactly
   * from the entries (no inverse of A is formed, so nothing breaks when A is
   * nearly singular):
   * - 2D: det A + t (A00 B11 + A11 B00 - A01 B10 - A10 B01) + t^2 det B;
   * - 3D: det A + t tr(adj(A) B) + t^2 tr(A adj(B)) + t^3 det B, with
   *   tr(adj(A) B) = cof(A) : B and tr(A adj(B)) = A : cof(B).
   * The coefficients above dim are zero. A coefficient of t^k, k >= 1,
   * that vanishes up to the rounding error of the products it is summed from
   * (|c_k| <= 32 eps sum |products|, e.g. det B of a rank-deficient B, as
   * when a single node moves) is set to exactly zero, so the degree drops:
   * its rounding noise, of either sign, would otherwise create a spurious
   * root near t ~ 1/eps.
   */
  template <int dim>
  PolynomialCoefficients
  determinant_polynomial(const Tensor<2, dim> &A, const Tensor<2, dim> &B);

  /**
   * The smallest t > 0 with det(A + t B) = 0, or +infinity if there is none,
   * assuming det A > 0 (not checked: with det A <= 0 the result is still
   * the first positive zero, or 0 if the polynomial vanishes identically).
   *
   * This bounds the line search of the implicit solve (DESIGN.md, solver/):
   * for an FEM element F(t) = T(x + t p) B_e^{-1} = (T(x) + t T(p)) B_e^{-1}
   * (eq. 24, T linear in the node positions), and for an MPM particle
   * F(t) = (I + dt grad v(t)) F_n = (A + t B) F_n with grad v linear in the
   * grid velocities. Since det(M C) = det(M) det(C) with det C > 0, det F
   * stays positive exactly for t below this bound. A double root of the
   * polynomial (det F touching zero) also counts, see
   * smallest_positive_root().
   */
  template <int dim>
  double
  determinant_step_bound(const Tensor<2, dim> &A, const Tensor<2, dim> &B);
} // namespace bfemp

#endif
