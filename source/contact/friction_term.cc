#include <bfemp/base/parallel_sum.h>
#include <bfemp/contact/distance.h>
#include <bfemp/contact/friction_mollifier.h>
#include <bfemp/contact/friction_term.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bfemp
{
  namespace
  {
    /** An orthonormal basis of the plane orthogonal to the unit vector n. */
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    tangent_basis(const Tensor<1, dim> &n)
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      if constexpr (dim == 2)
        {
          t[0][0] = -n[1];
          t[0][1] = n[0];
        }
      else
        {
          // Start from the axis least aligned with n.
          unsigned int axis = 0;
          for (unsigned int d = 1; d < 3; ++d)
            if (std::abs(n[d]) < std::abs(n[axis]))
              axis = d;
          Tensor<1, 3> e;
          e[axis] = 1.;
          t[0]    = e - (e * n) * n;
          t[0] /= t[0].norm();
          t[1] = cross_product_3d(n, t[0]);
        }
      return t;
    }
  } // namespace



  template <int dim>
  FrictionTerm<dim>::FrictionTerm(const BarrierTerm<dim>  &barrier,
                                  const ContactParameters &parameters)
    : barrier(barrier)
    , parameters(parameters)
  {}



  template <int dim>
  void
  FrictionTerm<dim>::set_scale(const double s, const double dt)
  {
    scale               = s;
    unwidened_threshold = parameters.static_friction_velocity * dt;
    threshold           = mollifier_factor * unwidened_threshold;
  }



  template <int dim>
  void
  FrictionTerm<dim>::set_mollifier_factor(const double g)
  {
    Assert(g >= 1., ExcMessage("the mollifier can only be widened"));
    mollifier_factor = g;
    threshold        = g * unwidened_threshold;
  }



  template <int dim>
  void
  FrictionTerm<dim>::clear()
  {
    pairs.clear();
  }



  template <int dim>
  unsigned int
  FrictionTerm<dim>::n_pairs() const
  {
    return static_cast<unsigned int>(pairs.size());
  }



  template <int dim>
  std::string
  FrictionTerm<dim>::name() const
  {
    return "friction";
  }



  template <int dim>
  void
  FrictionTerm<dim>::update(const Vector<double> &u)
  {
    const ContactGeometry<dim> &geometry = barrier.geometry();
    const auto                  x        = geometry.surface_positions(u);
    pairs.clear();
    for (const auto &contact : barrier.contacts(u))
      {
        const unsigned int q  = contact.particle;
        const Point<dim>   xq = geometry.particle_position(q, u);
        for (const auto &entry : contact.surfaces)
          {
            const double mu =
              parameters.friction_coefficient(geometry.particle_body(q),
                                              entry.surface);
            const double lambda = entry.force.norm();
            if (mu == 0. || lambda == 0.)
              continue;
            Pair pair;
            pair.particle = q;
            pair.surface  = entry.surface;
            pair.facet_nodes =
              geometry.surface(entry.surface).facets()[entry.nearest_facet];
            const auto &xs = x[entry.surface];
            if constexpr (dim == 2)
              {
                const auto d =
                  point_edge_squared_distance<2>(xq,
                                                 xs[pair.facet_nodes[0]],
                                                 xs[pair.facet_nodes[1]]);
                pair.weights = {{d.weights[0], d.weights[1]}};
              }
            else
              {
                const auto d =
                  point_triangle_squared_distance(xq,
                                                  xs[pair.facet_nodes[0]],
                                                  xs[pair.facet_nodes[1]],
                                                  xs[pair.facet_nodes[2]]);
                pair.weights = {{d.weights[0], d.weights[1], d.weights[2]}};
              }
            Point<dim> nearest;
            for (unsigned int a = 0; a < dim; ++a)
              nearest += pair.weights[a] * xs[pair.facet_nodes[a]];
            // The normal is the direction the barrier pushes in: from the
            // nearest point to the particle.
            Tensor<1, dim> normal = xq - nearest;
            if (normal.norm() == 0.)
              continue;
            normal /= normal.norm();
            pair.basis     = tangent_basis<dim>(normal);
            pair.mu_lambda = mu * lambda;
            pairs.push_back(pair);
            std::vector<unsigned int> fem_nodes;
            for (const unsigned int a : pair.facet_nodes)
              fem_nodes.push_back(geometry.node_dof(pair.surface, a));
            couplings_grew =
              barrier.register_couplings(q, fem_nodes) || couplings_grew;
          }
      }
  }



  template <int dim>
  Tensor<1, dim - 1>
  FrictionTerm<dim>::sliding(const Pair &pair, const Vector<double> &u) const
  {
    const ContactGeometry<dim> &geometry = barrier.geometry();
    Tensor<1, dim> relative = geometry.particle_interpolation(pair.particle, u);
    for (unsigned int a = 0; a < dim; ++a)
      relative -=
        pair.weights[a] *
        geometry.node_displacement(pair.surface, pair.facet_nodes[a], u);
    Tensor<1, dim - 1> y;
    for (unsigned int k = 0; k < dim - 1; ++k)
      y[k] = pair.basis[k] * relative;
    return y;
  }



  template <int dim>
  void
  FrictionTerm<dim>::chain_rule(const Pair &pair, ChainRule<dim> &rule) const
  {
    // The relative displacement x_q(u) - x_q^n - sum_a w_a (x_a(u) - x_a^n)
    // is the one block: the particle's stencil with dx_q/du_i, the facet's
    // deformable nodes with -w_a.
    const ContactGeometry<dim> &geometry = barrier.geometry();
    rule.clear();
    geometry.add_particle_stencil(rule, pair.particle, 0);
    for (unsigned int a = 0; a < dim; ++a)
      {
        const unsigned int node =
          geometry.node_dof(pair.surface, pair.facet_nodes[a]);
        if (node != DofSpace<dim>::invalid)
          rule.add(node, 0, -pair.weights[a]);
      }
  }



  template <int dim>
  void
  FrictionTerm<dim>::add_couplings(NodeSparsity &) const
  {
    // The barrier term adds the cliques of every registered pair.
  }



  template <int dim>
  bool
  FrictionTerm<dim>::couplings_missing(const Vector<double> &,
                                       const SparsityPattern &) const
  {
    const bool missing = couplings_grew;
    couplings_grew     = false;
    return missing;
  }



  template <int dim>
  double
  FrictionTerm<dim>::value(const Vector<double> &u) const
  {
    const double d =
      chunked_sum<double>(pairs.size(), [&](const std::size_t k) {
        return pairs[k].mu_lambda *
               FrictionMollifier(threshold).f0(sliding(pairs[k], u).norm());
      });
    last_magnitude = scale * d;
    return scale * d;
  }



  template <int dim>
  double
  FrictionTerm<dim>::magnitude() const
  {
    return std::abs(last_magnitude);
  }



  template <int dim>
  double
  FrictionTerm<dim>::dissipation(const Vector<double> &u) const
  {
    double work = 0.;
    for (const Pair &pair : pairs)
      {
        const double y = sliding(pair, u).norm();
        work += pair.mu_lambda * FrictionMollifier(threshold).f1(y) * y;
      }
    return work;
  }



  template <int dim>
  void
  FrictionTerm<dim>::add_gradient(const Vector<double> &u,
                                  Vector<double>       &gradient) const
  {
    ChainRule<dim> rule;
    for (const Pair &pair : pairs)
      {
        const Tensor<1, dim> force = scale * particle_force(pair, u);
        chain_rule(pair, rule);
        rule.add_gradient([&](const unsigned int) { return force; }, gradient);
      }
  }



  template <int dim>
  Tensor<1, dim>
  FrictionTerm<dim>::particle_force(const Pair           &pair,
                                    const Vector<double> &u) const
  {
    // dD/d(relative displacement) = mu lambda f1(|y|)/|y| T y.
    const Tensor<1, dim - 1> y = sliding(pair, u);
    Tensor<1, dim>           force;
    for (unsigned int k = 0; k < dim - 1; ++k)
      force += y[k] * pair.basis[k];
    return pair.mu_lambda * FrictionMollifier(threshold).f1_over_y(y.norm()) *
           force;
  }



  template <int dim>
  std::map<std::pair<unsigned int, unsigned int>, Tensor<1, dim>>
  FrictionTerm<dim>::forces(const Vector<double> &u) const
  {
    std::map<std::pair<unsigned int, unsigned int>, Tensor<1, dim>> result;
    for (const Pair &pair : pairs)
      result[{barrier.geometry().particle_body(pair.particle), pair.surface}] +=
        particle_force(pair, u);
    return result;
  }



  template <int dim>
  void
  FrictionTerm<dim>::add_hessian(const Vector<double> &u,
                                 SparseMatrix<double> &hessian,
                                 const HessianKind /*kind*/) const
  {
    ChainRule<dim> rule;
    for (const Pair &pair : pairs)
      {
        const Tensor<1, dim - 1> y    = sliding(pair, u);
        const double             norm = y.norm();
        // M = f1/y (I - yy^T/|y|^2) + f1' yy^T/|y|^2 in the tangent plane;
        // both coefficients are >= 0, so M is PSD. (Written this way, not
        // as f1/y I + (f1/y)'/y yy^T, so that f1' = 0 of kinetic sliding
        // comes out exactly 0, not as a round-off difference.)
        const FrictionMollifier mollifier(threshold);
        const double            f1_over_y = mollifier.f1_over_y(norm);
        const double            f1_prime =
          f1_over_y + mollifier.f1_derivative_minus_f1_over_y(norm);
        Tensor<2, dim - 1> M;
        if (dim == 2)
          M[0][0] = f1_prime;
        else
          for (unsigned int a = 0; a < dim - 1; ++a)
            {
              M[a][a] = f1_over_y;
              for (unsigned int b = 0; b < dim - 1; ++b)
                if (norm > 0.)
                  M[a][b] +=
                    (f1_prime - f1_over_y) * y[a] * y[b] / (norm * norm);
            }
        Tensor<2, dim> block;
        for (unsigned int a = 0; a < dim - 1; ++a)
          for (unsigned int b = 0; b < dim - 1; ++b)
            block += M[a][b] * outer_product(pair.basis[a], pair.basis[b]);
        block *= scale * pair.mu_lambda;

        chain_rule(pair, rule);
        rule.add_hessian(
          [&](const unsigned int row, const unsigned int column) {
            return block[row][column];
          },
          1.,
          hessian);
      }
  }



  template class FrictionTerm<2>;
  template class FrictionTerm<3>;
} // namespace bfemp
