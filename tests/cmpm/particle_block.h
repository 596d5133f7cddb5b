#ifndef bfemp_tests_cmpm_particle_block_h
#define bfemp_tests_cmpm_particle_block_h

// A block of particles in a ParticleSystem for the cMPM tests that run the
// discretization on real particles: counts[d] particles along direction d
// at spacing h from @p lower (cell centres), each with mass rho h^dim,
// rest volume h^dim, F = I and its initial position; set(x, p) may then
// change anything (material, F, velocity) or move x. finish_insertion() is
// left to the caller.

#include <bfemp/cmpm/cmpm_parameters.h>
#include <bfemp/grid/grid_parameters.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace bfemp_tests
{
  template <int dim, typename Set>
  void
  insert_particle_block(bfemp::ParticleSystem<dim>          &particles,
                        const dealii::Point<dim>            &lower,
                        const double                         h,
                        const std::array<unsigned int, dim> &counts,
                        const double                         density,
                        const Set                           &set)
  {
    using Layout       = bfemp::ParticleLayout<dim>;
    unsigned int total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= counts[d];
    for (unsigned int k = 0; k < total; ++k)
      {
        dealii::Point<dim> x;
        unsigned int       index = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] = lower[d] + (index % counts[d] + 0.5) * h;
            index /= counts[d];
          }
        std::vector<double>             properties(Layout::n_properties, 0.);
        const dealii::ArrayView<double> p = dealii::make_array_view(properties);
        p[Layout::mass]                   = density * std::pow(h, dim);
        p[Layout::rest_volume]            = std::pow(h, dim);
        Layout::set_tensor(p,
                           Layout::deformation_gradient,
                           dealii::unit_symmetric_tensor<dim>());
        set(x, p);
        Layout::set_vector(p, Layout::initial_position, x);
        particles.insert(x, dealii::make_array_view(std::as_const(properties)));
      }
  }

  /** counts of @p n along every direction. */
  template <int dim>
  std::array<unsigned int, dim>
  cube_counts(const unsigned int n)
  {
    std::array<unsigned int, dim> counts;
    counts.fill(n);
    return counts;
  }

  /** A grid over [0, 1]^dim with cells (coarse elements) of size @p H. */
  template <int dim>
  bfemp::GridParameters<dim>
  unit_box_grid(const double H)
  {
    bfemp::GridParameters<dim> parameters;
    for (unsigned int d = 0; d < dim; ++d)
      parameters.upper_corner[d] = 1.;
    parameters.cell_size = H;
    return parameters;
  }

  /** cMPM on, with the defaults and @p n fine nodes per direction. */
  inline bfemp::CmpmParameters
  cmpm_with_fine_nodes(const unsigned int n)
  {
    bfemp::CmpmParameters parameters;
    parameters.enabled = true;
    parameters.n_fine  = n;
    return parameters;
  }
} // namespace bfemp_tests

#endif
