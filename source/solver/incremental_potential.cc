#include <bfemp/solver/incremental_potential.h>
#include <bfemp/solver/node_sparsity.h>

#include <limits>

namespace bfemp
{
  template <int dim>
  IncrementalPotential<dim>::IncrementalPotential(const DofSpace<dim> &dofs)
    : dofs(dofs)
  {}



  template <int dim>
  void
  IncrementalPotential<dim>::set_terms(
    const std::vector<const EnergyTerm<dim> *> &new_terms)
  {
    terms = new_terms;
  }



  template <int dim>
  void
  IncrementalPotential<dim>::setup_system()
  {
    NodeSparsity node_sparsity(dofs.n_nodes());
    for (const EnergyTerm<dim> *term : terms)
      term->add_couplings(node_sparsity);
    matrix.clear();
    node_sparsity.build(dim, pattern);
    matrix.reinit(pattern);
    ++n_pattern_builds;
  }



  template <int dim>
  double
  IncrementalPotential<dim>::value(const Vector<double> &u) const
  {
    double energy = 0.;
    for (const EnergyTerm<dim> *term : terms)
      energy += term->value(u);
    return energy;
  }



  template <int dim>
  double
  IncrementalPotential<dim>::round_off() const
  {
    double magnitude = 0.;
    for (const EnergyTerm<dim> *term : terms)
      magnitude += term->magnitude();
    return 64. * std::numeric_limits<double>::epsilon() * magnitude;
  }



  template <int dim>
  std::vector<double>
  IncrementalPotential<dim>::term_values(const Vector<double> &u) const
  {
    std::vector<double> values;
    for (const EnergyTerm<dim> *term : terms)
      values.push_back(term->value(u));
    return values;
  }



  template <int dim>
  std::vector<std::string>
  IncrementalPotential<dim>::term_names() const
  {
    std::vector<std::string> names;
    for (const EnergyTerm<dim> *term : terms)
      names.push_back(term->name());
    return names;
  }



  template <int dim>
  void
  IncrementalPotential<dim>::gradient(const Vector<double> &u,
                                      Vector<double>       &g) const
  {
    g.reinit(dofs.n_dofs());
    for (const EnergyTerm<dim> *term : terms)
      term->add_gradient(u, g);
    dofs.project(g);
  }



  template <int dim>
  const SparseMatrix<double> &
  IncrementalPotential<dim>::hessian(const Vector<double> &u,
                                     const HessianKind     kind)
  {
    bool missing = false;
    for (const EnergyTerm<dim> *term : terms)
      missing = term->couplings_missing(u, pattern) || missing;
    if (missing)
      setup_system();
    matrix = 0.;
    for (const EnergyTerm<dim> *term : terms)
      term->add_hessian(u, matrix, kind);
    apply_constraints();
    return matrix;
  }



  template <int dim>
  Tensor<2, dim>
  IncrementalPotential<dim>::block(const unsigned int i,
                                   const unsigned int j) const
  {
    Tensor<2, dim> b;
    for (unsigned int r = 0; r < dim; ++r)
      for (unsigned int c = 0; c < dim; ++c)
        b[r][c] = matrix.el(dim * i + r, dim * j + c);
    return b;
  }



  template <int dim>
  void
  IncrementalPotential<dim>::set_block(const unsigned int    i,
                                       const unsigned int    j,
                                       const Tensor<2, dim> &b)
  {
    for (unsigned int r = 0; r < dim; ++r)
      for (unsigned int c = 0; c < dim; ++c)
        matrix.set(dim * i + r, dim * j + c, b[r][c]);
  }



  template <int dim>
  void
  IncrementalPotential<dim>::apply_constraints()
  {
    const auto &constraints = dofs.constraints();
    if (constraints.empty())
      return;
    const Tensor<2, dim> identity     = unit_symmetric_tensor<dim>();
    auto                 projector_of = [&](const unsigned int node) {
      const unsigned int c = dofs.constraint_index(node);
      return c == DofSpace<dim>::invalid ? identity
                                                         : constraints[c].free_projector;
    };
    // Block (i, j) becomes P_i H_ij P_j. Each block touching a constrained
    // node is rewritten once: from the row of the constrained node i, and
    // its mirror (j, i) unless j is constrained too (then row j does it).
    for (const auto &constraint : constraints)
      {
        const unsigned int i   = constraint.node;
        const auto        &P_i = constraint.free_projector;
        for (auto entry = pattern.begin(dim * i); entry != pattern.end(dim * i);
             ++entry)
          {
            if (entry->column() % dim != 0)
              continue;
            const unsigned int j = entry->column() / dim;
            const bool         j_constrained =
              dofs.constraint_index(j) != DofSpace<dim>::invalid;
            if (j_constrained && j < i)
              continue; // done from row j
            const Tensor<2, dim> P_j  = projector_of(j);
            const Tensor<2, dim> H_ij = block(i, j);
            if (j == i)
              {
                // The constrained directions get the node's mean diagonal
                // stiffness rather than 1, which keeps the matrix's
                // conditioning (and CG's iteration count) that of the free
                // problem.
                const double stiffness =
                  std::max(trace(H_ij) / dim,
                           std::numeric_limits<double>::min());
                set_block(i,
                          i,
                          P_i * H_ij * P_i + stiffness * (identity - P_i));
              }
            else
              {
                set_block(i, j, P_i * H_ij * P_j);
                set_block(j, i, P_j * block(j, i) * P_i);
              }
          }
      }
  }



  template <int dim>
  double
  IncrementalPotential<dim>::step_bound(const Vector<double>   &u,
                                        const Vector<double>   &p,
                                        const EnergyTerm<dim> **limiting) const
  {
    double bound = std::numeric_limits<double>::infinity();
    for (const EnergyTerm<dim> *term : terms)
      {
        const double b = term->step_bound(u, p);
        if (b < bound)
          {
            bound = b;
            if (limiting != nullptr)
              *limiting = term;
          }
      }
    return bound;
  }



  template <int dim>
  void
  IncrementalPotential<dim>::set_obstacle_path(const double from,
                                               const double to) const
  {
    for (const EnergyTerm<dim> *term : terms)
      term->set_obstacle_path(from, to);
  }



  template <int dim>
  double
  IncrementalPotential<dim>::minimum_distance(const Vector<double> &u) const
  {
    double minimum = std::numeric_limits<double>::infinity();
    for (const EnergyTerm<dim> *term : terms)
      minimum = std::min(minimum, term->minimum_distance(u));
    return minimum;
  }



  template <int dim>
  double
  IncrementalPotential<dim>::minimum_determinant(const Vector<double> &u) const
  {
    double minimum = std::numeric_limits<double>::infinity();
    for (const EnergyTerm<dim> *term : terms)
      minimum = std::min(minimum, term->minimum_determinant(u));
    return minimum;
  }



  template <int dim>
  const SparsityPattern &
  IncrementalPotential<dim>::sparsity_pattern() const
  {
    return pattern;
  }



  template <int dim>
  const DofSpace<dim> &
  IncrementalPotential<dim>::dof_space() const
  {
    return dofs;
  }



  template <int dim>
  void
  IncrementalPotential<dim>::set_increment_measure(
    std::function<double(const Vector<double> &)> measure)
  {
    increment_measure = std::move(measure);
  }



  template <int dim>
  double
  IncrementalPotential<dim>::increment_norm(const Vector<double> &p) const
  {
    return increment_measure ? increment_measure(p) : p.linfty_norm();
  }



  template class IncrementalPotential<2>;
  template class IncrementalPotential<3>;
} // namespace bfemp
