#ifndef bfemp_cmpm_cmpm_parameters_h
#define bfemp_cmpm_cmpm_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "cmpm": the coarsened C1 matrix-valued B-spline-patch
   * shape functions of seed 002 (Sections 3-7). The coarse element span H is
   * the grid's `cell size`. The boundary-interior map takes the seed's
   * default local solve, one Newton step of the local equilibrium (eqs.
   * 28-31), or the full Newton solve of Section 8.1.4.
   */
  struct CmpmParameters
  {
    /**
     * How the coarse nodes set the boundary fine nodes (the coarse-boundary
     * map Psi, seed 002 Section 5.1).
     */
    enum class ElementType
    {
      /** Quadratic B-spline volume on all coarse nodes (Section 5.1.1). */
      bspline,
      /**
       * One quadratic B-spline curve (2D) or surface (3D) per element face,
       * extruded (Section 5.1.2, eqs. 25-26 and 36-37).
       */
      boundary_bspline,
      /**
       * Element-local multilinear interpolation of the element's 2^dim
       * corner nodes: the C0 coarse element the seed compares against (not
       * part of cMPM; for comparisons and the C1 test).
       */
      multilinear
    };

    /**
     * How the boundary-interior map M solves the local equilibrium of a
     * coarse element (seed 002 Section 5.2 and 8.1.4).
     */
    enum class LocalSolve
    {
      /** One Newton step from the step's start, eq. 30: M from the tangent
       *  at F_p^n (the seed's default). */
      first_newton_step,
      /**
       * The local equilibrium solved to convergence under the boundary
       * displacement a first pass of the step reached; M from the tangent
       * there, and the step solved again with it (see doc/cmpm.md).
       */
      full_newton
    };

    /**
     * Extra shape functions of an element that vanish on its boundary fine
     * nodes (bfemp's addition beyond seed 002, see doc/cmpm.md "Interior
     * body-load modes").
     */
    enum class InteriorModes
    {
      /** The seed's space: eq. 30 with f_i = 0 only. */
      none,
      /**
       * One element-owned unknown (dim components) per element: the static
       * response K_i^-1 f_i of the interior fine nodes, with the boundary
       * fine nodes held, to a uniform body load on the element's particles
       * in each direction.
       */
      body_load
    };

    /**
     * The form of the blocks of the boundary-interior map (seed 002
     * Remark 1).
     */
    enum class ShapeFunctionForm
    {
      /** Full dim x dim blocks: the local problem couples the components
       *  (cMPM). */
      matrix,
      /**
       * Diagonal blocks: the local problem keeps only the K blocks that act
       * within one displacement component, so each component is condensed
       * on its own. With the multilinear element this is the seed's
       * "Diagonal" baseline of Section 8.2.1 on bfemp's fine patch.
       */
      diagonal
    };

    /** `cmpm/enabled`: the MPM bodies use cMPM instead of the grid kernel. */
    bool enabled = false;
    /** `cmpm/coarse element type`. */
    ElementType element_type = ElementType::boundary_bspline;
    /** `cmpm/coarse node span`: coarse node spacings per coarse element
     *  edge, 1 (L = H), 2 (L = H/2, the seed's default) or 3 (L = H/3, the
     *  seed's Section 8.2.1). */
    unsigned int nodes_per_span = 2;
    /** `cmpm/fine nodes per direction`: n >= 5, the seed's default 7. */
    unsigned int n_fine = 7;
    /**
     * `cmpm/empty span stiffness`: the stiffness, relative to the element's
     * mean particle stiffness, of a fictitious material added to every knot
     * span so that K_i stays invertible where spans hold no particle (the
     * role of the seed's diagonal shift, Remark 4; see doc/cmpm.md).
     */
    double empty_span_stiffness = 1e-6;
    /**
     * `cmpm/weak node regularization`: r of CmpmRegularizationTerm, which
     * ties the coarse nodes that the particles barely see to the affine
     * motion of their elements (bfemp's addition; 0 switches it off).
     */
    double weak_node_regularization = 1e-2;

    /** `cmpm/local solve`. */
    LocalSolve local_solve = LocalSolve::first_newton_step;

    /** `cmpm/shape function form`. */
    ShapeFunctionForm shape_function_form = ShapeFunctionForm::matrix;

    /** `cmpm/interior modes`. */
    InteriorModes interior_modes = InteriorModes::none;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** "B-spline", "boundary B-spline" or "multilinear". */
    static std::string
    to_string(const ElementType type);

    /** `cmpm/coarse node span` as written in a prm file: "H", "H/2" or
     *  "H/3" for 1, 2 or 3 node spacings per coarse element edge. */
    static std::string
    node_span_to_string(const unsigned int nodes_per_span);
  };
} // namespace bfemp

#endif
