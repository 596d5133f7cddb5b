// The vector kernels of the MPM elasticity Hessian (particle_block_kernels.h)
// against the blocks H_kl = sum_p w_p sum_jd A_p[a][j][b][d] g_k,p[j]
// g_l,p[d] of eq. (25) summed in long double, one term at a time: random
// tangents, weights and gradients of groups of 1 to 5 particles, stencils of
// full and partial length (nodes without mass are skipped), in 2D and 3D.
// Also checked: the columns past the stencil (zero-padded gradients) come out
// zero, and the entries before the row's first vector are left alone.

#include <bfemp/solver/particle_block_kernels.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20261127);

  template <int dim>
  void
  check_group(const unsigned int n_particles,
              const unsigned int n,
              const unsigned int L)
  {
    constexpr unsigned int           W = particle_block_width;
    std::vector<Tensor<4, dim>>      tangents(n_particles);
    std::vector<double>              weights(n_particles);
    std::vector<std::vector<double>> gradients(n_particles,
                                               std::vector<double>(dim * L));
    std::vector<std::vector<double>> contractions(n_particles,
                                                  std::vector<double>(
                                                    dim * dim * dim * L));
    for (unsigned int p = 0; p < n_particles; ++p)
      {
        for (auto v = tangents[p].begin_raw(); v != tangents[p].end_raw(); ++v)
          *v = random_numbers.uniform(-1e8, 1e8);
        weights[p] = random_numbers.uniform(1e-6, 1e-3);
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int l = 0; l < n; ++l)
            gradients[p][d * L + l] = random_numbers.uniform(-20., 20.);
        first_contractions<dim>(tangents[p].begin_raw(),
                                weights[p],
                                gradients[p].data(),
                                L,
                                contractions[p].data());
      }

    double       largest = 0., largest_error = 0., largest_padding = 0.;
    unsigned int touched_before_first = 0;
    std::vector<const double *> member_gradients(n_particles),
      member_contractions(n_particles);
    std::vector<double> row(dim * dim * L);
    for (unsigned int k = 0; k < n; ++k)
      {
        for (unsigned int p = 0; p < n_particles; ++p)
          {
            member_gradients[p]    = gradients[p].data();
            member_contractions[p] = contractions[p].data() + k;
          }
        const unsigned int l_begin = k / W * W;
        std::fill(row.begin(),
                  row.end(),
                  std::numeric_limits<double>::quiet_NaN());
        sum_block_row<dim>(member_contractions.data(),
                           member_gradients.data(),
                           n_particles,
                           L,
                           l_begin,
                           row.data());
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int l = 0; l < L; ++l)
              {
                const double value = row[(a * dim + b) * L + l];
                if (l < l_begin)
                  {
                    touched_before_first += std::isnan(value) ? 0 : 1;
                    continue;
                  }
                if (l >= n)
                  {
                    largest_padding =
                      std::max(largest_padding, std::abs(value));
                    continue;
                  }
                long double reference = 0.;
                for (unsigned int p = 0; p < n_particles; ++p)
                  for (unsigned int j = 0; j < dim; ++j)
                    for (unsigned int d = 0; d < dim; ++d)
                      reference += static_cast<long double>(weights[p]) *
                                   tangents[p][a][j][b][d] *
                                   gradients[p][j * L + k] *
                                   gradients[p][d * L + l];
                largest =
                  std::max(largest, std::abs(static_cast<double>(reference)));
                const double error =
                  std::abs(static_cast<double>(value - reference));
                largest_error =
                  std::isnan(error) ? error : std::max(largest_error, error);
              }
      }
    const std::string what = std::to_string(dim) + "D, " +
                             std::to_string(n_particles) + " particles, " +
                             std::to_string(n) + " of " + std::to_string(L) +
                             " nodes:";
    bfemp_tests::check(largest > 0., what + " non-zero blocks");
    bfemp_tests::check_below(largest_error / largest,
                             1e-14,
                             what + " largest error / largest entry");
    bfemp_tests::check(largest_padding == 0.,
                       what + " columns past the stencil are zero");
    bfemp_tests::check(touched_before_first == 0,
                       what + " entries before the first column vector kept");
  }
} // namespace

int
main()
{
  bfemp_tests::initlog();
  // quadratic B-splines: 3^dim nodes; fewer where nodes without mass drop
  for (const unsigned int n_particles : {1u, 3u, 5u})
    {
      check_group<2>(n_particles, 9, 12);
      check_group<3>(n_particles, 27, 28);
    }
  check_group<2>(2, 6, 12);
  check_group<3>(4, 18, 28);
  check_group<3>(1, 1, 28);
}
