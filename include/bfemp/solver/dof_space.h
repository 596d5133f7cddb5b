#ifndef bfemp_solver_dof_space_h
#define bfemp_solver_dof_space_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The unified unknowns of one implicit step (BFEMP Section 3): the nodes
   * of every FEM body first, then the active nodes of the MPM grid (mass >
   * 0) in lattice order. Node n owns DoFs dim n .. dim n + dim - 1, and the
   * unknown is the displacement u = x~^{n+1} - x^n of each node, which keeps
   * the solve free of the round-off that absolute coordinates would add.
   *
   * Dirichlet-type conditions (prescribed FEM nodes, sticky and slip grid
   * boundaries) are node constraints u_i = P_i u_i + (I - P_i) target_i with
   * an orthogonal projector P_i onto the directions left free: P = 0 fixes a
   * node, P = I - n n^T lets it slip along a wall with normal n.
   */
  template <int dim>
  class DofSpace
  {
  public:
    static constexpr unsigned int invalid =
      std::numeric_limits<unsigned int>::max();

    struct Constraint
    {
      unsigned int   node = invalid;
      Tensor<2, dim> free_projector;
      Tensor<1, dim> target;
    };

    /**
     * Numbers the FEM nodes of bodies with @p fem_nodes_per_body nodes, then
     * the lattice nodes with @p grid_mass > 0 (empty for scenes without MPM
     * bodies). Removes all constraints. numbering() changes only if the
     * numbering does.
     */
    void
    reinit(const std::vector<unsigned int> &fem_nodes_per_body,
           const std::vector<double>       &grid_mass);

    /**
     * Changes whenever reinit() numbers the nodes differently from before:
     * vectors and matrices built for one value are valid for another call
     * of reinit() with the same value (a factorization kept as a
     * preconditioner across time steps, say).
     */
    unsigned int
    numbering() const
    {
      return numbering_revision;
    }

    unsigned int
    n_nodes() const
    {
      return n_fem + static_cast<unsigned int>(grid_to_lattice.size());
    }

    unsigned int
    n_dofs() const
    {
      return dim * n_nodes();
    }

    unsigned int
    n_fem_nodes() const
    {
      return n_fem;
    }

    unsigned int
    n_grid_nodes() const
    {
      return static_cast<unsigned int>(grid_to_lattice.size());
    }

    /** Unified node of node @p local of FEM body @p body. */
    unsigned int
    fem_node(const unsigned int body, const unsigned int local) const
    {
      return fem_offsets[body] + local;
    }

    /** Unified node of lattice node @p lattice_node, or invalid. */
    unsigned int
    grid_node(const std::size_t lattice_node) const
    {
      return lattice_to_node[lattice_node];
    }

    /** Lattice node of the unified grid node @p node (node >= n_fem_nodes). */
    std::size_t
    lattice_node(const unsigned int node) const
    {
      return grid_to_lattice[node - n_fem];
    }

    /** Adds the constraint u_node = P u_node + (I - P) target. */
    void
    constrain(const unsigned int    node,
              const Tensor<2, dim> &free_projector,
              const Tensor<1, dim> &target);

    const std::vector<Constraint> &
    constraints() const
    {
      return constraint_list;
    }

    /** Index into constraints() of @p node, or invalid if it is free. */
    unsigned int
    constraint_index(const unsigned int node) const
    {
      return node_constraint[node];
    }

    /** v_i <- P_i v_i on constrained nodes (gradients, directions). */
    void
    project(Vector<double> &v) const;

    /** u_i <- P_i u_i + (I - P_i) target_i on constrained nodes. */
    void
    impose(Vector<double> &u) const;

    static Tensor<1, dim>
    get(const Vector<double> &v, const unsigned int node)
    {
      Tensor<1, dim> t;
      for (unsigned int c = 0; c < dim; ++c)
        t[c] = v[dim * node + c];
      return t;
    }

    static void
    set(Vector<double> &v, const unsigned int node, const Tensor<1, dim> &t)
    {
      for (unsigned int c = 0; c < dim; ++c)
        v[dim * node + c] = t[c];
    }

  private:
    unsigned int              n_fem              = 0;
    unsigned int              numbering_revision = 0;
    std::vector<unsigned int> fem_offsets;
    std::vector<unsigned int> lattice_to_node;
    std::vector<std::size_t>  grid_to_lattice;
    std::vector<Constraint>   constraint_list;
    std::vector<unsigned int> node_constraint;
  };
} // namespace bfemp

#endif
