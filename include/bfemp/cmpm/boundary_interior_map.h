#ifndef bfemp_cmpm_boundary_interior_map_h
#define bfemp_cmpm_boundary_interior_map_h

#include <bfemp/cmpm/coarse_boundary_map.h>
#include <bfemp/cmpm/coarse_grid.h>
#include <bfemp/material/material.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * One quadrature point of the local equilibrium of a coarse element: a
   * particle inside it (seed 002 Section 5.2 takes the particles as the
   * quadrature of the knot spans).
   */
  template <int dim>
  struct LocalQuadraturePoint
  {
    /** Position in element coordinates [m]. */
    Point<dim> position;
    /** Quadrature weight, the particle's rest volume V_p^0 [m^dim]. */
    double weight = 0.;
    /** The particle's mass m_p [kg]: the body load of the interior modes. */
    double mass = 0.;
    /** F_p^n, the particle's deformation gradient at the step's start. */
    Tensor<2, dim> deformation_gradient;
    /** dP/dF at F_p^n (PSD-projected), the particle's own material. */
    Tensor<4, dim> tangent;
    /** The particle's material: the full-Newton local solve evaluates it
     *  away from F_p^n. */
    const Material<dim> *material = nullptr;
  };



  /** How a full-Newton local solve (seed 002 Section 8.1.4) went. */
  struct LocalSolveStatistics
  {
    /** Newton iterations from the first-Newton-step state. */
    unsigned int iterations = 0;
    /** The element's strain energy (with the fictitious material) at the
     *  first-Newton-step interior displacement [J]. */
    double first_step_energy = 0.;
    /** The same at the converged local equilibrium [J]. */
    double energy = 0.;
    /** |f_i|_inf at the converged state [N]. */
    double residual = 0.;
  };



  /**
   * The boundary-interior map M of seed 002 (eqs. 28-31) of one coarse
   * element, multiplied with the coarse-boundary map Psi (eq. 20): the
   * interior rows of the control matrix p = M Psi,
   * @f[
   *   p_i = -K_i^{-1} K_{ib} \Psi_b ,
   * @f]
   * one dim x dim block per (interior fine node, local coarse node). The
   * boundary rows of p are Psi itself (the identity block of eq. 31).
   *
   * K is the tangent stiffness of the local equilibrium at the step's
   * start (the first Newton step of eq. 28): with the fine patch functions
   * B_k as shape functions and the particles as quadrature, in the same
   * displacement form as bfemp's MPM elasticity term (BFEMP eq. 25),
   * K_{ka,mc} = sum_p V_p^0 (dP/dF)_{abce} (F_p^T grad B_k)_b
   * (F_p^T grad B_m)_e. Knot spans without particles would leave K_i
   * singular (seed 002 Remark 4). Instead of the seed's diagonal shift, a
   * fictitious material of shear modulus eps * c (c the element's mean
   * particle stiffness, eps = `cmpm/empty span stiffness`) fills every knot
   * span, integrated exactly by 2 Gauss points per direction: its stiffness
   * annihilates translations and affine fields like the particles' does,
   * so the map keeps the partition of unity (eq. 34) and the affine
   * reproduction exact, which a diagonal shift would not (doc/cmpm.md).
   * An element without particles is the fictitious material alone.
   */
  template <int dim>
  class BoundaryInteriorMap
  {
  public:
    BoundaryInteriorMap(const CoarseGrid<dim>        &grid,
                        const CoarseBoundaryMap<dim> &psi);

    /**
     * p_i of the element whose particles are @p points, stored as
     * control[i * R + I] for interior fine node i and element unknown I
     * (R = CoarseGrid::n_element_unknowns()): the r local coarse nodes,
     * then, with interior modes, the element's own node, whose block
     * column is the static response K_i^-1 f_i to the body load
     * f_ka = sum_p m_p B_k(x_p) e_a in each direction (bfemp's addition,
     * doc/cmpm.md), scaled so that its largest entry at the particles is 1.
     */
    void
    compute(const std::vector<LocalQuadraturePoint<dim>> &points,
            std::vector<Tensor<2, dim>>                  &control) const;

    /**
     * The `full Newton` local solve (seed 002 Section 8.1.4): with the
     * boundary fine nodes at q_b = Psi_b Q (@p coarse_displacement: Q_I of
     * the r local coarse nodes), the interior fine nodes are moved to the
     * local equilibrium f_i(q_b, q_i) = 0 of the particles' own nonlinear
     * materials, by Newton's method with a backtracking line search on the
     * element's strain energy that keeps det F_p > 0, started from the
     * first-Newton-step state q_i = p_i Q. The control is then eq. 30 with
     * the tangent at that equilibrium, p_i = -K_i(q)^-1 K_ib(q) Psi_b. Each
     * point needs its material. Throws SimulationError if the local
     * solve does not converge.
     */
    LocalSolveStatistics
    compute_at_equilibrium(
      const std::vector<LocalQuadraturePoint<dim>> &points,
      const std::vector<Tensor<1, dim>>            &coarse_displacement,
      std::vector<Tensor<2, dim>>                  &control) const;

  private:
    using FineStencil = typename CoarseGrid<dim>::FineStencil;

    /** The fine stencil of every point, evaluated once per element so that
     *  the stiffness, the interior modes' load and their scaling share it. */
    void
    gather_stencils(const std::vector<LocalQuadraturePoint<dim>> &points,
                    std::vector<FineStencil> &stencils) const;

    /** compute() with the points' fine stencils already gathered. */
    void
    compute(const std::vector<LocalQuadraturePoint<dim>> &points,
            const std::vector<FineStencil>               &stencils,
            std::vector<Tensor<2, dim>>                  &control) const;

    /** The weight of the fictitious material: eps times the points' mean
     *  stiffness scale, or 1 without points. */
    double
    fictitious_weight(
      const std::vector<LocalQuadraturePoint<dim>> &points) const;

    /** Eq. 30 for every coarse column at once, control = -K_i^-1 R, and
     *  the interior modes' columns K_i^-1 f_i from the points' masses. */
    void
    condense(const FullMatrix<double>                     &K_i,
             const FullMatrix<double>                     &R,
             const std::vector<LocalQuadraturePoint<dim>> &points,
             const std::vector<FineStencil>               &stencils,
             std::vector<Tensor<2, dim>>                  &control) const;

    /** Scales the interior modes' column of @p control so that its
     *  largest entry at the points (their @p stencils) is 1. */
    void
    normalize_mode(const std::vector<FineStencil> &stencils,
                   std::vector<Tensor<2, dim>>    &control) const;

    /** Adds one quadrature point's w (dP/dF)-weighted products to the
     *  node blocks (i, j <= i) of K_i and to R = K_ib Psi_b; @p stencil is
     *  the point's fine stencil. mirror_lower_triangle() completes K_i. */
    void
    add_point(const LocalQuadraturePoint<dim> &point,
              const FineStencil               &stencil,
              FullMatrix<double>              &K_i,
              FullMatrix<double>              &R) const;

    /** K_i(r, c) <- K_i(c, r) above the diagonal: completes the symmetric
     *  K_i of which add_point() sums the lower node blocks. */
    static void
    mirror_lower_triangle(FullMatrix<double> &K_i);

    const CoarseGrid<dim>        &grid;
    const CoarseBoundaryMap<dim> &psi;
    /** K_i and K_ib Psi_b of the fictitious material (mu = 1, lambda = 0). */
    FullMatrix<double> fictitious_K_i;
    FullMatrix<double> fictitious_R;
  };
} // namespace bfemp

#endif
