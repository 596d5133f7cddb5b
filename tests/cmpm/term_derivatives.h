#ifndef bfemp_tests_cmpm_term_derivatives_h
#define bfemp_tests_cmpm_term_derivatives_h

// The finite-difference check of one energy term of a cMPM step, shared by
// the cMPM term tests.

#include <bfemp/solver/energy_term.h>
#include <bfemp/solver/incremental_potential.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <tuple>

#include "solver/solver_test_scene.h"

namespace bfemp_tests
{
  using namespace dealii;
  using namespace bfemp;

  /**
   * Gradient and Hessian of @p term against central differences: whole
   * matrices in 2D; in 3D (hundreds of unknowns) along 10 random
   * directions d: g.d against the difference of the value, H d against the
   * difference of the gradient.
   */
  template <int dim>
  void
  check_term(const std::string         &what,
             const EnergyTerm<dim>     &term,
             IncrementalPotential<dim> &potential,
             const Vector<double>      &u,
             const double               h,
             RandomNumbers             &random_numbers)
  {
    Vector<double> g(u.size());
    term.add_gradient(u, g);
    const SparseMatrix<double> &H              = potential.hessian(u);
    double                      gradient_error = 0., hessian_error = 0.;
    if (dim == 2)
      {
        const Vector<double> g_fd = finite_difference_gradient(
          [&](const Vector<double> &v) { return term.value(v); },
          u,
          h);
        const FullMatrix<double> H_fd = finite_difference_hessian(
          [&](const Vector<double> &v, Vector<double> &grad) {
            term.add_gradient(v, grad);
          },
          u,
          h);
        gradient_error = relative_difference(g_fd, g);
        hessian_error  = relative_difference(dense(H), H_fd);
      }
    else
      for (unsigned int k = 0; k < 10; ++k)
        {
          Vector<double> d(u.size()), plus(u), minus(u), g_plus(u.size()),
            g_minus(u.size()), Hd(u.size());
          for (unsigned int i = 0; i < d.size(); ++i)
            d[i] = random_numbers.uniform(-1., 1.);
          plus.add(h, d);
          minus.add(-h, d);
          const double slope = (term.value(plus) - term.value(minus)) / (2 * h);
          gradient_error =
            std::max(gradient_error,
                     std::abs(slope - g * d) / (g.l2_norm() * d.l2_norm()));
          term.add_gradient(plus, g_plus);
          term.add_gradient(minus, g_minus);
          g_plus.add(-1., g_minus);
          g_plus /= 2 * h;
          H.vmult(Hd, d);
          Hd.add(-1., g_plus);
          hessian_error =
            std::max(hessian_error, Hd.l2_norm() / g_plus.l2_norm());
        }
    double min_eigenvalue = 0., max_eigenvalue = 0.;
    if (dim == 2)
      std::tie(min_eigenvalue, max_eigenvalue) = eigenvalue_range(dense(H));
    // the sizes the relative errors refer to, at 3 digits (stable); the
    // round-off dependent errors themselves go to stdout
    char sizes[160];
    std::snprintf(sizes,
                  sizeof(sizes),
                  "%s: |gradient| %.3g, largest row sum of |H| %.3g",
                  what.c_str(),
                  g.l2_norm(),
                  H.linfty_norm());
    deallog << sizes << std::endl;
    std::cout << what << ": gradient error " << gradient_error
              << ", Hessian error " << hessian_error << ", eigenvalues ["
              << min_eigenvalue << ", " << max_eigenvalue << "]" << std::endl;
    check(gradient_error < 1e-6, what + ": gradient matches differences");
    check(hessian_error < 1e-6,
          what + ": Hessian matches differences of the gradient");
    if (dim == 2)
      check(min_eigenvalue >= -1e-10 * max_eigenvalue, what + ": Hessian PSD");
  }

} // namespace bfemp_tests

#endif
