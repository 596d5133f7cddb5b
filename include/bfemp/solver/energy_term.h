#ifndef bfemp_solver_energy_term_h
#define bfemp_solver_energy_term_h

#include <bfemp/material/tangent_projection.h>
#include <bfemp/solver/node_sparsity.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * Which second derivative EnergyTerm::add_hessian() assembles.
   */
  enum class HessianKind
  {
    /**
     * Every local Hessian (of a particle, element or contact) projected onto
     * the positive semi-definite cone before assembly: the sum is PSD by
     * construction (projected Newton, BFEMP Section 5).
     */
    projected,
    /**
     * The exact second derivative where the term has one; the sum may be
     * indefinite. Terms that are approximations anyway (lagged friction)
     * add the same matrix as for projected.
     */
    exact,
    /**
     * Every local Hessian with its negative eigenvalues replaced by their
     * absolute values before assembly (Chen et al., SIGGRAPH Asia 2024):
     * positive semi-definite like projected, but a direction of negative
     * curvature keeps a curvature of its size instead of none.
     */
    absolute
  };

  /** How the local Hessians of @p kind filter their eigenvalues. */
  inline EigenvalueFilter
  eigenvalue_filter(const HessianKind kind)
  {
    switch (kind)
      {
        case HessianKind::exact:
          return EigenvalueFilter::none;
        case HessianKind::absolute:
          return EigenvalueFilter::absolute;
        default:
          return EigenvalueFilter::clamp;
      }
  }



  /**
   * One additive part of the incremental potential E(u) of BFEMP eq. 22 (and
   * eq. 38 once contact and friction join): inertia, FEM elasticity, MPM
   * elasticity, ... Each is a function of the unified displacement vector u
   * (see DofSpace) and supplies what projected Newton needs: its value,
   * gradient, its Hessian (exact, or with local Hessians projected before
   * assembly) and the largest admissible step along a direction.
   */
  template <int dim>
  class EnergyTerm
  {
  public:
    virtual ~EnergyTerm() = default;

    /** Name for diagnostics and messages. */
    virtual std::string
    name() const = 0;

    /** Adds the node couplings of this term's Hessian. */
    virtual void
    add_couplings(NodeSparsity &sparsity) const = 0;

    /** The term's energy at u; +inf or NaN where it is not defined. */
    virtual double
    value(const Vector<double> &u) const = 0;

    virtual void
    add_gradient(const Vector<double> &u, Vector<double> &gradient) const = 0;

    /**
     * Adds the Hessian at u: the exact one or its positive semi-definite
     * approximation, as @p kind asks.
     */
    virtual void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const = 0;

    /**
     * The smallest t > 0 at which u + t p leaves the term's domain (a det F
     * reaching 0, a contact distance reaching 0); +inf if nothing limits.
     */
    virtual double
    step_bound(const Vector<double> &, const Vector<double> &) const
    {
      return std::numeric_limits<double>::infinity();
    }

    /**
     * The size of the floating-point terms that value() adds up, so that
     * eps * magnitude() bounds its round-off. Elastic energies near rest
     * are small differences of large terms (psi = mu/2 (|F|^2 - dim) - ...),
     * and their round-off, not eps |E|, limits how small an energy change
     * the line search can see.
     */
    virtual double
    magnitude() const
    {
      return 0.;
    }

    /**
     * Terms whose couplings depend on u (contact pairs) register those at u
     * and return true if the current @p pattern lacks some of them; the
     * potential then rebuilds its pattern from add_couplings().
     */
    virtual bool
    couplings_missing(const Vector<double> &, const SparsityPattern &) const
    {
      return false;
    }

    /**
     * Kinematic obstacles (fully prescribed FEM bodies) sit at progress
     * @p from of their motion over the step; step_bound() moves them on to
     * @p to along with u + t p. Terms without obstacles ignore this.
     */
    virtual void
    set_obstacle_path(const double /*from*/, const double /*to*/) const
    {}

    /** Whether step_bound() is a collision (CCD) bound, for statistics. */
    virtual bool
    is_contact() const
    {
      return false;
    }

    /** Smallest contact distance of the term at u (+inf if it has none). */
    virtual double
    minimum_distance(const Vector<double> &) const
    {
      return std::numeric_limits<double>::infinity();
    }

    /** Smallest det F of the term at u (+inf if it has none). */
    virtual double
    minimum_determinant(const Vector<double> &) const
    {
      return std::numeric_limits<double>::infinity();
    }
  };
} // namespace bfemp

#endif
