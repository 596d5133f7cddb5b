#ifndef bfemp_cmpm_coarsened_shape_functions_h
#define bfemp_cmpm_coarsened_shape_functions_h

#include <bfemp/cmpm/boundary_interior_map.h>
#include <bfemp/cmpm/coarse_boundary_map.h>
#include <bfemp/cmpm/coarse_grid.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cstddef>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The matrix-valued coarsened shape function of one coarse node at a point:
   * Phi_I (eq. 11 / 35) and its gradient, gradient[a][c][b] =
   * d(Phi_I)_ac / dx_b (eq. 16), so that u(x) = sum_I Phi_I Q_I and
   * grad u(x) = sum_I gradient contracted with Q_I over c.
   */
  template <int dim>
  struct CoarseShapeValue
  {
    /** The unknown node (CoarseGrid::unknown_node()): a coarse node's flat
     *  index in CoarseGrid::node_lattice(), or an element's interior-mode
     *  node after them. */
    std::size_t    node = 0;
    Tensor<2, dim> value;
    Tensor<3, dim> gradient;
  };



  /**
   * The coarsened C1 shape functions of cMPM (seed 002): on coarse element
   * alpha, Phi^alpha(x) = B^alpha(x) p^alpha with p^alpha = M^alpha Psi
   * (eqs. 15, 20). Psi is built once; the interior rows of p^alpha are
   * rebuilt by reinit() from the particles in the element (Section 7.2:
   * every step, as the material distribution moves). Each element's data
   * belongs to that element alone, so elements are rebuilt independently
   * (in parallel here, on their owning rank later).
   *
   * With `cmpm/interior modes` = body load every element has one more
   * unknown node of its own (CoarseGrid::n_element_unknowns() = r + 1):
   * its block column of p is zero on the boundary fine nodes and the
   * interior's response to a body load on the interior ones
   * (BoundaryInteriorMap). Below, "the r coarse nodes" of an element are
   * then its r + 1 unknowns: the products with p run over all of them.
   */
  template <int dim>
  class CoarsenedShapeFunctions
  {
  public:
    explicit CoarsenedShapeFunctions(const CoarseGrid<dim> &grid);

    /**
     * Rebuilds the control matrices of the elements @p elements (flat
     * indices) from their particles, @p points[e] holding those of
     * elements[e] in element coordinates; every other element becomes
     * inactive. The elements are independent and run on threads.
     */
    void
    reinit(const std::vector<std::size_t>                            &elements,
           const std::vector<std::vector<LocalQuadraturePoint<dim>>> &points);

    /** Makes every element inactive (the start of a step's rebuild). */
    void
    clear();

    /**
     * Rebuilds one element from its particles. Elements are independent:
     * different elements may be rebuilt on different threads.
     */
    void
    rebuild(const std::size_t                             element,
            const std::vector<LocalQuadraturePoint<dim>> &points);

    /**
     * Rebuilds one element with the `full Newton` local solve at the coarse
     * displacement @p coarse_displacement of its r local nodes
     * (BoundaryInteriorMap::compute_at_equilibrium).
     */
    LocalSolveStatistics
    rebuild_at_equilibrium(
      const std::size_t                             element,
      const std::vector<LocalQuadraturePoint<dim>> &points,
      const std::vector<Tensor<1, dim>>            &coarse_displacement);

    /** Whether reinit() built element @p element. */
    bool
    is_active(const std::size_t element) const;

    /**
     * Phi_I and grad Phi_I (eqs. 15-16) at x (global coordinates) of the r
     * coarse nodes of @p element, which must be active. x may lie on the
     * element's faces, so both sides of a face can be evaluated.
     */
    void
    evaluate(const std::array<int, dim>         &element,
             const Point<dim>                   &x,
             std::vector<CoarseShapeValue<dim>> &values) const;

    /**
     * Phi_I (eq. 15, without gradients) of the r coarse nodes of the active
     * element @p element at the point where the fine functions are
     * @p stencil (CoarseGrid::fine_stencil).
     */
    void
    values(const std::size_t                            element,
           const typename CoarseGrid<dim>::FineStencil &stencil,
           std::vector<Tensor<2, dim>>                 &phi) const;

    /** The same in the element that contains x. */
    void
    evaluate(const Point<dim>                   &x,
             std::vector<CoarseShapeValue<dim>> &values) const;

    /**
     * The averaged scalar shape function of Phi_I for mass P2G (seed 002
     * Fig. 17): tr(Phi_I) / dim. These sum to one over the coarse nodes
     * because the Phi_I sum to the identity (eq. 34).
     */
    static double
    averaged_scalar(const Tensor<2, dim> &value);

    const CoarseGrid<dim> &
    grid() const;

    const CoarseBoundaryMap<dim> &
    coarse_boundary_map() const;

    /**
     * C of an active element: |u(x)|_inf <= C max_I |Q_I|_inf in the
     * element, the largest absolute row sum of its fine control matrices
     * p^alpha (the fine B-splines are nonnegative and sum to one). Contact
     * uses it to bound how far a particle moves with the coarse nodes.
     */
    double
    interpolation_bound(const std::size_t element) const;

    /**
     * The control values q_k = sum_I p_kI Q_I at all n^dim fine nodes of an
     * active element from the displacements Q of its r local coarse nodes,
     * so that u(x) = sum_k B_k(x) q_k in the element (eq. 15 applied to a
     * field). With them a particle costs what a fine B-spline particle
     * costs: 3^dim fine functions instead of r matrix-valued ones.
     */
    void
    fine_values(const std::size_t                  element,
                const std::vector<Tensor<1, dim>> &coarse,
                std::vector<Tensor<1, dim>>       &fine) const;

    /**
     * The transpose: F_I = sum_k p_kI^T f_k, the forces on the r local
     * coarse nodes that do the same work as the forces @p fine on the fine
     * nodes (seed 002's f_alpha = p_alpha^T f). @p coarse is overwritten.
     */
    void
    coarse_forces(const std::size_t                  element,
                  const std::vector<Tensor<1, dim>> &fine,
                  std::vector<Tensor<1, dim>>       &coarse) const;

    /**
     * The condensed stiffness K_IJ = sum_kl p_kI^T K_kl p_lJ (seed 002's
     * K_alpha = p_alpha^T K p_alpha) of the fine blocks K_kl between the
     * fine nodes @p nodes (in increasing order, so that the sums run in one
     * order whatever the caller): the block of nodes[i] and nodes[j] for i <= j
     * is
     * @p upper[i * m + j] (m = nodes.size()), K symmetric, read only where
     * @p coupled[i * m + j] is nonzero (the others are zero blocks). Blocks
     * of fine nodes more than two apart in a direction share no knot span
     * and are skipped. @p coarse receives all r x r blocks,
     * coarse[I * r + J].
     */
    void
    condense(const std::size_t                  element,
             const std::vector<unsigned int>   &nodes,
             const std::vector<Tensor<2, dim>> &upper,
             const std::vector<char>           &coupled,
             std::vector<Tensor<2, dim>>       &coarse) const;

    /** p_i of an active element, control[i * r + I] (BoundaryInteriorMap). */
    const std::vector<Tensor<2, dim>> &
    interior_control(const std::size_t element) const;

  private:
    const CoarseGrid<dim>                   &coarse_grid;
    CoarseBoundaryMap<dim>                   psi;
    BoundaryInteriorMap<dim>                 condensation;
    std::vector<std::vector<Tensor<2, dim>>> control;
    /** interpolation_bound() of each element. */
    std::vector<double> bound;
    /** The largest absolute row sum of psi over the boundary fine nodes. */
    double boundary_bound = 0.;

    /** Builds element @p element's control and bound from its particles. */
    void
    build(const std::size_t                             element,
          const std::vector<LocalQuadraturePoint<dim>> &points);

    /** interpolation_bound() of @p element from its control. */
    void
    update_bound(const std::size_t element);
  };
} // namespace bfemp

#endif
