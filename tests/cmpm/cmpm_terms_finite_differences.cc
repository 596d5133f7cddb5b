// The energy terms of a cMPM step (seed 002 on the implicit solver) against
// finite differences, 2D and 3D, on a block of particles of two materials
// (one half 100 times stiffer) over 2^dim coarse elements (boundary
// B-spline, L = H/2, n = 5):
// - the MPM elasticity through the matrix-valued map (MpmElasticityTerm
//   with CmpmDiscretization): gradient against central differences of the
//   value, Hessian against central differences of the gradient (whole
//   matrices in 2D, 10 random directions in 3D), with F_p^n
//   near a stretched rotation so that every tangent is PSD (projection
//   inactive), and its forces sum to zero over the coarse nodes (partition
//   of unity: no net internal force);
// - the consistent inertia over the particles (CmpmInertiaTerm): gradient
//   and Hessian the same way; both Hessians PSD (2D eigenvalues);
// - both terms against the direct sums over the particles through the
//   matrix-valued Phi_I and grad Phi_I (CmpmDiscretization::evaluate): the
//   terms integrate on each element's fine patch and condense with p once
//   per element, which must give the same value, gradient and Hessian to
//   round-off;
// - P2G and G2P through Phi: P2G keeps the total momentum, and a uniform
//   coarse velocity V with u = dt V moves every particle by dt V with
//   velocity V and leaves F_p unchanged.
// All of it again with `cmpm/interior modes = body load` (one element-owned
// unknown per element, doc/cmpm.md): the same checks, with the sums of
// forces, momentum and the translation over the coarse lattice nodes (a
// mode is no part of a translation); and the modes are checked to leave
// the lattice nodes' shape functions unchanged at every particle.
// Round-off dependent numbers go to stdout; the output holds the checks.

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/cmpm/cmpm_inertia_term.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/mpm_elasticity_term.h>

#include <cstdio>
#include <iostream>
#include <tuple>

#include "cmpm/particle_block.h"
#include "cmpm/term_derivatives.h"
#include "solver/solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(31415);

  template <int dim>
  Tensor<2, dim>
  stretched_rotation()
  {
    Tensor<2, dim> R = unit_symmetric_tensor<dim>();
    R[0][0] = R[1][1] = std::cos(0.2);
    R[0][1]           = -std::sin(0.2);
    R[1][0]           = std::sin(0.2);
    return 1.05 * R;
  }

  template <int dim>
  struct Scene
  {
    using Layout = ParticleLayout<dim>;

    static CmpmParameters
    parameters(const bool interior_modes)
    {
      CmpmParameters prm = bfemp_tests::cmpm_with_fine_nodes(5);
      if (interior_modes)
        prm.interior_modes = CmpmParameters::InteriorModes::body_load;
      return prm;
    }

    explicit Scene(const bool interior_modes)
      : grid(bfemp_tests::unit_box_grid<dim>(0.25))
      , particles(grid)
      , cmpm(grid, parameters(interior_modes))
      , elasticity(grid, particles, materials, dofs, &cmpm)
      , inertia(particles, cmpm, dofs)
      , potential_elasticity(dofs)
      , potential_inertia(dofs)
    {
      materials.push_back(
        create_material<dim>("neo-Hookean",
                             ElasticModuli::from_young_poisson(1e5, 0.3)));
      materials.push_back(
        create_material<dim>("neo-Hookean",
                             ElasticModuli::from_young_poisson(1e7, 0.3)));
      // a block over 2^dim elements of H = 0.25, 2 particles per knot span
      const double h = 0.5 / 12;
      Point<dim>   lower;
      for (unsigned int d = 0; d < dim; ++d)
        lower[d] = 0.25;
      bfemp_tests::insert_particle_block<dim>(
        particles,
        lower,
        h,
        bfemp_tests::cube_counts<dim>(12),
        1000.,
        [&](Point<dim> &x, const ArrayView<double> &p) {
          for (unsigned int d = 0; d < dim; ++d)
            x[d] += random_numbers.uniform(-0.1, 0.1) * h;
          p[Layout::material_id] = x[0] < 0.5 ? 1 : 0;
          Layout::set_tensor(p,
                             Layout::deformation_gradient,
                             stretched_rotation<dim>() +
                               random_numbers.tensor<dim>(0.005));
          Layout::set_vector(p,
                             Layout::velocity,
                             random_numbers.vector<dim>(1.));
        });
      particles.finish_insertion();
      cmpm.reinit(particles, materials);
      cmpm.particles_to_grid(particles, state);
      // the activity filter of ImplicitIntegrator for cMPM
      double max_mass = 0.;
      for (const double m : state.mass)
        max_mass = std::max(max_mass, m);
      for (double &m : state.mass)
        if (m <= 1e-8 * max_mass)
          m = 0.;
      dofs.reinit({}, state.mass);
      inertia.reinit(1e-2, 1e-4, Tensor<1, dim>());
      potential_elasticity.set_terms({&elasticity});
      potential_elasticity.setup_system();
      potential_inertia.set_terms({&inertia});
      potential_inertia.setup_system();
    }

    Vector<double>
    random_displacement(const double amplitude)
    {
      Vector<double> u(dofs.n_dofs());
      for (unsigned int i = 0; i < u.size(); ++i)
        u[i] = random_numbers.uniform(-amplitude, amplitude);
      return u;
    }

    BackgroundGrid<dim>                         grid;
    ParticleSystem<dim>                         particles;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    CmpmDiscretization<dim>                     cmpm;
    GridState<dim>                              state;
    DofSpace<dim>                               dofs;
    MpmElasticityTerm<dim>                      elasticity;
    CmpmInertiaTerm<dim>                        inertia;
    IncrementalPotential<dim>                   potential_elasticity;
    IncrementalPotential<dim>                   potential_inertia;
  };

  /**
   * The two terms' value, gradient and Hessian summed particle by particle
   * through the matrix-valued shape functions, the definition (seed 002
   * eqs. 15-16; BFEMP eq. 22 with F_p(u) = (I + sum_I grad(Phi_I u_I))
   * F_p^n): the reference of the element-condensed assembly.
   */
  template <int dim>
  struct DirectSums
  {
    double             elastic_energy = 0., kinetic_energy = 0.;
    Vector<double>     elastic_gradient, kinetic_gradient;
    FullMatrix<double> elastic_hessian, kinetic_hessian;
  };

  template <int dim>
  DirectSums<dim>
  direct_sums(Scene<dim> &scene, const Vector<double> &u)
  {
    using Layout = ParticleLayout<dim>;
    DirectSums<dim>    sums;
    const unsigned int n = u.size();
    sums.elastic_gradient.reinit(n);
    sums.kinetic_gradient.reinit(n);
    sums.elastic_hessian.reinit(n, n);
    sums.kinetic_hessian.reinit(n, n);
    std::vector<CoarseShapeValue<dim>> values;
    for (const auto &particle : scene.particles.handler())
      {
        scene.cmpm.evaluate(particle.get_location(), values);
        const auto           p = particle.get_properties();
        const Tensor<2, dim> F_n =
          Layout::get_tensor(p, Layout::deformation_gradient);
        const Material<dim> &material =
          *scene.materials[static_cast<unsigned int>(p[Layout::material_id])];
        // dF_ab/du_Ic = sum_e d(Phi_I)_ac/dx_e (F_n)_eb, and Phi_I itself
        std::vector<unsigned int>   dofs;
        std::vector<Tensor<2, dim>> dF, Phi;
        for (const CoarseShapeValue<dim> &value : values)
          {
            const unsigned int node = scene.dofs.grid_node(value.node);
            if (node == DofSpace<dim>::invalid)
              continue;
            for (unsigned int c = 0; c < dim; ++c)
              {
                Tensor<2, dim> D;
                for (unsigned int a = 0; a < dim; ++a)
                  D[a] = transpose(F_n) * value.gradient[a][c];
                Tensor<2, dim> Phi_c;
                for (unsigned int a = 0; a < dim; ++a)
                  Phi_c[a][0] = value.value[a][c];
                dofs.push_back(dim * node + c);
                dF.push_back(D);
                Phi.push_back(Phi_c);
              }
          }
        Tensor<2, dim> F = F_n;
        Tensor<1, dim> r = -(1e-2 * Layout::get_vector(p, Layout::velocity));
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            F += u[dofs[i]] * dF[i];
            for (unsigned int a = 0; a < dim; ++a)
              r[a] += u[dofs[i]] * Phi[i][a][0];
          }
        const double         V = p[Layout::rest_volume];
        const double         m = p[Layout::mass];
        const Tensor<2, dim> P = material.first_piola_kirchhoff(F);
        const Tensor<4, dim> A = material.tangent(F, true);
        sums.elastic_energy += V * material.energy_density(F);
        sums.kinetic_energy += 0.5 * m * r.norm_square();
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            sums.elastic_gradient[dofs[i]] += V * scalar_product(P, dF[i]);
            double Phi_r = 0.;
            for (unsigned int a = 0; a < dim; ++a)
              Phi_r += Phi[i][a][0] * r[a];
            sums.kinetic_gradient[dofs[i]] += m * Phi_r;
            const Tensor<2, dim> A_dF = double_contract<2, 0, 3, 1>(A, dF[i]);
            for (unsigned int j = 0; j < dofs.size(); ++j)
              {
                sums.elastic_hessian(dofs[i], dofs[j]) +=
                  V * scalar_product(A_dF, dF[j]);
                double Phi_Phi = 0.;
                for (unsigned int a = 0; a < dim; ++a)
                  Phi_Phi += Phi[i][a][0] * Phi[j][a][0];
                sums.kinetic_hessian(dofs[i], dofs[j]) += m * Phi_Phi;
              }
          }
      }
    return sums;
  }

  /** Compares a term with its direct sums; returns the largest relative
   *  difference of value, gradient and Hessian. */
  template <int dim>
  double
  compare_with_direct(const std::string         &what,
                      const EnergyTerm<dim>     &term,
                      IncrementalPotential<dim> &potential,
                      const Vector<double>      &u,
                      const double               energy,
                      const Vector<double>      &gradient,
                      const FullMatrix<double>  &hessian)
  {
    Vector<double> g(u.size());
    term.add_gradient(u, g);
    const double value_error =
      std::abs(term.value(u) - energy) / std::abs(energy);
    const double gradient_error = bfemp_tests::relative_difference(g, gradient);
    const double hessian_error =
      bfemp_tests::relative_difference(bfemp_tests::dense(potential.hessian(u)),
                                       hessian);
    std::cout << what << " against the direct sums through Phi: value "
              << value_error << ", gradient " << gradient_error << ", Hessian "
              << hessian_error << std::endl;
    const double largest =
      std::max({value_error, gradient_error, hessian_error});
    check(largest < 1e-11,
          what + ": value, gradient and Hessian equal the direct sums "
                 "through Phi to 1e-11");
    return largest;
  }

  /** Whether DoF node @p node is a lattice node (not an interior mode). */
  template <int dim>
  bool
  is_lattice_node(const Scene<dim> &scene, const unsigned int node)
  {
    return node < scene.dofs.n_fem_nodes() ||
           scene.dofs.lattice_node(node) <
             scene.cmpm.coarse_grid().node_lattice().n_nodes;
  }

  template <int dim>
  void
  test(const bool interior_modes)
  {
    using Layout = ParticleLayout<dim>;
    const std::string name =
      std::to_string(dim) + "D " + (interior_modes ? "modes " : "");
    const bfemp_tests::RandomNumbers start = random_numbers;
    Scene<dim>                       scene(interior_modes);
    unsigned int                     n_modes = 0;
    for (unsigned int node = 0; node < scene.dofs.n_nodes(); ++node)
      n_modes += is_lattice_node(scene, node) ? 0 : 1;
    deallog << name << scene.particles.n_particles() << " particles, "
            << scene.dofs.n_grid_nodes() << " coarse nodes as unknowns";
    if (interior_modes)
      deallog << " (" << n_modes << " of them interior-mode nodes)";
    deallog << std::endl;
    if (interior_modes)
      {
        check(n_modes == (1u << dim),
              name + "each of the 2^dim elements with particles holds an "
                     "interior-mode node");
        // the lattice nodes' Phi_I are those without modes at every particle
        // (the same particles: the scene's random numbers again)
        const bfemp_tests::RandomNumbers after = random_numbers;
        random_numbers                         = start;
        Scene<dim> plain(false);
        random_numbers = after;
        std::vector<CoarseShapeValue<dim>> with, without;
        double                             difference = 0.;
        for (const auto &particle : scene.particles.handler())
          {
            scene.cmpm.evaluate(particle.get_location(), with);
            plain.cmpm.evaluate(particle.get_location(), without);
            for (unsigned int I = 0; I < without.size(); ++I)
              difference =
                std::max(difference,
                         (with[I].value - without[I].value).norm() +
                           (with[I].gradient - without[I].gradient).norm());
          }
        check(difference == 0.,
              name + "the lattice nodes' Phi_I and grad Phi_I are unchanged");
      }

    const Vector<double> u = scene.random_displacement(2e-4);
    bfemp_tests::check_term<dim>(name + "cMPM elasticity",
                                 scene.elasticity,
                                 scene.potential_elasticity,
                                 u,
                                 1e-7,
                                 random_numbers);
    bfemp_tests::check_term<dim>(name + "cMPM inertia",
                                 scene.inertia,
                                 scene.potential_inertia,
                                 u,
                                 1e-7,
                                 random_numbers);

    // the element-condensed assembly against the direct sums
    {
      const DirectSums<dim> sums = direct_sums(scene, u);
      compare_with_direct<dim>(name + "cMPM elasticity",
                               scene.elasticity,
                               scene.potential_elasticity,
                               u,
                               sums.elastic_energy,
                               sums.elastic_gradient,
                               sums.elastic_hessian);
      compare_with_direct<dim>(name + "cMPM inertia",
                               scene.inertia,
                               scene.potential_inertia,
                               u,
                               sums.kinetic_energy,
                               sums.kinetic_gradient,
                               sums.kinetic_hessian);
    }

    // no net internal force: sum over nodes of dE/du_I = 0
    Vector<double> g(u.size());
    scene.elasticity.add_gradient(u, g);
    Tensor<1, dim> net;
    double         largest = 0.;
    for (unsigned int node = 0; node < scene.dofs.n_nodes(); ++node)
      if (is_lattice_node(scene, node))
        {
          net += DofSpace<dim>::get(g, node);
          largest = std::max(largest, DofSpace<dim>::get(g, node).norm());
        }
    char force[80];
    std::snprintf(force, sizeof(force), "largest nodal force %.4g", largest);
    deallog << name << force << std::endl;
    std::cout << name << "net internal force " << net.norm() << " of "
              << largest << std::endl;
    check(net.norm() < 1e-10 * largest,
          name + "the elastic forces sum to zero over the coarse nodes");

    // P2G keeps the momentum
    Tensor<1, dim> particle_momentum, grid_momentum;
    for (const auto &particle : scene.particles.handler())
      {
        const auto p = particle.get_properties();
        particle_momentum +=
          p[Layout::mass] * Layout::get_vector(p, Layout::velocity);
      }
    GridState<dim>    state;
    const std::size_t n_lattice =
      scene.cmpm.coarse_grid().node_lattice().n_nodes;
    scene.cmpm.particles_to_grid(scene.particles, state);
    for (std::size_t i = 0; i < n_lattice; ++i)
      grid_momentum += state.velocity[i];
    check((grid_momentum - particle_momentum).norm() <
            1e-12 * particle_momentum.norm(),
          name + "P2G: sum_I sum_p m_p Phi_Ip^T v_p = sum_p m_p v_p");

    // G2P of a uniform coarse velocity: a translation
    Tensor<1, dim> V;
    for (unsigned int d = 0; d < dim; ++d)
      V[d] = 0.3 - 0.2 * d;
    const double dt = 0.01;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      {
        // (interior modes at rest: a translation moves the lattice only)
        state.new_velocity[i] = i < n_lattice ? V : Tensor<1, dim>();
        state.displacement[i] = i < n_lattice ? dt * V : Tensor<1, dim>();
      }
    std::vector<Point<dim>>     before;
    std::vector<Tensor<2, dim>> F_before;
    for (const auto &particle : scene.particles.handler())
      {
        before.push_back(particle.get_location());
        F_before.push_back(Layout::get_tensor(particle.get_properties(),
                                              Layout::deformation_gradient));
      }
    TransferParameters pic;
    pic.scheme = TransferParameters::Scheme::pic;
    scene.cmpm.grid_to_particles(scene.particles, state, pic);
    double       position_error = 0., velocity_error = 0., F_error = 0.;
    unsigned int q = 0;
    for (const auto &particle : scene.particles.handler())
      {
        const auto p = particle.get_properties();
        position_error =
          std::max(position_error,
                   (particle.get_location() - before[q] - dt * V).norm());
        velocity_error =
          std::max(velocity_error,
                   (Layout::get_vector(p, Layout::velocity) - V).norm());
        F_error =
          std::max(F_error,
                   (Layout::get_tensor(p, Layout::deformation_gradient) -
                    F_before[q])
                     .norm());
        ++q;
      }
    check(position_error < 1e-14 && velocity_error < 1e-12 && F_error < 1e-12,
          name + "G2P of a uniform coarse velocity translates every particle "
                 "and keeps F_p");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  for (const bool interior_modes : {false, true})
    {
      test<2>(interior_modes);
      test<3>(interior_modes);
    }
}
