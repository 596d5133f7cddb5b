#ifndef bfemp_cmpm_cmpm_regularization_term_h
#define bfemp_cmpm_cmpm_regularization_term_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace bfemp
{
  /**
   * Ties the coarse nodes that the particles barely see to the affine
   * motion of their elements (bfemp's addition, not in seed 002; see
   * doc/cmpm.md "Weakly seen coarse nodes"):
   * @f[
   *   E(u) = \frac{1}{2} \sum_e \sum_{I \in e} \kappa_I^e
   *          \big| [(\mathbf 1 - P_e)\, u]_I \big|^2, \quad
   *   \kappa_I^e = r \max(0, \bar m_e - m_I),
   * @f]
   * over the elements e holding particles and their coarse nodes I that
   * are unknowns: u is the step's displacement, m_I the node's mass
   * (sum_p m_p |Phi_Ip|), m_e the mean of the element's m_I, and P_e the
   * least-squares fit of nodal values by a field affine in the node
   * positions X_I, weighted by m_I (the same for each displacement
   * component), so that the nodes the particles see well set the affine
   * motion and the weak ones follow.
   *
   * Why: the consistent inertia sum_p m_p |Phi_p u - u^_p|^2 holds a node
   * that the particles see with weights eps by about eps^2 m, far less
   * than the elasticity couples into it. A node outside the body in the
   * outer ring of an element's connectivity, or far from the few particles
   * of a partly filled element, has eps of 1e-5 or less; held only by the
   * 1e-8 lumped floor it moved 4e4 times as far as the particles in one
   * step of prm/cmpm/beam_2d.prm. The particles hardly feel that (their
   * weights are eps), but the coarse-grid output, the largest nodal
   * displacement that bounds the contact broad phase, and Newton's stopping
   * test on nodal increments do.
   *
   * Properties: an affine step displacement costs nothing, and that covers
   * every rigid motion over a step (x -> R x + t is affine) and any
   * homogeneous deformation; E is invariant under a uniform translation of
   * u, so its forces sum to zero and linear momentum is kept exactly;
   * nodes at or above their element's mean mass carry no weight. It acts
   * on u, not on u - u^: the cMPM P2G gives no nodal velocity field that a
   * uniform motion reproduces (the matrix-valued weights are normalised by
   * the scalar marks), so a tie to the nodal predictor deformed a block in
   * free flight. The price is a drag on the non-affine motion of the weak
   * nodes alone.
   */
  template <int dim>
  class CmpmRegularizationTerm : public EnergyTerm<dim>
  {
  public:
    CmpmRegularizationTerm(ParticleSystem<dim>           &particles,
                           const CmpmDiscretization<dim> &cmpm,
                           const DofSpace<dim>           &dofs,
                           const double                   weight);

    /**
     * The elements of this step (after the shape functions and the
     * unknowns are set up), with the nodes' masses m_I in unified
     * numbering.
     */
    void
    reinit(const std::vector<double> &node_mass);

    std::string
    name() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

    double
    value(const Vector<double> &u) const override;

    void
    add_gradient(const Vector<double> &u,
                 Vector<double>       &gradient) const override;

    void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const override;

    /** Elements with a node of nonzero weight in this step. */
    unsigned int
    n_elements() const;

    /** The largest kappa_I^e / (r m_e) of this step: how weak the weakest
     *  node is (0: every node as heavy as its element's mean). */
    double
    largest_relative_weight() const;

  private:
    /** One element's share: its unknowns and (1 - P_e)^T K (1 - P_e). */
    struct Element
    {
      std::size_t               index = 0;
      std::vector<unsigned int> nodes;
      FullMatrix<double>        stiffness;
      double                    relative_weight = 0.;
    };

    /** The element's unknowns and matrix (eq. above); no nodes if none has
     *  a weight. */
    Element
    build_element(const std::array<int, dim> &element) const;

    /** The element's stiffness times its nodal u: dE_e/du_k per node. */
    std::vector<Tensor<1, dim>>
    force(const Element &element, const Vector<double> &u) const;

    ParticleSystem<dim>           &particles;
    const CmpmDiscretization<dim> &cmpm;
    const DofSpace<dim>           &dofs;
    const double                   weight;
    std::vector<double>            node_mass;
    /** In element order, so that the sums are independent of threads. */
    std::vector<Element> elements;
  };
} // namespace bfemp

#endif
