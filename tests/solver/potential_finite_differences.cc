// Checks the energy terms of the incremental potential (BFEMP eq. 22) and the
// constraints of IncrementalPotential in 2D and 3D against finite
// differences:
//  - FemElasticityTerm for every material on a small perturbed box mesh: the
//    gradient against central differences of the value, and, in a stretched
//    and rotated configuration whose material tangents are PSD (so the
//    projection of projected Newton must leave them unchanged, which is
//    checked element by element), the assembled Hessian against central
//    differences of the gradient. In a strongly compressed and sheared
//    configuration the raw (unprojected) Hessian is indefinite for the
//    nonlinear models while the assembled one is PSD (LAPACK eigenvalues).
//  - MpmElasticityTerm the same way for particles in a small block on a
//    quadratic-kernel grid for every material, and on linear and cubic
//    kernels for neo-Hookean; the active grid nodes are numbered from the
//    P2G mass as in ImplicitIntegrator. F_p(u) = (I + sum_i u_i grad
//    w_ip^T) F_p^n is compared with ParticleGridTransfer::
//    update_deformation_gradient for the same u (through the energy and the
//    smallest det F).
//  - InertiaTerm: exact quadratic (value, gradient by differences, Hessian
//    diag(m), second-order Taylor expansion exact).
//  - Constraints: with one FEM node fixed (P = 0) and one on a slip plane
//    (P = I - n n^T), the projected gradient vanishes in the constrained
//    directions, the Newton direction from CHOLMOD satisfies p = P p, and
//    the constrained Hessian matches differences of the projected gradient
//    along admissible directions.
// Numbers that depend on round-off go to stdout; the output holds the checks
// and counts.

#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/cholmod_solver.h>
#include <bfemp/solver/inertia_term.h>
#include <bfemp/solver/mpm_elasticity_term.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <iostream>
#include <tuple>

#include "solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;
using bfemp_tests::check_below;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20240923);

  const double youngs_modulus = 1e5;
  const double poisson_ratio  = 0.3;

  /** A rotation by @p angle (3D: about a fixed oblique axis). */
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    Tensor<1, dim> axis;
    for (unsigned int d = 0; d < dim; ++d)
      axis[d] = d + 1.;
    return bfemp_tests::rotation(angle, axis / axis.norm());
  }

  /** The strongly compressed and sheared map x = A X. */
  template <int dim>
  Tensor<2, dim>
  crushing_map()
  {
    Tensor<2, dim> A;
    if constexpr (dim == 2)
      {
        A[0][0] = 0.6;
        A[0][1] = 0.5;
        A[1][1] = 0.7;
      }
    else
      {
        A[0][0] = 0.6;
        A[0][1] = 0.4;
        A[0][2] = 0.2;
        A[1][1] = 0.7;
        A[1][2] = 0.3;
        A[2][2] = 0.8;
      }
    return A;
  }

  /**
   * ||proj(C) - C|| / ||C|| for the tangent C = dP/dF(F) of @p material
   * and its PSD projection as the energy terms use it
   * (Material::projected_first_piola_kirchhoff_derivative).
   */
  template <int dim>
  double
  projection_change(const Material<dim> &material, const Tensor<2, dim> &F)
  {
    const Tensor<4, dim> C = material.first_piola_kirchhoff_derivative(F);
    return (material.projected_first_piola_kirchhoff_derivative(F) - C).norm() /
           C.norm();
  }

  std::string
  label(const unsigned int dim, const std::string &what)
  {
    return std::to_string(dim) + "D " + what + ": ";
  }

  /** What the value/gradient/Hessian comparison of one term found. */
  struct Comparison
  {
    double gradient_error = 0.;
    double hessian_error  = 0.;
    double min_eigenvalue = 0.;
    double max_eigenvalue = 0.;
  };

  /**
   * Value and gradient of @p term against central differences at @p u, and
   * the Hessian assembled through @p potential (only @p term, no
   * constraints) against central differences of the gradient and in its
   * eigenvalues.
   */
  template <int dim>
  Comparison
  compare(const EnergyTerm<dim>     &term,
          IncrementalPotential<dim> &potential,
          const Vector<double>      &u,
          const double               h,
          const bool                 with_hessian_differences)
  {
    Comparison     result;
    Vector<double> g(u.size());
    term.add_gradient(u, g);
    const Vector<double> g_fd = bfemp_tests::finite_difference_gradient(
      [&](const Vector<double> &v) { return term.value(v); },
      u,
      h);
    result.gradient_error = bfemp_tests::relative_difference(g_fd, g);

    const FullMatrix<double> H = bfemp_tests::dense(potential.hessian(u));
    if (with_hessian_differences)
      {
        const FullMatrix<double> H_fd = bfemp_tests::finite_difference_hessian(
          [&](const Vector<double> &v, Vector<double> &grad) {
            term.add_gradient(v, grad);
          },
          u,
          h);
        result.hessian_error = bfemp_tests::relative_difference(H, H_fd);
      }
    std::tie(result.min_eigenvalue, result.max_eigenvalue) =
      bfemp_tests::eigenvalue_range(H);
    return result;
  }



  // ------------------------------------------------------------------ FEM

  template <int dim>
  std::vector<FemBodyParameters<dim>>
  small_box(const std::string &model)
  {
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = (dim == 2 ? (d == 0 ? 1.0 : 0.6) : (d == 0 ? 0.6 : 0.4));
    return {bfemp_tests::box_body_parameters<dim>(Point<dim>(),
                                                  upper,
                                                  0.2,
                                                  model,
                                                  youngs_modulus,
                                                  poisson_ratio,
                                                  1000.)};
  }

  /** u_a = (A - I) X_a + noise of amplitude @p noise, for all FEM nodes. */
  template <int dim>
  Vector<double>
  mapped_displacement(const bfemp_tests::FemScene<dim> &scene,
                      const Tensor<2, dim>             &A,
                      const double                      noise)
  {
    Vector<double>       u(scene.dofs.n_dofs());
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    for (unsigned int a = 0; a < scene.dofs.n_nodes(); ++a)
      DofSpace<dim>::set(u,
                         a,
                         (A - I) * scene.rest_position(a) +
                           random_numbers.vector<dim>(noise));
    return u;
  }

  /** The deformation gradients of all elements at u. */
  template <int dim>
  std::vector<Tensor<2, dim>>
  element_deformation_gradients(const bfemp_tests::FemScene<dim> &scene,
                                const Vector<double>             &u)
  {
    const FemBody<dim>         &body = *scene.bodies[0];
    std::vector<Tensor<2, dim>> result;
    for (unsigned int e = 0; e < body.elements().size(); ++e)
      {
        typename SimplexElement<dim>::NodePositions x;
        for (unsigned int a = 0; a <= dim; ++a)
          {
            const unsigned int node = body.element_nodes()[e][a];
            x[a] = body.positions()[node] + DofSpace<dim>::get(u, node);
          }
        result.push_back(body.elements()[e].deformation_gradient(x));
      }
    return result;
  }

  /** Elements whose tangent the PSD projection changes by more than
   *  @p threshold (relative), and the largest relative change. */
  template <int dim>
  std::pair<unsigned int, double>
  projected_elements(const bfemp_tests::FemScene<dim> &scene,
                     const Vector<double>             &u,
                     const double                      threshold)
  {
    unsigned int n          = 0;
    double       max_change = 0.;
    for (const auto &F : element_deformation_gradients(scene, u))
      {
        const double change = projection_change(scene.bodies[0]->material(), F);
        max_change          = std::max(max_change, change);
        if (change > threshold)
          ++n;
      }
    return {n, max_change};
  }

  /** The Hessian of the FEM term with the raw (unprojected) tangents. */
  template <int dim>
  FullMatrix<double>
  raw_fem_hessian(const bfemp_tests::FemScene<dim> &scene,
                  const Vector<double>             &u)
  {
    const FemBody<dim> &body = *scene.bodies[0];
    const auto          F    = element_deformation_gradients(scene, u);
    FullMatrix<double>  H(u.size(), u.size());
    for (unsigned int e = 0; e < body.elements().size(); ++e)
      {
        const FullMatrix<double> local = body.elements()[e].hessian(
          body.material().first_piola_kirchhoff_derivative(F[e]));
        const auto &nodes = body.element_nodes()[e];
        for (unsigned int i = 0; i < local.m(); ++i)
          for (unsigned int j = 0; j < local.n(); ++j)
            H(dim * nodes[i / dim] + i % dim, dim * nodes[j / dim] + j % dim) +=
              local(i, j);
      }
    return H;
  }

  template <int dim>
  void
  check_fem(const std::string &model)
  {
    bfemp_tests::FemScene<dim> scene(small_box<dim>(model));
    scene.potential.set_terms({&scene.elasticity});
    scene.potential.setup_system();
    const std::string what = label(dim, "FEM " + model);
    deallog << what << scene.bodies[0]->elements().size() << " elements, "
            << scene.dofs.n_dofs() << " DoFs" << std::endl;
    const double h = 1e-7; // elements are 0.2 m

    // Stretched by 5 % and rotated: small strain with PSD tangents.
    {
      const Vector<double> u =
        mapped_displacement<dim>(scene, 1.05 * rotation<dim>(0.3), 0.002);
      const double     max_change = projected_elements(scene, u, 1e-8).second;
      const Comparison c          = compare<dim>(scene.elasticity,
                                        scene.potential,
                                        u,
                                        h,
                                        /*with_hessian_differences=*/true);
      const double     raw_difference =
        bfemp_tests::relative_difference(bfemp_tests::dense(
                                           scene.potential.hessian(u)),
                                         raw_fem_hessian(scene, u));
      std::cout << what << "stretched: gradient error " << c.gradient_error
                << ", Hessian error " << c.hessian_error
                << ", tangent projection change " << max_change
                << ", assembled vs raw " << raw_difference << std::endl;
      check(max_change < 1e-10,
            what + "small strain: projection leaves every tangent unchanged");
      check(raw_difference < 1e-10,
            what + "small strain: assembled Hessian = unprojected Hessian");
      check(c.gradient_error < 1e-6,
            what + "small strain: gradient matches differences of value");
      check(c.hessian_error < 1e-6,
            what + "small strain: Hessian matches differences of gradient");
    }

    // Compressed to J ~ 0.4 and sheared: projection active for the
    // nonlinear models, the assembled Hessian stays PSD.
    {
      const Vector<double> u =
        mapped_displacement<dim>(scene, crushing_map<dim>(), 0.01);
      check(scene.elasticity.minimum_determinant(u) > 0.,
            what + "compressed: all det F > 0");
      const unsigned int projected = projected_elements(scene, u, 1e-8).first;
      const Comparison   c         = compare<dim>(scene.elasticity,
                                        scene.potential,
                                        u,
                                        h,
                                        /*with_hessian_differences=*/false);
      const auto [raw_min, raw_max] =
        bfemp_tests::eigenvalue_range(raw_fem_hessian(scene, u));
      std::cout << what << "compressed: gradient error " << c.gradient_error
                << ", eigenvalues [" << c.min_eigenvalue << ", "
                << c.max_eigenvalue << "], raw [" << raw_min << ", " << raw_max
                << "], projected tangents " << projected << std::endl;
      deallog << what << "compressed: elements with projected tangent: "
              << (projected > 0 ? "some" : "none") << std::endl;
      check(c.gradient_error < 1e-6,
            what + "compressed: gradient matches differences of value");
      if (model != "linear elastic")
        check(projected > 0 && raw_min < -1e-6 * raw_max,
              what + "compressed: unprojected Hessian is indefinite");
      check(c.min_eigenvalue >= -1e-10 * c.max_eigenvalue,
            what + "compressed: assembled Hessian is PSD");
    }
  }



  // ------------------------------------------------------------------ MPM

  /**
   * A block of particles (2 per cell and direction, jittered) on the grid
   * [-1/2, 1/2]^dim with cell size 1/16, all with deformation gradient near
   * @p F_base, P2G'd so that DofSpace numbers the active grid nodes.
   */
  template <int dim>
  struct MpmScene
  {
    using Layout = ParticleLayout<dim>;

    MpmScene(const unsigned int    kernel_degree,
             const std::string    &model,
             const Tensor<2, dim> &F_base,
             const double          F_noise)
      : grid(grid_parameters(kernel_degree))
      , particles(grid)
      , materials(make_materials(model))
      , transfer(grid, TransferParameters(), materials)
      , elasticity(grid, particles, materials, dofs)
      , potential(dofs)
    {
      const double       dx    = grid.lattice().dx;
      const unsigned int n_1d  = dim == 2 ? 8 : 4; // particles per direction
      const double       begin = -0.5 * n_1d * 0.5 * dx;
      const double       V     = std::pow(0.5 * dx, dim);
      for (unsigned int k = 0; k < std::pow(n_1d, dim); ++k)
        {
          Point<dim>   x;
          unsigned int index = k;
          for (unsigned int d = 0; d < dim; ++d, index /= n_1d)
            x[d] = begin + ((index % n_1d) + 0.5) * 0.5 * dx +
                   random_numbers.uniform(-0.1, 0.1) * dx;
          std::vector<double>     properties(Layout::n_properties, 0.);
          const ArrayView<double> p = make_array_view(properties);
          p[Layout::mass]           = 1000. * V;
          p[Layout::rest_volume]    = V;
          Layout::set_tensor(p,
                             Layout::deformation_gradient,
                             F_base + random_numbers.tensor<dim>(F_noise));
          Layout::set_vector(p, Layout::initial_position, x);
          particles.insert(x, make_array_view(std::as_const(properties)));
        }
      particles.finish_insertion();

      state.reinit(grid.lattice().n_nodes);
      transfer.particles_to_grid(particles, state, false);
      dofs.reinit({}, state.mass);
      potential.set_terms({&elasticity});
      potential.setup_system();
    }

    static GridParameters<dim>
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

    static std::vector<std::unique_ptr<Material<dim>>>
    make_materials(const std::string &model)
    {
      std::vector<std::unique_ptr<Material<dim>>> result;
      result.push_back(create_material<dim>(
        model,
        ElasticModuli::from_young_poisson(youngs_modulus, poisson_ratio)));
      return result;
    }

    /** u_i = (A - I) x_i + noise on the active nodes. */
    Vector<double>
    mapped_displacement(const Tensor<2, dim> &A, const double noise) const
    {
      Vector<double>       u(dofs.n_dofs());
      const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
      for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
        DofSpace<dim>::set(u,
                           node,
                           (A - I) * grid.lattice().node_position(
                                       dofs.lattice_node(node)) +
                             random_numbers.vector<dim>(noise));
      return u;
    }

    /**
     * Moves F_p^n to F_p^n+1 with the transfer's update for the grid
     * displacement u (zero on nodes without mass) and returns
     * sum_p V_p psi(F_p^n+1), the smallest det F_p^n+1 and the largest
     * relative change of a tangent dP/dF(F_p^n+1) by the PSD projection.
     * Modifies the particles: call last.
     */
    std::array<double, 3>
    advance_deformation_gradients(const Vector<double> &u)
    {
      std::vector<Tensor<1, dim>> displacement(grid.lattice().n_nodes);
      for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
        displacement[dofs.lattice_node(node)] = DofSpace<dim>::get(u, node);
      transfer.update_deformation_gradient(particles, displacement);
      double energy = 0., min_det = 1e300, max_change = 0.;
      for (const auto &particle : particles.handler())
        {
          const auto           p = particle.get_properties();
          const Tensor<2, dim> F =
            Layout::get_tensor(p, Layout::deformation_gradient);
          energy += p[Layout::rest_volume] * materials[0]->energy_density(F);
          min_det = std::min(min_det, determinant(F));
          max_change =
            std::max(max_change, projection_change(*materials[0], F));
        }
      return {{energy, min_det, max_change}};
    }

    BackgroundGrid<dim>                         grid;
    ParticleSystem<dim>                         particles;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    ParticleGridTransfer<dim>                   transfer;
    GridState<dim>                              state;
    DofSpace<dim>                               dofs;
    MpmElasticityTerm<dim>                      elasticity;
    IncrementalPotential<dim>                   potential;
  };

  template <int dim>
  void
  check_mpm(const std::string &model, const unsigned int degree)
  {
    const std::string what =
      label(dim, "MPM degree " + std::to_string(degree) + " " + model);
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();

    // F_p^n near 1.05 R_0, u a rotation plus noise: PSD tangents.
    {
      MpmScene<dim>  scene(degree, model, 1.05 * rotation<dim>(0.2), 0.005);
      const double   dx = scene.grid.lattice().dx;
      Vector<double> u =
        scene.mapped_displacement(rotation<dim>(0.3), 0.002 * dx);
      deallog << what << scene.particles.n_particles() << " particles, "
              << scene.dofs.n_grid_nodes() << " active nodes" << std::endl;
      const Comparison c     = compare<dim>(scene.elasticity,
                                        scene.potential,
                                        u,
                                        1e-6 * dx,
                                        /*with_hessian_differences=*/true);
      const double     value = scene.elasticity.value(u);
      const double     det   = scene.elasticity.minimum_determinant(u);
      const auto [energy, min_det, max_change] =
        scene.advance_deformation_gradients(u);
      const double energy_error = std::abs(value - energy) / energy;
      const double det_error    = std::abs(det - min_det) / min_det;
      std::cout << what << "stretched: gradient error " << c.gradient_error
                << ", Hessian error " << c.hessian_error
                << ", tangent projection change " << max_change
                << ", F_p(u) energy error " << energy_error << ", det error "
                << det_error << std::endl;
      check(max_change < 1e-10,
            what + "small strain: projection leaves every tangent unchanged");
      check(c.gradient_error < 1e-6,
            what + "small strain: gradient matches differences of value");
      check(c.hessian_error < 1e-6,
            what + "small strain: Hessian matches differences of gradient");
      check(energy_error < 1e-12 && det_error < 1e-12,
            what + "small strain: F_p(u) = transfer's updated F_p");
    }

    // The step's stored stencils (MpmElasticityTerm::begin_step()) give
    // every evaluation to the bit as the stencils computed on the fly, and
    // end_step() goes back to those.
    {
      MpmScene<dim> scene(degree, model, 1.05 * rotation<dim>(0.2), 0.005);
      const double  dx = scene.grid.lattice().dx;
      const Vector<double> u =
        scene.mapped_displacement(rotation<dim>(0.3), 0.002 * dx);
      const Vector<double> p =
        scene.mapped_displacement(rotation<dim>(-0.2), 0.001 * dx);
      const auto evaluate = [&]() {
        std::vector<double> r = {scene.elasticity.value(u),
                                 scene.elasticity.step_bound(u, p),
                                 scene.elasticity.minimum_determinant(u),
                                 scene.elasticity.material_increment(p, dx)};
        Vector<double>      gradient(u.size());
        scene.elasticity.add_gradient(u, gradient);
        r.insert(r.end(), gradient.begin(), gradient.end());
        for (const HessianKind kind :
             {HessianKind::exact, HessianKind::projected})
          {
            const SparseMatrix<double> &H = scene.potential.hessian(u, kind);
            for (unsigned int row = 0; row < H.m(); ++row)
              for (auto entry = H.begin(row); entry != H.end(row); ++entry)
                r.push_back(entry->value());
          }
        return r;
      };
      const std::vector<double> computed = evaluate();
      scene.elasticity.begin_step();
      const std::vector<double> stored = evaluate();
      scene.elasticity.end_step();
      const std::vector<double> again = evaluate();
      check(computed == stored && computed == again,
            what +
              "stored stencils: value, step bound, det F, increment, "
              "gradient and both Hessians (" +
              std::to_string(computed.size()) +
              " numbers) as computed ones, to the bit");
    }

    // The Newton increment on the material points (`solver/Newton
    // increment`): a translation c moves every particle by c and leaves F
    // (partition of unity); a linear field p_i = B x_i moves particle p by
    // B x_p and F_p by B F_p^n (B-splines reproduce linear fields).
    {
      MpmScene<dim>  scene(degree, model, 1.05 * rotation<dim>(0.2), 0.005);
      const double   dx = scene.grid.lattice().dx;
      Tensor<1, dim> c;
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = 1e-3 * (d + 1.);
      const Tensor<2, dim> B = 1e-2 * (rotation<dim>(0.3) - I);
      Vector<double> translation(scene.dofs.n_dofs()), linear(translation);
      for (unsigned int node = 0; node < scene.dofs.n_nodes(); ++node)
        {
          DofSpace<dim>::set(translation, node, c);
          DofSpace<dim>::set(linear,
                             node,
                             B * scene.grid.lattice().node_position(
                                   scene.dofs.lattice_node(node)));
        }
      double expected = 0.;
      for (const auto &particle : scene.particles.handler())
        {
          const Tensor<2, dim> F = MpmScene<dim>::Layout::get_tensor(
            particle.get_properties(),
            MpmScene<dim>::Layout::deformation_gradient);
          expected =
            std::max({expected,
                      (B * Tensor<1, dim>(particle.get_location())).norm(),
                      dx * (B * F).norm()});
        }
      const double translation_error =
        std::abs(scene.elasticity.material_increment(translation, dx) -
                 c.norm()) /
        c.norm();
      const double linear_error =
        std::abs(scene.elasticity.material_increment(linear, dx) - expected) /
        expected;
      check_below(translation_error,
                  1e-12,
                  what + "material increment of a translation: relative "
                         "error against |c|");
      check_below(linear_error,
                  1e-12,
                  what + "material increment of a linear field: relative "
                         "error against max(|B x_p|, h |B F_p|)");
    }

    // F_p^n compressed and sheared, u random: projection active.
    {
      MpmScene<dim>        scene(degree, model, crushing_map<dim>(), 0.05);
      const double         dx = scene.grid.lattice().dx;
      const Vector<double> u  = scene.mapped_displacement(I, 0.02 * dx);
      check(scene.elasticity.minimum_determinant(u) > 0.,
            what + "compressed: all det F > 0");
      const Comparison c     = compare<dim>(scene.elasticity,
                                        scene.potential,
                                        u,
                                        1e-6 * dx,
                                        /*with_hessian_differences=*/false);
      const double     value = scene.elasticity.value(u);
      const auto [energy, min_det, max_change] =
        scene.advance_deformation_gradients(u);
      const double energy_error = std::abs(value - energy) / energy;
      std::cout << what << "compressed: gradient error " << c.gradient_error
                << ", eigenvalues [" << c.min_eigenvalue << ", "
                << c.max_eigenvalue << "], tangent projection change "
                << max_change << ", F_p(u) energy error " << energy_error
                << std::endl;
      check(c.gradient_error < 1e-6,
            what + "compressed: gradient matches differences of value");
      if (model != "linear elastic")
        check(max_change > 1e-6, what + "compressed: some tangent projected");
      check(c.min_eigenvalue >= -1e-10 * c.max_eigenvalue,
            what + "compressed: assembled Hessian is PSD");
      check(energy_error < 1e-12,
            what + "compressed: F_p(u) = transfer's updated F_p");
    }
  }



  // -------------------------------------------------------------- inertia

  template <int dim>
  void
  check_inertia()
  {
    const std::string  what    = label(dim, "inertia");
    const unsigned int n_nodes = 10;
    DofSpace<dim>      dofs;
    dofs.reinit({n_nodes}, {});
    std::vector<double> mass(n_nodes);
    Vector<double> predictor(dofs.n_dofs()), u(dofs.n_dofs()), p(dofs.n_dofs());
    for (double &m : mass)
      m = random_numbers.uniform(0.5, 1.5);
    for (unsigned int n = 0; n < dofs.n_dofs(); ++n)
      {
        predictor[n] = random_numbers.uniform(-1., 1.);
        u[n]         = random_numbers.uniform(-1., 1.);
        p[n]         = random_numbers.uniform(-1., 1.);
      }
    InertiaTerm<dim> inertia;
    inertia.reinit(mass, predictor);
    IncrementalPotential<dim> potential(dofs);
    potential.set_terms({&inertia});
    potential.setup_system();

    double exact = 0.;
    for (unsigned int n = 0; n < dofs.n_dofs(); ++n)
      exact += 0.5 * mass[n / dim] * std::pow(u[n] - predictor[n], 2);
    const Comparison c = compare<dim>(inertia, potential, u, 1e-3, true);

    const FullMatrix<double> H = bfemp_tests::dense(potential.hessian(u));
    FullMatrix<double>       M(dofs.n_dofs(), dofs.n_dofs());
    for (unsigned int n = 0; n < dofs.n_dofs(); ++n)
      M(n, n) = mass[n / dim];
    Vector<double> g, Hp(dofs.n_dofs()), v(u);
    potential.gradient(u, g);
    H.vmult(Hp, p);
    v += p;
    const double taylor =
      std::abs(inertia.value(v) - inertia.value(u) - g * p - 0.5 * (p * Hp)) /
      inertia.value(v);
    std::cout << what << "value error "
              << std::abs(inertia.value(u) - exact) / exact
              << ", gradient error " << c.gradient_error << ", Hessian error "
              << c.hessian_error << ", Taylor error " << taylor << std::endl;
    check(std::abs(inertia.value(u) - exact) < 1e-14 * exact,
          what + "value = 1/2 sum m |u - u^|^2");
    check(c.gradient_error < 1e-10,
          what + "gradient matches differences (exact for a quadratic)");
    check(c.hessian_error < 1e-10 &&
            bfemp_tests::relative_difference(H, M) == 0.,
          what + "Hessian = diag(m) exactly");
    check(taylor < 1e-13, what + "second-order Taylor expansion is exact");
  }



  // ---------------------------------------------------------- constraints

  template <int dim>
  void
  check_constraints()
  {
    const std::string          what = label(dim, "constraints");
    bfemp_tests::FemScene<dim> scene(small_box<dim>("neo-Hookean"));
    const unsigned int         n_dofs = scene.dofs.n_dofs();

    // A stretched, rotated configuration (PSD tangents, so the constrained
    // Hessian is the exact second derivative).
    Vector<double> u =
      mapped_displacement<dim>(scene, 1.05 * rotation<dim>(0.3), 0.002);

    const unsigned int   fixed = 0, slip = scene.dofs.n_nodes() / 2;
    Tensor<1, dim>       normal = random_numbers.vector<dim>(1.);
    const Tensor<2, dim> I      = unit_symmetric_tensor<dim>();
    normal /= normal.norm();
    const Tensor<2, dim> P_slip = I - outer_product(normal, normal);
    scene.dofs.constrain(fixed, Tensor<2, dim>(), DofSpace<dim>::get(u, fixed));
    scene.dofs.constrain(slip, P_slip, DofSpace<dim>::get(u, slip));

    Vector<double> predictor(n_dofs);
    for (double &entry : predictor)
      entry = random_numbers.uniform(-0.01, 0.01);
    InertiaTerm<dim> inertia;
    inertia.reinit(scene.node_masses(), predictor);
    scene.potential.set_terms({&inertia, &scene.elasticity});
    scene.potential.setup_system();

    Vector<double> u_imposed(u);
    scene.dofs.impose(u_imposed);
    check(bfemp_tests::relative_difference(u_imposed, u) < 1e-15,
          what + "the configuration meets the constraints");

    Vector<double> g, raw(n_dofs);
    scene.potential.gradient(u, g);
    inertia.add_gradient(u, raw);
    scene.elasticity.add_gradient(u, raw);
    const double fixed_g  = DofSpace<dim>::get(g, fixed).norm();
    const double slip_g   = std::abs(DofSpace<dim>::get(g, slip) * normal);
    double       free_err = 0.;
    for (unsigned int node = 0; node < scene.dofs.n_nodes(); ++node)
      if (node != fixed && node != slip)
        free_err = std::max(
          free_err,
          (DofSpace<dim>::get(g, node) - DofSpace<dim>::get(raw, node)).norm());
    const double tangential =
      (DofSpace<dim>::get(g, slip) - P_slip * DofSpace<dim>::get(raw, slip))
        .norm();
    std::cout << what << "|g_fixed| " << fixed_g << ", |n.g_slip| " << slip_g
              << " of ||g||_inf " << g.linfty_norm() << std::endl;
    check(fixed_g == 0. && slip_g < 1e-14 * g.linfty_norm(),
          what + "gradient is zero in the constrained directions");
    check(free_err == 0. && tangential < 1e-14 * g.linfty_norm(),
          what + "gradient is P grad E (unchanged where free)");

    // Newton direction with CHOLMOD.
    const SparseMatrix<double> &H = scene.potential.hessian(u);
    CholmodSolver               solver;
    solver.factorize(H);
    Vector<double> minus_g(g), p, residual(n_dofs);
    minus_g *= -1.;
    solver.solve(minus_g, p);
    H.residual(residual, p, minus_g);
    const double p_fixed = DofSpace<dim>::get(p, fixed).norm();
    const double p_slip  = std::abs(DofSpace<dim>::get(p, slip) * normal);
    std::cout << what << "|p_fixed| " << p_fixed << ", |n.p_slip| " << p_slip
              << " of ||p||_inf " << p.linfty_norm() << ", ||H||_inf "
              << H.linfty_norm() << ", residual "
              << residual.l2_norm() / g.l2_norm() << std::endl;
    check(residual.l2_norm() < 1e-10 * g.l2_norm(),
          what + "CHOLMOD solves H p = -g");
    // A fixed node has P = 0 exactly, so p_fixed = 0 exactly. For the
    // oblique slip plane, n^T P = O(eps) in floating point, and since
    // IncrementalPotential adds (I - P) with weight 1 next to P H P, n.p is
    // O(eps ||H||) ||p||, about 1e-12 ||p|| here (without the constraint it
    // would be O(||p||)).
    check(p_fixed == 0. && p_slip < 1e-9 * p.linfty_norm(),
          what + "Newton direction satisfies p = P p");

    // The constrained Hessian along admissible directions d = P d against
    // differences of the projected gradient.
    double max_error = 0.;
    for (unsigned int sample = 0; sample < 3; ++sample)
      {
        Vector<double> d(n_dofs), Hd(n_dofs), v(u), gp, gm;
        for (double &entry : d)
          entry = random_numbers.uniform(-1., 1.);
        scene.dofs.project(d);
        H.vmult(Hd, d);
        const double h = 1e-7;
        v.add(h, d);
        scene.potential.gradient(v, gp);
        v.add(-2. * h, d);
        scene.potential.gradient(v, gm);
        gp -= gm;
        gp /= 2. * h;
        max_error =
          std::max(max_error, bfemp_tests::relative_difference(gp, Hd));
      }
    std::cout << what << "H d vs differences " << max_error << std::endl;
    check(max_error < 1e-6,
          what + "P H P + (I - P) matches differences along d = P d");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  const std::vector<std::string> models = {"neo-Hookean",
                                           "linear elastic",
                                           "fixed corotated"};
  for (const std::string &model : models)
    check_fem<2>(model);
  for (const std::string &model : models)
    check_fem<3>(model);

  for (const std::string &model : models)
    check_mpm<2>(model, 2);
  check_mpm<2>("neo-Hookean", 1);
  check_mpm<2>("neo-Hookean", 3);
  for (const std::string &model : models)
    check_mpm<3>(model, 2);
  check_mpm<3>("neo-Hookean", 1);
  check_mpm<3>("neo-Hookean", 3);

  check_inertia<2>();
  check_inertia<3>();
  check_constraints<2>();
  check_constraints<3>();
}
