#ifndef bfemp_cmpm_element_assembly_h
#define bfemp_cmpm_element_assembly_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/solver/dof_space.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace bfemp
{
  /**
   * The integrals of one cMPM element over its particles, formed on the
   * element's fine B-spline patch and condensed to the coarse unknowns with
   * the element's control matrix p (seed 002 eq. 15 with eq. 20:
   * Phi = B p). A particle then costs what a particle of quadratic B-spline
   * MPM on the fine mesh costs, 3^dim scalar fine functions, instead of r
   * matrix-valued coarse ones; each element adds one product with p:
   *   gather():       q = p Q, the fine control values of the unknowns;
   *   add_forces():   gradient += p^T f for fine nodal forces f;
   *   add_stiffness(): Hessian += p^T K p for fine blocks K.
   * Coarse nodes that are no unknowns of the step (DofSpace::invalid) stay
   * at zero, as with the shape functions evaluated directly.
   *
   * One object per element and thread: it is built for the particles of
   * one ParticleSystem cell, which is one coarse element to the last bit
   * (CoarseGrid::element_of).
   */
  template <int dim>
  class CmpmElementAssembly
  {
  public:
    using FineStencil = typename CoarseGrid<dim>::FineStencil;

    /** The element that contains @p x (any of its particles). */
    CmpmElementAssembly(const CmpmDiscretization<dim> &cmpm,
                        const DofSpace<dim>           &dofs,
                        const Point<dim>              &x);

    /** The fine functions nonzero at @p x (global coordinates). */
    void
    fine_stencil(const Point<dim> &x, FineStencil &stencil) const;

    /** n^dim, the fine nodes (gather() size, add_forces() argument). */
    unsigned int
    n_fine() const;

    /** q_k = sum_I p_kI u_I at the element's fine nodes. */
    void
    gather(const Vector<double> &u, std::vector<Tensor<1, dim>> &fine) const;

    /** gradient += p^T @p fine_forces at the element's unknowns. */
    void
    add_forces(const std::vector<Tensor<1, dim>> &fine_forces,
               Vector<double>                    &gradient) const;

    /**
     * hessian += p^T K p with the fine blocks of CoarsenedShapeFunctions::
     * condense() (the upper blocks between @p fine_nodes, those that
     * @p coupled marks).
     */
    void
    add_stiffness(const std::vector<unsigned int>   &fine_nodes,
                  const std::vector<Tensor<2, dim>> &upper,
                  const std::vector<char>           &coupled,
                  SparseMatrix<double>              &hessian) const;

    /** The unknowns (unified nodes) of the element's coarse nodes. */
    const std::vector<unsigned int> &
    unknowns() const;

  private:
    const CoarsenedShapeFunctions<dim> &phi;
    std::size_t                         element;
    Point<dim>                          corner;
    /** Unified node of each of the r local coarse nodes, or invalid. */
    std::vector<unsigned int> local_unknowns;
    /** The valid ones, and their local indices. */
    std::vector<unsigned int> valid_unknowns;
    std::vector<unsigned int> valid_local;
  };
} // namespace bfemp

#endif
