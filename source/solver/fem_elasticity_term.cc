#include <bfemp/base/parallel_sum.h>
#include <bfemp/material/tangent_projection.h>
#include <bfemp/solver/determinant_bound.h>
#include <bfemp/solver/fem_elasticity_term.h>

#include <deal.II/base/work_stream.h>

namespace bfemp
{
  template <int dim>
  FemElasticityTerm<dim>::FemElasticityTerm(
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
    const DofSpace<dim>                              &dofs)
    : bodies(bodies)
    , dofs(dofs)
  {
    // Kinematic bodies have no unknowns: their elastic energy is constant.
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!bodies[b]->is_kinematic())
        for (unsigned int e = 0; e < bodies[b]->elements().size(); ++e)
          all_elements.push_back({b, e});
  }



  template <int dim>
  void
  FemElasticityTerm<dim>::set_scale(const double s)
  {
    scale = s;
  }



  template <int dim>
  std::string
  FemElasticityTerm<dim>::name() const
  {
    return "FEM elasticity";
  }



  template <int dim>
  std::array<unsigned int, dim + 1>
  FemElasticityTerm<dim>::unified_nodes(const ElementReference &e) const
  {
    std::array<unsigned int, dim + 1> nodes;
    const auto &local = bodies[e.body]->element_nodes()[e.element];
    for (unsigned int a = 0; a <= dim; ++a)
      nodes[a] = dofs.fem_node(e.body, local[a]);
    return nodes;
  }



  template <int dim>
  typename FemElasticityTerm<dim>::NodePositions
  FemElasticityTerm<dim>::positions(const ElementReference &e,
                                    const Vector<double>   &u) const
  {
    const FemBody<dim> &body  = *bodies[e.body];
    const auto         &local = body.element_nodes()[e.element];
    NodePositions       x;
    for (unsigned int a = 0; a <= dim; ++a)
      x[a] = body.positions()[local[a]] +
             DofSpace<dim>::get(u, dofs.fem_node(e.body, local[a]));
    return x;
  }



  template <int dim>
  typename FemElasticityTerm<dim>::NodePositions
  FemElasticityTerm<dim>::directions(const ElementReference &e,
                                     const Vector<double>   &p) const
  {
    const auto   &local = bodies[e.body]->element_nodes()[e.element];
    NodePositions d;
    for (unsigned int a = 0; a <= dim; ++a)
      d[a] = Point<dim>(DofSpace<dim>::get(p, dofs.fem_node(e.body, local[a])));
    return d;
  }



  template <int dim>
  void
  FemElasticityTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    for (const ElementReference &e : all_elements)
      {
        const auto nodes = unified_nodes(e);
        sparsity.add_clique(nodes.data(), nodes.size());
      }
  }



  template <int dim>
  double
  FemElasticityTerm<dim>::value(const Vector<double> &u) const
  {
    return scale *
           chunked_sum<double>(all_elements.size(), [&](const std::size_t i) {
             const ElementReference &e       = all_elements[i];
             const FemBody<dim>     &body    = *bodies[e.body];
             const auto             &element = body.elements()[e.element];
             const NodePositions     x       = positions(e, u);
             if (!(determinant(element.deformation_gradient(x)) > 0.))
               return std::numeric_limits<double>::infinity();
             return element.energy(x, body.material());
           });
  }



  template <int dim>
  double
  FemElasticityTerm<dim>::magnitude() const
  {
    double size = 0.;
    for (const auto &body : bodies)
      size += body->mesh().total_volume() * body->material().energy_scale();
    return scale * size;
  }



  template <int dim>
  void
  FemElasticityTerm<dim>::add_gradient(const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    struct Copy
    {
      std::array<unsigned int, dim + 1> nodes;
      Vector<double>                    local;
    };
    struct Scratch
    {};
    WorkStream::run(
      all_elements.begin(),
      all_elements.end(),
      [&](const auto &e, Scratch &, Copy &copy) {
        const FemBody<dim> &body = *bodies[e->body];
        copy.nodes               = unified_nodes(*e);
        copy.local = body.elements()[e->element].gradient(positions(*e, u),
                                                          body.material());
      },
      [&](const Copy &copy) {
        for (unsigned int a = 0; a <= dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            gradient[dim * copy.nodes[a] + c] +=
              scale * copy.local[dim * a + c];
      },
      Scratch(),
      Copy());
  }



  template <int dim>
  void
  FemElasticityTerm<dim>::add_hessian(const Vector<double> &u,
                                      SparseMatrix<double> &hessian,
                                      const HessianKind     kind) const
  {
    struct Copy
    {
      std::vector<types::global_dof_index> dof_indices;
      FullMatrix<double>                   local;
    };
    struct Scratch
    {};
    WorkStream::run(
      all_elements.begin(),
      all_elements.end(),
      [&](const auto &e, Scratch &, Copy &copy) {
        const FemBody<dim> &body    = *bodies[e->body];
        const auto         &element = body.elements()[e->element];
        const auto          nodes   = unified_nodes(*e);
        copy.dof_indices.resize(SimplexElement<dim>::n_dofs);
        for (unsigned int a = 0; a <= dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            copy.dof_indices[dim * a + c] = dim * nodes[a] + c;
        const Tensor<2, dim> F = element.deformation_gradient(positions(*e, u));
        copy.local =
          element.hessian(body.material().tangent(F, eigenvalue_filter(kind)));
        copy.local *= scale;
      },
      [&](const Copy &copy) { hessian.add(copy.dof_indices, copy.local); },
      Scratch(),
      Copy());
  }



  template <int dim>
  double
  FemElasticityTerm<dim>::step_bound(const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    // F_e(x + t p) = (T_e(x) + t T_e(p)) B_e^-1 with det B_e^-1 > 0, so the
    // roots are those of det(T_e(x) + t T_e(p)).
    return chunked_sum<Minimum>(all_elements.size(),
                                [&](const std::size_t i) {
                                  const ElementReference &e = all_elements[i];
                                  const NodePositions     x = positions(e, u);
                                  const NodePositions     d = directions(e, p);
                                  Tensor<2, dim>          T, dT;
                                  for (unsigned int a = 1; a <= dim; ++a)
                                    for (unsigned int r = 0; r < dim; ++r)
                                      {
                                        T[r][a - 1]  = x[a][r] - x[0][r];
                                        dT[r][a - 1] = d[a][r] - d[0][r];
                                      }
                                  Minimum m;
                                  m += determinant_step_bound<dim>(T, dT);
                                  return m;
                                })
      .value;
  }



  template <int dim>
  double
  FemElasticityTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    return chunked_sum<Minimum>(all_elements.size(),
                                [&](const std::size_t i) {
                                  const ElementReference &e = all_elements[i];
                                  const auto             &element =
                                    bodies[e.body]->elements()[e.element];
                                  Minimum m;
                                  m += determinant(element.deformation_gradient(
                                    positions(e, u)));
                                  return m;
                                })
      .value;
  }



  template class FemElasticityTerm<2>;
  template class FemElasticityTerm<3>;
} // namespace bfemp
