// A static FEM cantilever against Euler-Bernoulli beam theory: a neo-Hookean
// beam of length L = 1 m and height h = L / 20 in 2D plane strain, clamped
// at x = 0 (node constraints P = 0) and loaded by its own weight as a dead
// load f_a = m_a g (a uniform load q = rho h g per unit length and unit
// thickness), solved by NewtonSolver on the IncrementalPotential
// Psi(u) - f.u (no inertia, dt = 1). The tip deflection of the node on the
// neutral axis is compared with w = q L^4 / (8 E' I), with the plane-strain
// modulus E' = E / (1 - nu^2) and I = h^3 / 12; w / L = 5e-4, so geometric
// nonlinearity changes w by O(1e-7).
//
// Linear triangles are stiff in bending, so the FEM deflection approaches
// the theory from below: with 2, 4, 8, 16 elements through the height
// (squares of side h / n split into 2 triangles; errors about -48 %, -19 %,
// -5.6 %, -1.4 %) the error must decrease monotonically, about as h^2, and
// be below 2 % on the finest mesh. (Shear deformation, neglected by
// Euler-Bernoulli, adds about +0.3 % at L / h = 20: (E' / (3 kappa G))
// (h / L)^2 with kappa = 5/6, so the error would level off near +0.3 %
// on much finer meshes.)

#include <bfemp/solver/newton_solver.h>
#include <bfemp/solver/solver_parameters.h>

#include <iostream>

#include "solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;

namespace
{
  const double length         = 1.;
  const double height         = length / 20.;
  const double youngs_modulus = 1e10;
  const double poisson_ratio  = 0.3;
  const double density        = 1000.;
  const double gravity        = 9.81;

  /** Euler-Bernoulli tip deflection of the cantilever under q = rho h g. */
  double
  theory()
  {
    const double q = density * height * gravity;
    const double E_prime =
      youngs_modulus / (1. - poisson_ratio * poisson_ratio);
    const double I = std::pow(height, 3) / 12.;
    return q * std::pow(length, 4) / (8. * E_prime * I);
  }

  /** The FEM tip deflection with @p n elements through the height. */
  double
  tip_deflection(const unsigned int n)
  {
    bfemp_tests::FemScene<2> scene(
      {bfemp_tests::box_body_parameters<2>(Point<2>(0., 0.),
                                           Point<2>(length, height),
                                           height / n,
                                           "neo-Hookean",
                                           youngs_modulus,
                                           poisson_ratio,
                                           density)});
    const unsigned int n_clamped = scene.clamp(0);

    bfemp_tests::DeadLoadTerm<2> load(scene.dofs.n_dofs());
    const std::vector<double>    masses = scene.node_masses();
    for (unsigned int a = 0; a < masses.size(); ++a)
      {
        Tensor<1, 2> weight;
        weight[1] = -masses[a] * gravity;
        load.add_force(a, weight);
      }
    scene.potential.set_terms({&scene.elasticity, &load});
    scene.potential.setup_system();

    // Newton stops when the last correction is below 1e-6 of the expected
    // deflection, far below the digits printed. (The round-off floor of
    // ||p||_inf is about 1e-8 of the deflection on the finest mesh, whose
    // stiffness matrix has a condition number near 1e8: a tolerance of
    // 1e-8 w is not reachable there.)
    SolverParameters parameters;
    parameters.newton_tolerance = 1e-6 * theory();
    parameters.linear_solver    = "CHOLMOD";
    parameters.check_invariants = true;
    NewtonSolver<2>        newton(parameters);
    Vector<double>         u(scene.dofs.n_dofs());
    const NewtonStatistics statistics =
      newton.minimize(scene.potential, u, 1., "cantilever");

    // The tip node on the neutral axis, (L, h / 2).
    unsigned int tip = 0;
    for (unsigned int a = 1; a < scene.dofs.n_nodes(); ++a)
      if (scene.rest_position(a).distance(Point<2>(length, height / 2.)) <
          scene.rest_position(tip).distance(Point<2>(length, height / 2.)))
        tip = a;
    check(scene.rest_position(tip).distance(Point<2>(length, height / 2.)) <
            1e-12,
          std::to_string(n) + " elements through the height: a node at "
                              "(L, h/2)");

    std::cout << n << " elements through the height: "
              << scene.bodies[0]->elements().size() << " triangles, "
              << n_clamped << " clamped nodes, " << statistics.iterations
              << " Newton iterations, residual " << statistics.residual
              << " m, tip deflection " << -u[2 * tip + 1] << " m" << std::endl;
    deallog << n << " elements through the height: "
            << scene.bodies[0]->elements().size() << " triangles, " << n_clamped
            << " clamped nodes" << std::endl;
    return -u[2 * tip + 1];
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  const double w = theory();
  deallog << "Euler-Bernoulli tip deflection " << bfemp_tests::fixed(w * 1e6, 3)
          << " um" << std::endl;

  std::vector<double> errors;
  for (const unsigned int n : {2u, 4u, 8u, 16u})
    {
      const double w_fem = tip_deflection(n);
      errors.push_back((w_fem - w) / w);
      deallog << n << " elements through the height: tip deflection "
              << bfemp_tests::fixed(w_fem * 1e6, 2) << " um, relative error "
              << bfemp_tests::fixed(100. * errors.back(), 2) << " %"
              << std::endl;
    }

  bool monotone = true;
  for (unsigned int k = 1; k < errors.size(); ++k)
    monotone = monotone && std::abs(errors[k]) < std::abs(errors[k - 1]);
  const unsigned int n     = errors.size();
  const double       order = std::log2(errors[n - 2] / errors[n - 1]);
  deallog << "observed order of the last refinement "
          << bfemp_tests::fixed(order, 2) << std::endl;
  check(monotone, "the error decreases with every refinement");
  check(errors.back() < 0. && std::abs(errors.back()) < 0.02,
        "the finest mesh is within 2 % of Euler-Bernoulli, from below");
  check(order > 1.5, "the error falls about as h^2 (order > 1.5)");
}
