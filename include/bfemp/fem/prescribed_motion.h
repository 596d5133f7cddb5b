#ifndef bfemp_fem_prescribed_motion_h
#define bfemp_fem_prescribed_motion_h

#include <bfemp/fem/prescribed_motion_parameters.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <memory>
#include <set>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The prescribed motion of a node set of one FEM body (prm subsection
   * "prescribed motion", see PrescribedMotionParameters): which nodes it
   * drives, and their positions and velocities as functions of the rest
   * position X and the time t. The implicit solve makes the selected nodes
   * Dirichlet DoFs with x^{n+1} = position(X, t^{n+1}).
   *
   * The motions:
   * - fixed: x(t) = X, v = 0;
   * - expression: x(t) = X + u(X, t) with the user's muParser expressions;
   *   the velocity is a finite difference (see velocity());
   * - rigid: with the keyframes' piecewise-constant velocity v(t) of the
   *   center and angular velocity omega(t), integrated exactly,
   *   c(t) = c0 + int_0^t v, theta(t) = int_0^t omega, and
   *   x(t) = c(t) + R(theta(t)) (X - c0),
   *   v_x(t) = v(t) + omega(t) n x (x(t) - c(t)) (in 2D n x a is a rotated
   *   by +90 degrees). Before the first keyframe the body is at rest; at a
   *   keyframe time the velocity is that of the new keyframe.
   *
   * Thread safety: all const member functions may be called concurrently
   * (e.g. from WorkStream over the nodes). deal.II 9.4's FunctionParser
   * keeps its muParser objects per thread (Threads::ThreadLocalStorage), but
   * its time is the object's state (FunctionTime::set_time), which threads
   * evaluating at different times would race on. The expressions are
   * therefore evaluated through the time-explicit evaluation FunctionParser
   * itself uses, never through set_time(). Copies share the (immutable)
   * parsed expressions.
   */
  template <int dim>
  class PrescribedMotion
  {
  public:
    /** No prescribed nodes (a free body). */
    PrescribedMotion();

    /**
     * Compiles the displacement expressions (motion = expression) and
     * integrates the keyframes (motion = rigid). Throws an InputError naming
     * parameters.where if an expression does not parse.
     */
    explicit PrescribedMotion(
      const PrescribedMotionParameters<dim> &parameters);

    /** False for "nodes = none": the body has no Dirichlet nodes. */
    bool
    active() const;

    /**
     * Whether the node with rest position @p rest_position is driven by
     * this motion; @p node_boundary_ids are the boundary ids of the
     * boundary facets that contain the node (empty for an interior node),
     * as FemMesh::node_boundary_ids() gives them.
     *
     * A box contains a node when it lies inside it or on its faces, up to
     * 1e-10 times the box diagonal (at least 1e-12 m), so nodes that a
     * mesh file stores as 0.99999999999 of a face at 1 are not missed.
     */
    bool
    selects(const Point<dim>                      &rest_position,
            const std::vector<types::boundary_id> &node_boundary_ids) const;

    /** The same for boundary ids given as a set. */
    bool
    selects(const Point<dim>                   &rest_position,
            const std::set<types::boundary_id> &node_boundary_ids) const;

    /** x(t) of the node with rest position @p rest_position. */
    Point<dim>
    position(const Point<dim> &rest_position, const double t) const;

    /**
     * dx/dt. Exact for fixed and rigid motions. For an expression it is the
     * central difference (u(t + h) - u(t - h)) / (2h) with
     * h = 1e-6 max(1, |t|) (relative error about (h/T)^2 for a motion with
     * time scale T, plus 1e-10 |u| / max(1, |t|) from rounding); where
     * 0 <= t < h it is the one-sided second-order difference
     * (-3u(t) + 4u(t + h) - u(t + 2h)) / (2h), so an expression that is
     * only defined for t >= 0 (sqrt(t)) is never evaluated at t < 0.
     */
    Tensor<1, dim>
    velocity(const Point<dim> &rest_position, const double t) const;

    const PrescribedMotionParameters<dim> &
    get_parameters() const;

  private:
    class Expression;

    PrescribedMotionParameters<dim> parameters;

    /** The compiled displacement (motion = expression only). */
    std::shared_ptr<const Expression> displacement;

    /** c(t_k) - c0 and theta(t_k) at every keyframe time t_k. */
    std::vector<Tensor<1, dim>> center_displacement_at_keyframe;
    std::vector<double>         angle_at_keyframe;

    /** u(X, t) = x - X (motion = expression). */
    Tensor<1, dim>
    expression_displacement(const Point<dim> &rest_position,
                            const double      t) const;

    /**
     * The keyframe whose velocities apply at time @p t, c(t) - c0 and
     * theta(t); false before the first keyframe (at rest).
     */
    bool
    rigid_state(const double    t,
                unsigned int   &keyframe,
                Tensor<1, dim> &center_displacement,
                double         &angle) const;

    /** R(angle) a: in the plane (2D) or about the rotation axis (3D). */
    Tensor<1, dim>
    rotate(const Tensor<1, dim> &a, const double angle) const;

    /** n x a: a turned by +90 degrees in 2D. */
    Tensor<1, dim>
    axis_cross(const Tensor<1, dim> &a) const;
  };
} // namespace bfemp

#endif
