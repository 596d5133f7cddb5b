// A force-free step (v~_i = v_i, u_i = dt v_i): FLIP (Table 3, no PIC blend)
// adds the grid increment sum_i w_ip (v~_i - v_i) = 0, so every particle keeps
// its velocity and the kinetic energy is unchanged; PIC (Table 2) replaces the
// velocities by their grid average and strictly loses kinetic energy for
// random velocities. Linear, quadratic and cubic kernels, 2D and 3D.

#include <cmath>
#include <map>
#include <string>

#include "tests.h"
#include "transfer_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::TransferScene;

namespace
{
  template <int dim>
  std::map<types::particle_index, Tensor<1, dim>>
  velocities(const ParticleSystem<dim> &particles)
  {
    std::map<types::particle_index, Tensor<1, dim>> v;
    for (const auto &particle : particles.handler())
      v[particle.get_id()] =
        ParticleLayout<dim>::get_vector(particle.get_properties(),
                                        ParticleLayout<dim>::velocity);
    return v;
  }

  /** Kinetic energy before and after a force-free step. */
  template <int dim>
  std::pair<double, double>
  step(TransferScene<dim> &scene)
  {
    const double   before = scene.measure().kinetic_energy;
    GridState<dim> state  = scene.particles_to_grid();
    TransferScene<dim>::free_flight(state, 1e-3);
    scene.transfer.grid_to_particles(scene.particles, state, true);
    return {before, scene.measure().kinetic_energy};
  }

  template <int dim>
  void
  test(const unsigned int degree)
  {
    const std::string name =
      std::to_string(dim) + "D degree " + std::to_string(degree) + " ";
    const unsigned int n_particles = dim == 2 ? 300 : 150;

    {
      TransferScene<dim> scene(degree, TransferParameters::Scheme::flip);
      scene.insert_random(n_particles, false);
      const auto v_before   = velocities(scene.particles);
      const auto [E0, E1]   = step(scene);
      const auto v_after    = velocities(scene.particles);
      double     max_change = 0.;
      for (const auto &[id, v] : v_before)
        max_change = std::max(max_change, (v_after.at(id) - v).norm());
      bfemp_tests::check(v_after.size() == n_particles && max_change < 1e-15,
                         name + "FLIP: every particle keeps its velocity");
      bfemp_tests::check(std::abs(E1 - E0) < 1e-13 * E0,
                         name + "FLIP: kinetic energy unchanged");
    }
    {
      TransferScene<dim> scene(degree, TransferParameters::Scheme::pic);
      scene.insert_random(n_particles, false);
      const auto [E0, E1] = step(scene);
      dealii::deallog << name << "PIC: kinetic energy ratio "
                      << bfemp_tests::two_decimals(E1 / E0) << std::endl;
      bfemp_tests::check(E1 < E0, name + "PIC: kinetic energy decreases");
    }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (unsigned int degree = 1; degree <= 3; ++degree)
    {
      test<2>(degree);
      test<3>(degree);
    }
}
