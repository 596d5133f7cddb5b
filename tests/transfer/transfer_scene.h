#ifndef bfemp_tests_transfer_scene_h
#define bfemp_tests_transfer_scene_h

// Shared set-up of the transfer tests: a background grid on [-1/2, 1/2]^dim
// (cell size 1/16, so node coordinates are exact), a particle system, one
// neo-Hookean material and a ParticleGridTransfer, plus random particles and
// grid-side sums.

#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/io/step_diagnostics.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <deal.II/base/tensor.h>

#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tests.h"

namespace bfemp_tests
{
  using namespace dealii;
  using namespace bfemp;

  inline RandomNumbers random_numbers(20240917);

  inline double
  uniform(const double low, const double high)
  {
    return random_numbers.uniform(low, high);
  }

  template <int dim>
  Tensor<1, dim>
  random_vector(const double amplitude)
  {
    return random_numbers.vector<dim>(amplitude);
  }

  template <int dim>
  Tensor<2, dim>
  random_tensor(const double amplitude)
  {
    return random_numbers.tensor<dim>(amplitude);
  }

  /** x with two decimals, for output that must not depend on round-off. */
  inline std::string
  two_decimals(const double x)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.2f", x);
    return buffer;
  }

  inline std::string
  scheme_name(const TransferParameters::Scheme scheme)
  {
    return scheme == TransferParameters::Scheme::pic    ? "PIC"
           : scheme == TransferParameters::Scheme::flip ? "FLIP"
                                                        : "APIC";
  }

  /** x cross v as a 3-vector (only the z component in 2D). */
  template <int dim>
  Tensor<1, 3>
  cross(const Point<dim> &x, const Tensor<1, dim> &v)
  {
    Tensor<1, 3> L;
    if constexpr (dim == 2)
      L[2] = x[0] * v[1] - x[1] * v[0];
    else
      L = cross_product_3d(Tensor<1, 3>(x), v);
    return L;
  }

  template <int dim>
  GridParameters<dim>
  grid_parameters(const unsigned int kernel_degree)
  {
    GridParameters<dim> parameters;
    for (unsigned int d = 0; d < dim; ++d)
      {
        parameters.lower_corner[d] = -0.5;
        parameters.upper_corner[d] = 0.5;
      }
    parameters.cell_size     = 1. / 16.;
    parameters.kernel_degree = kernel_degree;
    return parameters;
  }

  inline TransferParameters
  transfer_parameters(const TransferParameters::Scheme scheme)
  {
    TransferParameters parameters;
    parameters.scheme = scheme;
    return parameters;
  }

  template <int dim>
  std::vector<std::unique_ptr<Material<dim>>>
  neo_hookean()
  {
    std::vector<std::unique_ptr<Material<dim>>> materials;
    materials.push_back(
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3)));
    return materials;
  }

  template <int dim>
  struct TransferScene
  {
    using Layout = ParticleLayout<dim>;

    TransferScene(const unsigned int               kernel_degree,
                  const TransferParameters::Scheme scheme)
      : grid(grid_parameters<dim>(kernel_degree))
      , particles(grid)
      , materials(neo_hookean<dim>())
      , transfer(grid, transfer_parameters(scheme), materials)
    {}

    void
    insert(const Point<dim>     &x,
           const double          m,
           const Tensor<1, dim> &v,
           const Tensor<2, dim> &F = unit_symmetric_tensor<dim>(),
           const Tensor<2, dim> &C = Tensor<2, dim>())
    {
      std::vector<double>     properties(Layout::n_properties, 0.);
      const ArrayView<double> p = make_array_view(properties);
      p[Layout::mass]           = m;
      p[Layout::rest_volume]    = m / 1000.;
      Layout::set_vector(p, Layout::velocity, v);
      Layout::set_tensor(p, Layout::deformation_gradient, F);
      Layout::set_tensor(p, Layout::affine_velocity, C);
      Layout::set_vector(p, Layout::initial_position, x);
      particles.insert(x, make_array_view(std::as_const(properties)));
    }

    /** A point whose kernel stencil is at least two cells inside the grid. */
    Point<dim>
    random_point() const
    {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = uniform(-0.5 + 4. / 16., 0.5 - 4. / 16.);
      return x;
    }

    /** n random particles: mass, velocity, F near I and (APIC) C. */
    void
    insert_random(const unsigned int n, const bool with_affine)
    {
      for (unsigned int q = 0; q < n; ++q)
        {
          const Point<dim> x = random_point();
          const double     m = uniform(0.5e-3, 1.5e-3);
          const auto       v = random_vector<dim>(1.);
          const auto F = unit_symmetric_tensor<dim>() + random_tensor<dim>(0.1);
          insert(x,
                 m,
                 v,
                 F,
                 with_affine ? random_tensor<dim>(5.) : Tensor<2, dim>());
        }
      particles.finish_insertion();
    }

    /** P2G into a fresh grid state (momentum left in velocity). */
    GridState<dim>
    particles_to_grid(const bool with_stress = false)
    {
      GridState<dim> state;
      state.reinit(grid.lattice().n_nodes);
      transfer.particles_to_grid(particles, state, with_stress);
      return state;
    }

    /** Divides the momentum by the mass and sets an explicit step without
     *  forces: new_velocity = velocity, displacement = dt velocity. */
    static void
    free_flight(GridState<dim> &state, const double dt)
    {
      for (std::size_t i = 0; i < state.mass.size(); ++i)
        if (state.mass[i] > 0.)
          {
            state.velocity[i] /= state.mass[i];
            state.new_velocity[i] = state.velocity[i];
            state.displacement[i] = dt * state.velocity[i];
          }
    }

    /** sum_i x_i cross field_i over all nodes. */
    Tensor<1, 3>
    grid_moment(const std::vector<Tensor<1, dim>> &field) const
    {
      Tensor<1, 3> L;
      for (std::size_t i = 0; i < field.size(); ++i)
        L += cross(grid.lattice().node_position(i), field[i]);
      return L;
    }

    StepDiagnostics<dim>
    measure() const
    {
      return StepDiagnostics<dim>::measure(particles,
                                           materials,
                                           transfer,
                                           Tensor<1, dim>());
    }

    BackgroundGrid<dim>                         grid;
    ParticleSystem<dim>                         particles;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    ParticleGridTransfer<dim>                   transfer;
  };
} // namespace bfemp_tests

#endif
