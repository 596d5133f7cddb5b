#ifndef bfemp_fem_prescribed_motion_parameters_h
#define bfemp_fem_prescribed_motion_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "prescribed motion" of an FEM body (the caller enters
   * it): which nodes follow a motion given as a function of time, and that
   * motion. The selected nodes become Dirichlet DoFs of the implicit solve;
   * PrescribedMotion evaluates their positions and velocities.
   *
   * Everything is checked here, when the prm is read, so a typo in a
   * keyframe list or a muParser expression stops the run before anything is
   * computed, with a message naming the subsection, the entry, the value and
   * the form that is allowed.
   */
  template <int dim>
  struct PrescribedMotionParameters
  {
    /** Entry "nodes". */
    enum class NodeSelection
    {
      /** No node is prescribed: a free body (the default). */
      none,
      /** Every node: the whole body is driven. */
      all,
      /** The nodes whose rest position lies in a box (faces included). */
      box,
      /** The nodes on a boundary facet with a given boundary id. */
      boundary_id
    };

    /** Entry "motion". */
    enum class Motion
    {
      /** The nodes stay at their rest positions. */
      fixed,
      /** x = X + u(X, t) with a muParser expression u. */
      expression,
      /** A rigid motion with piecewise-constant velocities (keyframes). */
      rigid
    };

    /**
     * From time @p time on (until the next keyframe) the rotation center
     * moves with @p velocity and the body turns with @p angular_velocity
     * [rad/s] about the rotation axis (counter-clockwise in 2D).
     */
    struct Keyframe
    {
      double         time;
      Tensor<1, dim> velocity;
      double         angular_velocity;
    };

    /** Entry "nodes". */
    NodeSelection nodes = NodeSelection::none;

    /** Entries "box lower corner" and "box upper corner" [m]. */
    Point<dim> box_lower_corner;
    Point<dim> box_upper_corner;

    /** Entry "boundary id". */
    types::boundary_id boundary_id = 0;

    /** Entry "motion". */
    Motion motion = Motion::fixed;

    /**
     * Entry "displacement": the dim components of u(x, y, [z,] t) [m], one
     * muParser expression each, split at the commas outside parentheses (so
     * "min(x, y)" stays one component).
     */
    std::vector<std::string> displacement;

    /**
     * Entry "constants" ("name=value, ..."), always with pi; the constants
     * the displacement expressions may use.
     */
    std::map<std::string, double> constants;

    /** Entry "rotation center" [m]: c0, the rest position of the center. */
    Point<dim> rotation_center;

    /** Entry "rotation axis" (3D only), normalized; (0, 0, 1) in 2D. */
    Tensor<1, 3> rotation_axis;

    /** Entry "keyframes", times strictly increasing. */
    std::vector<Keyframe> keyframes;

    /** The subsection path given to parse_parameters(), for messages. */
    std::string where = "prescribed motion";

    PrescribedMotionParameters();

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Reads a keyframe list 't: vx, vy[, vz], omega; ...' (entry
     * "keyframes" of subsection @p where); throws an InputError for a
     * malformed keyframe, times that do not increase or an empty list.
     */
    static std::vector<Keyframe>
    parse_keyframes(const std::string &text, const std::string &where);

    /**
     * Reads and checks the entries; @p where is the path of this
     * subsection (e.g. "fem body 0/prescribed motion") for messages. Throws
     * an InputError for malformed keyframes, non-increasing keyframe times,
     * a wrong number of components, a muParser error in the displacement
     * (the parser's message and the expression), a bad constant, a zero
     * rotation axis or an empty box.
     */
    void
    parse_parameters(ParameterHandler &prm, const std::string &where);
  };
} // namespace bfemp

#endif
