#ifndef bfemp_contact_friction_term_h
#define bfemp_contact_friction_term_h

#include <bfemp/contact/barrier_term.h>
#include <bfemp/contact/contact_parameters.h>
#include <bfemp/solver/energy_term.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace bfemp
{
  /**
   * The lagged friction pseudo-potential of BFEMP eq. 37, scaled by s =
   * 2 alpha beta dt^2:
   * @f[
   *   s D(u) = s \sum_k \mu_k \lambda_k f_0(\|\bar u_k\|),\qquad
   *   \bar u_k = T_k^T \big(\Delta x_q(u) - \textstyle\sum_a \beta_a
   *   \Delta x_a(u)\big),
   * @f]
   * one pair k per particle and FEM surface in contact. The lagged state
   * (update()) fixes the pair set, the normal force lambda_k = |dB_s/dx_q|
   * (the barrier force of that surface on the particle, eq. 35), the
   * tangent basis T_k orthogonal to the direction from the surface's
   * nearest point to the particle, and that point's barycentric weights
   * beta_a on the nearest facet. Delta x_q is the grid displacement
   * interpolated at the particle (Section 4.3: not the particle velocity,
   * which FLIP decouples from the motion); Delta x_a that of the facet node
   * (obstacles: along their prescribed path). f0, f1 are the mollifiers of
   * eq. 36 with eps_v dt.
   *
   * The Hessian block of a pair, mu lambda Gamma^T T M T^T Gamma with
   * M = f1(y)/y (I - uu^T) + f1'(y) uu^T, is PSD without projection since
   * f1 >= 0 and f1' >= 0.
   */
  template <int dim>
  class FrictionTerm : public EnergyTerm<dim>
  {
  public:
    FrictionTerm(const BarrierTerm<dim>  &barrier,
                 const ContactParameters &parameters);

    /** s = 2 alpha beta dt^2 and dt (the mollifier's eps_v dt). */
    void
    set_scale(const double scale, const double dt);

    /**
     * Widens the mollifier to g eps_v dt (g >= 1) for the passes of a step
     * before its last ('contact/friction pass mollifier factor'); 1 is
     * eq. 36 as written.
     */
    void
    set_mollifier_factor(const double g);

    /** Lags lambda, T, beta and the pair set at u (Algorithm 1, lines 5, 9). */
    void
    update(const Vector<double> &u);

    /** Drops all pairs (start of a step, before the first update). */
    void
    clear();

    unsigned int
    n_pairs() const;

    /**
     * Work of the (lagged) friction forces over the step's displacement at
     * u, sum_k mu lambda f1(y_k) y_k >= 0 [J]: the energy friction removes.
     */
    double
    dissipation(const Vector<double> &u) const;

    /**
     * The friction force on FEM body f from MPM body m at u, keyed (m, f):
     * the reaction of -dD/dx_q (unscaled) over the pairs [N].
     */
    std::map<std::pair<unsigned int, unsigned int>, Tensor<1, dim>>
    forces(const Vector<double> &u) const;

    std::string
    name() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

    bool
    couplings_missing(const Vector<double>  &u,
                      const SparsityPattern &pattern) const override;

    double
    value(const Vector<double> &u) const override;

    double
    magnitude() const override;

    void
    add_gradient(const Vector<double> &u,
                 Vector<double>       &gradient) const override;

    void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const override;

  private:
    struct Pair
    {
      unsigned int                        particle;
      unsigned int                        surface;
      std::array<unsigned int, dim>       facet_nodes;
      std::array<double, dim>             weights;
      std::array<Tensor<1, dim>, dim - 1> basis;
      double                              mu_lambda;
    };

    /** mu lambda f1(|y|)/|y| T y: the force the pair's particle exerts. */
    Tensor<1, dim>
    particle_force(const Pair &pair, const Vector<double> &u) const;

    /** T^T (Delta x_q - sum beta_a Delta x_a) of pair @p k at u. */
    Tensor<1, dim - 1>
    sliding(const Pair &pair, const Vector<double> &u) const;

    /** The pair's unknowns and their factors of the chain rule (the
     *  relative displacement is the one block). */
    void
    chain_rule(const Pair &pair, ChainRule<dim> &rule) const;

    const BarrierTerm<dim>  &barrier;
    const ContactParameters &parameters;
    double                   scale     = 1.;
    double                   threshold = 1.;
    /** eps_v dt, the threshold at mollifier factor 1. */
    double            unwidened_threshold = 1.;
    double            mollifier_factor    = 1.;
    std::vector<Pair> pairs;
    mutable double    last_magnitude = 0.;
    /** A friction pair's clique was new to the barrier's registry. */
    mutable bool couplings_grew = false;
  };
} // namespace bfemp

#endif
