// Finite-difference checks of the contact terms of the incremental
// potential over the unified unknowns (grid nodes and FEM nodes), in 2D and
// 3D: the barrier potential of eqs. 31 / 32 with its duplicate subtraction,
// carried to the grid by the chain rule of eq. 29, and the lagged friction
// pseudo-potential of eq. 37.
//
// Scene: a jittered block of particles (2 per cell and direction, grid
// cell 1/16) hovering over the top face of a deformable FEM box with
// particles between 0.1 dhat and 1.2 dhat from it, so that facet, edge
// (3D) and vertex terms are all active, dhat = 0.02. At a random u near 0
// (grid and FEM nodes moved by up to 1e-4):
//  - gradient vs central differences of the value (h = 1e-7);
//  - the raw (unprojected) Hessian vs central differences of the gradient;
//  - the projected Hessian is PSD (smallest eigenvalue >= -1e-10 |H|);
//  - friction (mu = 0.5, lagged at the start, u = 0, evaluated at a
//    sliding displacement well beyond eps_v dt and once inside the static
//    zone): gradient and Hessian vs differences (the Hessian error relative
//    to max(|H_fd|, |grad D| / sliding), since 2D kinetic friction has
//    H = 0); its Hessian is PSD without projection.
// The same checks run with the MPM side discretized by cMPM (seed 002:
// coarse elements H = 1/8, n = 5, boundary B-spline, L = H), where the
// chain rule's factors are the matrix-valued Phi_I(x_q) instead of w_iq I
// (ChainRule): the barrier and friction terms are the same code.
// Relative errors are printed against stated tolerances.

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/contact/barrier_term.h>
#include <bfemp/contact/contact_geometry.h>
#include <bfemp/contact/friction_term.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include "../solver/solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using namespace bfemp_tests;

namespace
{
  RandomNumbers random_numbers(20261121);

  template <int dim>
  struct ContactScene
  {
    using Layout = ParticleLayout<dim>;

    ContactScene(const double dhat, const bool with_cmpm)
      : grid(grid_parameters(with_cmpm))
      , particles(grid)
      , materials(make_materials())
      , transfer(grid, TransferParameters(), materials)
      , bodies(FemScene<dim>::make_bodies(
          {box_body_parameters<dim>(corner<dim>(-0.3, -0.45),
                                    corner<dim>(0.3, -0.2),
                                    dim == 2 ? 0.1 : 0.15,
                                    "neo-Hookean",
                                    1e6,
                                    0.3,
                                    1000.)}))
    {
      parameters.activation_distance          = dhat;
      parameters.barrier_stiffness            = 1e4;
      parameters.default_friction_coefficient = 0.5;
      parameters.static_friction_velocity     = 1e-3;

      const double       dx   = 1. / 16.; // particles 2 per dx
      const unsigned int n_1d = dim == 2 ? 12 : 6;
      const double       V    = std::pow(0.5 * dx, dim);
      for (unsigned int k = 0; k < std::pow(n_1d, dim); ++k)
        {
          Point<dim>   x;
          unsigned int index = k;
          unsigned int layer = 0;
          for (unsigned int d = 0; d < dim; ++d, index /= n_1d)
            {
              x[d] = -0.5 * n_1d * 0.5 * dx +
                     ((index % n_1d) + 0.5) * 0.5 * dx +
                     random_numbers.uniform(-0.1, 0.1) * dx;
              if (d == 1)
                layer = index % n_1d;
            }
          // The bottom layer within 0.1 .. 1.2 dhat of the face y = -0.2,
          // the others above it.
          x[1] = layer == 0 ? -0.2 + random_numbers.uniform(0.1, 1.2) * dhat
                            : -0.2 + 1.5 * dhat + layer * 0.5 * dx;
          std::vector<double>     properties(Layout::n_properties, 0.);
          const ArrayView<double> p = make_array_view(properties);
          p[Layout::mass]           = 1000. * V;
          p[Layout::rest_volume]    = V;
          Layout::set_tensor(p,
                             Layout::deformation_gradient,
                             unit_symmetric_tensor<dim>());
          particles.insert(x, make_array_view(std::as_const(properties)));
        }
      particles.finish_insertion();
      if (with_cmpm)
        {
          CmpmParameters cmpm_parameters;
          cmpm_parameters.enabled = true;
          cmpm_parameters.n_fine  = 5;
          cmpm =
            std::make_unique<CmpmDiscretization<dim>>(grid, cmpm_parameters);
          cmpm->reinit(particles, materials);
          cmpm->particles_to_grid(particles, state);
          // the activity filter of ImplicitIntegrator for cMPM
          const double largest =
            *std::max_element(state.mass.begin(), state.mass.end());
          for (double &m : state.mass)
            if (m <= 1e-8 * largest)
              m = 0.;
        }
      else
        {
          state.reinit(grid.lattice().n_nodes);
          transfer.particles_to_grid(particles, state, false);
        }
      dofs.reinit({bodies[0]->n_nodes()}, state.mass);
      geometry = std::make_unique<ContactGeometry<dim>>(grid,
                                                        particles,
                                                        bodies,
                                                        dofs,
                                                        cmpm.get());
      geometry->begin_step(0.);
    }

    template <int d>
    static Point<d>
    corner(const double x, const double y)
    {
      Point<d> p;
      for (unsigned int c = 0; c < d; ++c)
        p[c] = x;
      p[1] = y;
      return p;
    }

    static GridParameters<dim>
    grid_parameters(const bool with_cmpm)
    {
      GridParameters<dim> parameters;
      for (unsigned int d = 0; d < dim; ++d)
        {
          parameters.lower_corner[d] = -0.5;
          parameters.upper_corner[d] = 0.5;
        }
      parameters.cell_size     = with_cmpm ? 1. / 8. : 1. / 16.;
      parameters.kernel_degree = 2;
      return parameters;
    }

    static std::vector<std::unique_ptr<Material<dim>>>
    make_materials()
    {
      std::vector<std::unique_ptr<Material<dim>>> result;
      result.push_back(
        create_material<dim>("neo-Hookean",
                             ElasticModuli::from_young_poisson(1e5, 0.3)));
      return result;
    }

    Vector<double>
    random_displacement(const double amplitude) const
    {
      Vector<double> u(dofs.n_dofs());
      for (double &v : u)
        v = random_numbers.uniform(-amplitude, amplitude);
      return u;
    }

    BackgroundGrid<dim>                         grid;
    ParticleSystem<dim>                         particles;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    ParticleGridTransfer<dim>                   transfer;
    std::vector<std::unique_ptr<FemBody<dim>>>  bodies;
    GridState<dim>                              state;
    DofSpace<dim>                               dofs;
    ContactParameters                           parameters;
    std::unique_ptr<CmpmDiscretization<dim>>    cmpm;
    std::unique_ptr<ContactGeometry<dim>>       geometry;
  };



  /** The assembled Hessian of @p term at u as a dense matrix. */
  template <int dim>
  FullMatrix<double>
  assembled_hessian(const EnergyTerm<dim>  &term,
                    const BarrierTerm<dim> &registry,
                    const DofSpace<dim>    &dofs,
                    const Vector<double>   &u,
                    const HessianKind       kind = HessianKind::projected)
  {
    // The barrier term holds the couplings of barrier and friction pairs.
    NodeSparsity sparsity(dofs.n_nodes());
    registry.add_couplings(sparsity);
    SparsityPattern pattern;
    sparsity.build(dim, pattern);
    SparseMatrix<double> matrix(pattern);
    term.add_hessian(u, matrix, kind);
    return dense(matrix);
  }



  /** "2D" or "2D cMPM": the prefix of a scene's lines. */
  std::string label;

  template <int dim>
  void
  report(const std::string &what, const double error, const double tolerance)
  {
    deallog << label << " " << what << ": "
            << (error <= tolerance ? "ok"
                                   : "FAILED (" + std::to_string(error) + ")")
            << " (tolerance " << tolerance << ")" << std::endl;
  }



  template <int dim>
  void
  check(const bool with_cmpm)
  {
    label = std::to_string(dim) + "D" + (with_cmpm ? " cMPM" : "");
    const double         dhat = 0.02;
    ContactScene<dim>    scene(dhat, with_cmpm);
    BarrierTerm<dim>     barrier(*scene.geometry, scene.parameters);
    const Vector<double> u = scene.random_displacement(1e-4);
    barrier.begin_step(u);

    const auto   contacts      = barrier.contacts(u);
    unsigned int n_facet_terms = 0;
    for (const auto &c : contacts)
      n_facet_terms += c.nodes.size();
    deallog << label << " particles in contact: " << contacts.size() << " ("
            << (contacts.size() > (dim == 2 ? 8u : 20u) ? "enough" : "too few")
            << "), FEM nodes per stencil > " << dim << ": "
            << (n_facet_terms > dim * contacts.size() ? "yes" : "no") << " ("
            << n_facet_terms << " in all), unknowns: " << u.size() << std::endl;

    const auto value = [&](const Vector<double> &v) {
      return barrier.value(v);
    };
    const auto gradient = [&](const Vector<double> &v, Vector<double> &g) {
      barrier.add_gradient(v, g);
    };
    Vector<double> g(u.size());
    gradient(u, g);
    report<dim>("barrier gradient",
                relative_difference(g,
                                    finite_difference_gradient(value, u, 1e-7)),
                1e-5);

    const FullMatrix<double> raw = assembled_hessian<dim>(barrier,
                                                          barrier,
                                                          scene.dofs,
                                                          u,
                                                          HessianKind::exact);
    report<dim>(
      "barrier Hessian (raw)",
      relative_difference(raw, finite_difference_hessian(gradient, u, 1e-8)),
      1e-5);
    const FullMatrix<double> projected =
      assembled_hessian<dim>(barrier, barrier, scene.dofs, u);
    const auto range = eigenvalue_range(projected);
    report<dim>("projected barrier Hessian PSD",
                std::max(0., -range.first / range.second),
                1e-10);

    // Friction lagged at u, evaluated at u + sliding: beyond eps_v dt
    // (kinetic) and inside it (static).
    for (const double sliding : {5e-3, 2e-7})
      {
        FrictionTerm<dim> friction(barrier, scene.parameters);
        const double      dt = 1e-2; // eps_v dt = 1e-5
        friction.set_scale(1., dt);
        // Lagged at the step's start (u = 0), so that the sliding
        // displacement at v is the imposed one.
        const Vector<double> start(u.size());
        friction.update(start);
        Vector<double> v = start;
        for (unsigned int i = 0; i < v.size(); i += dim)
          v[i] += sliding * (i < dim * scene.dofs.n_fem_nodes() ? 0.2 : 1.);
        v.add(1., scene.random_displacement(0.1 * sliding));
        const auto f_value = [&](const Vector<double> &w) {
          return friction.value(w);
        };
        const auto f_gradient = [&](const Vector<double> &w,
                                    Vector<double>       &gw) {
          friction.add_gradient(w, gw);
        };
        Vector<double> gf(v.size());
        f_gradient(v, gf);
        const std::string zone = sliding > 1e-5 ? "kinetic" : "static";
        deallog << label << " friction pairs: "
                << (friction.n_pairs() > 0 ? "some" : "none") << std::endl;
        report<dim>("friction gradient (" + zone + ")",
                    relative_difference(
                      gf,
                      finite_difference_gradient(f_value, v, 1e-3 * sliding)),
                    1e-5);
        const FullMatrix<double> hf =
          assembled_hessian<dim>(friction, barrier, scene.dofs, v);
        // In 2D kinetic friction has a zero Hessian (f1' = 0): measure the
        // error against the natural scale |grad D| / |sliding| as well.
        const FullMatrix<double> fd =
          finite_difference_hessian(f_gradient, v, 1e-3 * sliding);
        FullMatrix<double> difference(hf);
        difference.add(-1., fd);
        report<dim>("friction Hessian (" + zone + ")",
                    difference.frobenius_norm() /
                      std::max(fd.frobenius_norm(), gf.l2_norm() / sliding),
                    1e-5);
        const auto frange = eigenvalue_range(hf);
        report<dim>("friction Hessian PSD (" + zone + ")",
                    std::max(0., -frange.first / frange.second),
                    1e-10);
      }
  }
} // namespace



int
main()
{
  initlog();
  check<2>(false);
  check<3>(false);
  check<2>(true);
  check<3>(true);
}
