#ifndef bfemp_solver_incremental_potential_h
#define bfemp_solver_incremental_potential_h

#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace bfemp
{
  /**
   * The incremental potential E(u) of one implicit step, BFEMP eq. 22 (eq. 38
   * with contact), as the sum of its energy terms over the unified DoF space,
   * restricted to the displacements the node constraints allow.
   *
   * With the block-diagonal projector P of the constraints (DofSpace), the
   * free problem is min E(P u + (I - P) target): its gradient is P grad E
   * and its Hessian P H P. Adding (I - P) on the diagonal keeps the matrix
   * nonsingular, and the Newton direction then satisfies p = P p, so
   * iterates keep meeting the constraints.
   */
  template <int dim>
  class IncrementalPotential
  {
  public:
    explicit IncrementalPotential(const DofSpace<dim> &dofs);

    /** The terms of E; not owned. */
    void
    set_terms(const std::vector<const EnergyTerm<dim> *> &terms);

    /** Builds the sparsity pattern of the Hessian from the terms. */
    void
    setup_system();

    double
    value(const Vector<double> &u) const;

    /** A bound of the round-off of value(): 64 eps sum of magnitudes. */
    double
    round_off() const;

    /** Each term's value at u, in the order of set_terms(). */
    std::vector<double>
    term_values(const Vector<double> &u) const;

    /** Each term's name, in the order of set_terms(). */
    std::vector<std::string>
    term_names() const;

    /** P grad E(u). */
    void
    gradient(const Vector<double> &u, Vector<double> &gradient) const;

    /**
     * P H(u) P + (I - P) with H the sum of the terms' Hessians of @p kind.
     * Rebuilds the sparsity pattern first if a term's couplings at u outgrew
     * it.
     */
    const SparseMatrix<double> &
    hessian(const Vector<double> &u,
            const HessianKind     kind = HessianKind::projected);

    /**
     * The smallest step bound of any term along p; @p limiting (if given)
     * receives the term that set it.
     */
    double
    step_bound(const Vector<double>   &u,
               const Vector<double>   &p,
               const EnergyTerm<dim> **limiting = nullptr) const;

    /**
     * How Newton measures an increment p for its stopping test: by default
     * ||p||_inf over the unknowns (BFEMP Section 5); @p measure replaces it
     * (an empty function restores the default).
     */
    void
    set_increment_measure(
      std::function<double(const Vector<double> &)> measure);

    /** The increment measure of @p p (see set_increment_measure()). */
    double
    increment_norm(const Vector<double> &p) const;

    /** Forwards the obstacle path to the terms (EnergyTerm). */
    void
    set_obstacle_path(const double from, const double to) const;

    /** Smallest contact distance of any term at u. */
    double
    minimum_distance(const Vector<double> &u) const;

    /** Smallest det F of any element or particle at u. */
    double
    minimum_determinant(const Vector<double> &u) const;

    const SparsityPattern &
    sparsity_pattern() const;

    const DofSpace<dim> &
    dof_space() const;

  private:
    /** H <- P H P + (I - P) for the constrained nodes. */
    void
    apply_constraints();

    /** The dim x dim block (i, j) of the Hessian. */
    Tensor<2, dim>
    block(const unsigned int i, const unsigned int j) const;

    void
    set_block(const unsigned int    i,
              const unsigned int    j,
              const Tensor<2, dim> &b);

    const DofSpace<dim>                          &dofs;
    std::vector<const EnergyTerm<dim> *>          terms;
    SparsityPattern                               pattern;
    SparseMatrix<double>                          matrix;
    unsigned int                                  n_pattern_builds = 0;
    std::function<double(const Vector<double> &)> increment_measure;

  public:
    /** How often setup_system() has built a pattern (diagnostics). */
    unsigned int
    n_sparsity_builds() const
    {
      return n_pattern_builds;
    }
  };
} // namespace bfemp

#endif
