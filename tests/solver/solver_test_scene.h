#ifndef bfemp_tests_solver_test_scene_h
#define bfemp_tests_solver_test_scene_h

// Shared set-up of the tests of the incremental potential and its Newton
// solver: FEM bodies on generated rectangles/boxes, a scene that wires
// bodies, DofSpace, FemElasticityTerm and IncrementalPotential the way
// ImplicitIntegrator does, a dead-load energy term for static problems, a
// test-local Newton loop that records every residual, and dense-matrix
// helpers (finite differences, extreme eigenvalues).

#include <bfemp/fem/fem_body.h>
#include <bfemp/fem/fem_body_parameters.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>
#include <bfemp/solver/fem_elasticity_term.h>
#include <bfemp/solver/incremental_potential.h>
#include <bfemp/solver/linear_solver.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tests.h"

namespace bfemp_tests
{
  using namespace dealii;
  using namespace bfemp;

  /**
   * The parameters of an FEM body on the box [lower, upper] meshed with
   * ceil(side / edge) subdivisions per direction (2 triangles per square,
   * 5 tetrahedra per cube), no prescribed motion.
   */
  template <int dim>
  FemBodyParameters<dim>
  box_body_parameters(const Point<dim>  &lower,
                      const Point<dim>  &upper,
                      const double       edge,
                      const std::string &model,
                      const double       youngs_modulus,
                      const double       poisson_ratio,
                      const double       density)
  {
    FemBodyParameters<dim> parameters;
    parameters.mesh.source       = FemMeshParameters<dim>::Source::rectangle;
    parameters.mesh.lower_corner = lower;
    parameters.mesh.upper_corner = upper;
    parameters.mesh.target_edge_length = edge;
    parameters.material.model          = model;
    parameters.material.youngs_modulus = youngs_modulus;
    parameters.material.poisson_ratio  = poisson_ratio;
    parameters.material.density        = density;
    return parameters;
  }



  /**
   * A neo-Hookean bar [0, length] x [0, width]^(dim-1) (density 1000), as
   * box_body_parameters(); its face x = 0 has boundary id 0, x = length id 1.
   */
  template <int dim>
  FemBodyParameters<dim>
  neo_hookean_bar(const double length,
                  const double width,
                  const double edge,
                  const double youngs_modulus,
                  const double poisson_ratio)
  {
    Point<dim> upper;
    upper[0] = length;
    for (unsigned int d = 1; d < dim; ++d)
      upper[d] = width;
    return box_body_parameters<dim>(Point<dim>(),
                                    upper,
                                    edge,
                                    "neo-Hookean",
                                    youngs_modulus,
                                    poisson_ratio,
                                    1000.);
  }



  /**
   * FEM bodies with their unified DoF space, elasticity term and incremental
   * potential, wired as in ImplicitIntegrator (members are constructed in
   * this order, so the references the term and the potential keep are
   * valid). The caller sets the constraints and the potential's terms.
   */
  template <int dim>
  struct FemScene
  {
    explicit FemScene(const std::vector<FemBodyParameters<dim>> &parameters)
      : bodies(make_bodies(parameters))
      , elasticity(bodies, dofs)
      , potential(dofs)
    {
      std::vector<unsigned int> nodes_per_body;
      for (const auto &body : bodies)
        nodes_per_body.push_back(body->n_nodes());
      dofs.reinit(nodes_per_body, std::vector<double>());
    }

    static std::vector<std::unique_ptr<FemBody<dim>>>
    make_bodies(const std::vector<FemBodyParameters<dim>> &parameters)
    {
      std::vector<std::unique_ptr<FemBody<dim>>> result;
      for (unsigned int b = 0; b < parameters.size(); ++b)
        result.push_back(
          std::make_unique<FemBody<dim>>(parameters[b],
                                         "fem body " + std::to_string(b)));
      return result;
    }

    /** Fixes (projector 0, target 0) every node of body 0 on the facets
     *  with boundary id @p id; returns how many. */
    unsigned int
    clamp(const types::boundary_id id)
    {
      const auto nodes = bodies[0]->mesh().nodes_with_boundary_id(id);
      for (const unsigned int a : nodes)
        dofs.constrain(dofs.fem_node(0, a), Tensor<2, dim>(), Tensor<1, dim>());
      return nodes.size();
    }

    /** Lumped masses of all FEM nodes in unified order. */
    std::vector<double>
    node_masses() const
    {
      std::vector<double> masses(dofs.n_nodes(), 0.);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        for (unsigned int a = 0; a < bodies[b]->n_nodes(); ++a)
          masses[dofs.fem_node(b, a)] = bodies[b]->masses()[a];
      return masses;
    }

    /** Rest position of a unified FEM node of body 0. */
    const Point<dim> &
    rest_position(const unsigned int node) const
    {
      return bodies[0]->mesh().rest_position(node);
    }

    std::vector<std::unique_ptr<FemBody<dim>>> bodies;
    DofSpace<dim>                              dofs;
    FemElasticityTerm<dim>                     elasticity;
    IncrementalPotential<dim>                  potential;
  };



  /**
   * A dead load (conservative constant nodal forces f_a, e.g. gravity m_a g
   * or a traction): E_load(u) = -sum_a f_a . u_a, gradient -f, Hessian 0.
   */
  template <int dim>
  class DeadLoadTerm : public EnergyTerm<dim>
  {
  public:
    explicit DeadLoadTerm(const unsigned int n_dofs)
      : force(n_dofs)
    {}

    void
    add_force(const unsigned int node, const Tensor<1, dim> &f)
    {
      for (unsigned int c = 0; c < dim; ++c)
        force[dim * node + c] += f[c];
    }

    const Vector<double> &
    forces() const
    {
      return force;
    }

    std::string
    name() const override
    {
      return "dead load";
    }

    void
    add_couplings(NodeSparsity &) const override
    {}

    double
    value(const Vector<double> &u) const override
    {
      return -(force * u);
    }

    void
    add_gradient(const Vector<double> &,
                 Vector<double> &gradient) const override
    {
      gradient -= force;
    }

    void
    add_hessian(const Vector<double> &,
                SparseMatrix<double> &,
                const HessianKind) const override
    {}

  private:
    Vector<double> force;
  };



  /**
   * Adds the nodal forces of a uniform traction @p t [Pa] on the boundary
   * facets of body 0 with boundary id @p id to @p load: each facet gives
   * t |facet| / dim to each of its dim nodes (consistent for linear
   * elements).
   */
  template <int dim>
  void
  add_traction(const FemScene<dim>     &scene,
               DeadLoadTerm<dim>       &load,
               const types::boundary_id id,
               const Tensor<1, dim>    &t)
  {
    const FemMesh<dim> &mesh = scene.bodies[0]->mesh();
    for (unsigned int f = 0; f < mesh.boundary_facets().size(); ++f)
      if (mesh.boundary_facet_ids()[f] == id)
        {
          const auto &facet = mesh.boundary_facets()[f];
          const auto &x0    = mesh.rest_position(facet[0]);
          double      area  = 0.;
          if constexpr (dim == 2)
            area = mesh.rest_position(facet[1]).distance(x0);
          else
            area = 0.5 * cross_product_3d(mesh.rest_position(facet[1]) - x0,
                                          mesh.rest_position(facet[2]) - x0)
                           .norm();
          for (const unsigned int a : facet)
            load.add_force(scene.dofs.fem_node(0, a), t * (area / dim));
        }
  }



  /** What the test-local Newton loop saw. */
  /** Elements of body 0 whose tangent the PSD projection changes at u. */
  template <int dim>
  unsigned int
  projected_tangents(const FemScene<dim> &scene, const Vector<double> &u)
  {
    const FemBody<dim> &body = *scene.bodies[0];
    unsigned int        n    = 0;
    for (unsigned int e = 0; e < body.elements().size(); ++e)
      {
        typename SimplexElement<dim>::NodePositions x;
        for (unsigned int a = 0; a <= dim; ++a)
          {
            const unsigned int node = body.element_nodes()[e][a];
            x[a] = body.positions()[node] + DofSpace<dim>::get(u, node);
          }
        const Tensor<2, dim> F = body.elements()[e].deformation_gradient(x);
        const Tensor<4, dim> C = body.material().tangent(F, false);
        if ((body.material().tangent(F, true) - C).norm() > 1e-12 * C.norm())
          ++n;
      }
    return n;
  }



  struct NewtonHistory
  {
    /** ||p_k||_inf of every iteration k = 0, 1, ... */
    std::vector<double> residuals;
    /** Smallest det F over the iterates. */
    double minimum_determinant = std::numeric_limits<double>::infinity();
    bool   converged           = false;
  };

  /**
   * Plain Newton on @p potential with full steps (no line search):
   * p = -H^-1 g from the potential's projected gradient and its Hessian of
   * @p kind (projected: projected Newton), u <- u + p, until ||p||_inf < @p
   * tolerance or
   * @p max_iterations. Every residual is recorded.
   */
  template <int dim>
  NewtonHistory
  full_newton(IncrementalPotential<dim> &potential,
              LinearSolver              &solver,
              Vector<double>            &u,
              const double               tolerance,
              const unsigned int         max_iterations,
              const HessianKind          kind = HessianKind::projected)
  {
    NewtonHistory  history;
    Vector<double> gradient, direction;
    for (unsigned int k = 0; k < max_iterations; ++k)
      {
        potential.gradient(u, gradient);
        solver.factorize(potential.hessian(u, kind));
        gradient *= -1.;
        solver.solve(gradient, direction);
        u += direction;
        history.residuals.push_back(direction.linfty_norm());
        history.minimum_determinant =
          std::min(history.minimum_determinant,
                   potential.minimum_determinant(u));
        if (direction.linfty_norm() < tolerance)
          {
            history.converged = true;
            break;
          }
      }
    return history;
  }



  /** The dense copy of a sparse matrix. */
  inline FullMatrix<double>
  dense(const SparseMatrix<double> &matrix)
  {
    FullMatrix<double> result(matrix.m(), matrix.n());
    for (unsigned int row = 0; row < matrix.m(); ++row)
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        result(row, entry->column()) = entry->value();
    return result;
  }

  /** The smallest and largest eigenvalue of the symmetric part of @p A
   *  (LAPACK). */
  inline std::pair<double, double>
  eigenvalue_range(const FullMatrix<double> &A)
  {
    LAPACKFullMatrix<double> S(A.m(), A.n());
    for (unsigned int i = 0; i < A.m(); ++i)
      for (unsigned int j = 0; j < A.n(); ++j)
        S(i, j) = 0.5 * (A(i, j) + A(j, i));
    S.compute_eigenvalues();
    double smallest = std::numeric_limits<double>::infinity();
    double largest  = -std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < A.m(); ++i)
      {
        smallest = std::min(smallest, S.eigenvalue(i).real());
        largest  = std::max(largest, S.eigenvalue(i).real());
      }
    return {smallest, largest};
  }

  /** ||A - B||_F / ||B||_F. */
  inline double
  relative_difference(const FullMatrix<double> &A, const FullMatrix<double> &B)
  {
    FullMatrix<double> D(A);
    D.add(-1., B);
    return D.frobenius_norm() / B.frobenius_norm();
  }

  /** ||a - b||_2 / ||b||_2. */
  inline double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /** Central differences of @p value at @p u with step @p h, per DoF. */
  inline Vector<double>
  finite_difference_gradient(
    const std::function<double(const Vector<double> &)> &value,
    const Vector<double>                                &u,
    const double                                         h)
  {
    Vector<double> g(u.size()), v(u);
    for (unsigned int n = 0; n < u.size(); ++n)
      {
        v[n]            = u[n] + h;
        const double Ep = value(v);
        v[n]            = u[n] - h;
        const double Em = value(v);
        v[n]            = u[n];
        g[n]            = (Ep - Em) / (2. * h);
      }
    return g;
  }

  /** Central differences of @p gradient at @p u, column by column. */
  inline FullMatrix<double>
  finite_difference_hessian(
    const std::function<void(const Vector<double> &, Vector<double> &)>
                         &gradient,
    const Vector<double> &u,
    const double          h)
  {
    FullMatrix<double> H(u.size(), u.size());
    Vector<double>     v(u), gp(u.size()), gm(u.size());
    for (unsigned int n = 0; n < u.size(); ++n)
      {
        v[n] = u[n] + h;
        gp   = 0.;
        gradient(v, gp);
        v[n] = u[n] - h;
        gm   = 0.;
        gradient(v, gm);
        v[n] = u[n];
        for (unsigned int m = 0; m < u.size(); ++m)
          H(m, n) = (gp[m] - gm[m]) / (2. * h);
      }
    return H;
  }

  /** x in %.Nf, for output that must not depend on round-off. */
  inline std::string
  fixed(const double x, const unsigned int digits)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.*f", int(digits), x);
    return buffer;
  }
} // namespace bfemp_tests

#endif
