#include <bfemp/base/input_error.h>
#include <bfemp/cmpm/cmpm_parameters.h>

namespace bfemp
{
  void
  CmpmParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("cmpm");
    prm.declare_entry("enabled",
                      "false",
                      Patterns::Bool(),
                      "[-] Discretize the MPM bodies with the coarsened C1 "
                      "shape functions of cMPM (seed 002) on coarse elements "
                      "of span H = grid/cell size.");
    prm.declare_entry(
      "coarse element type",
      "boundary B-spline",
      Patterns::Selection("B-spline|boundary B-spline|multilinear"),
      "[-] Coarse-boundary map (seed 002 Section 5.1): a quadratic B-spline "
      "on all coarse nodes around the element (B-spline), one B-spline "
      "curve/surface per element face extruded inward (boundary B-spline, "
      "eqs. 25-26 / 36-37), or the C0 element-local multilinear "
      "interpolation of the corner nodes (multilinear, for comparison).");
    prm.declare_entry("coarse node span",
                      "H/2",
                      Patterns::Selection("H|H/2|H/3"),
                      "[-] Spacing L of the coarse nodes: the element span H, "
                      "H/2 (nodes also at edge and face centres) or H/3 "
                      "(two nodes inside every edge, seed 002 Section 8.2.1).");
    prm.declare_entry("fine nodes per direction",
                      "7",
                      Patterns::Integer(5, 32),
                      "[-] n quadratic B-spline functions per direction in "
                      "each coarse element (n >= 5); the fine knot span is "
                      "s = H / (n - 2).");
    prm.declare_entry("empty span stiffness",
                      "1e-6",
                      Patterns::Double(),
                      "[-] Stiffness of a fictitious material in every fine "
                      "knot span, relative to the element's mean particle "
                      "stiffness: keeps the local condensation solvable where "
                      "spans hold no particle (seed 002 Remark 4) without "
                      "breaking the partition of unity. In [0, 1e-2].");
    prm.declare_entry(
      "weak node regularization",
      "1e-2",
      Patterns::Double(),
      "[-] r: a coarse node whose mass m_I (sum_p m_p |Phi_Ip|) is below the "
      "mean m_e of its element's nodes is tied to the affine motion of the "
      "element's nodes, relative to the predictor, with the weight "
      "r (m_e - m_I). The particles see such nodes with weights near zero, "
      "and without the tie they take arbitrary displacements that inflate "
      "the coarse-grid output and the contact broad phase (doc/cmpm.md). "
      "The tie conserves momentum and leaves affine motion alone. 0 "
      "switches it off. In [0, 1].");
    prm.declare_entry(
      "local solve",
      "first Newton step",
      Patterns::Selection("first Newton step|full Newton"),
      "[-] Local equilibrium behind the boundary-interior map (seed 002 "
      "Sections 5.2, 8.1.4): one Newton step from the step's start with the "
      "particles' tangent at F^n (eq. 30, the seed's default), or the local "
      "equilibrium solved to convergence under the coarse displacement a "
      "first pass of the step reached, M from the tangent there and the step "
      "solved again (about twice the cost).");
    prm.declare_entry(
      "shape function form",
      "matrix",
      Patterns::Selection("matrix|diagonal"),
      "[-] Blocks of the boundary-interior map (seed 002 Remark 1): matrix "
      "(full dim x dim blocks, the local problem couples the components: "
      "cMPM), or diagonal (each displacement component condensed on its own "
      "with the K blocks within that component; with the multilinear "
      "element, the seed's 'Diagonal' baseline of Section 8.2.1).");
    prm.declare_entry(
      "interior modes",
      "none",
      Patterns::Selection("none|body load"),
      "[-] Extra shape functions per coarse element that vanish with their "
      "gradient on the element's faces (bfemp's addition, not in seed 002): "
      "none (the seed's space, eq. 30 with f_i = 0), or body load: one "
      "element-owned unknown of dim components whose shape functions are "
      "the interior's static response K_i^-1 f_i, boundary fine nodes held, "
      "to a uniform body load on the element's particles in each direction. "
      "It lets a soft region move inside a stiffer frame (doc/cmpm.md).");
    prm.leave_subsection();
  }



  void
  CmpmParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("cmpm");
    enabled                = prm.get_bool("enabled");
    const std::string type = prm.get("coarse element type");
    element_type           = type == "B-spline"      ? ElementType::bspline
                             : type == "multilinear" ? ElementType::multilinear
                                                     : ElementType::boundary_bspline;
    const std::string span = prm.get("coarse node span");
    // the entry's pattern admits exactly the three names
    nodes_per_span = 1;
    while (node_span_to_string(nodes_per_span) != span && nodes_per_span < 3)
      ++nodes_per_span;
    const long n             = prm.get_integer("fine nodes per direction");
    empty_span_stiffness     = prm.get_double("empty span stiffness");
    weak_node_regularization = prm.get_double("weak node regularization");
    local_solve              = prm.get("local solve") == "full Newton"
                                 ? LocalSolve::full_newton
                                 : LocalSolve::first_newton_step;
    shape_function_form      = prm.get("shape function form") == "diagonal"
                                 ? ShapeFunctionForm::diagonal
                                 : ShapeFunctionForm::matrix;
    interior_modes           = prm.get("interior modes") == "body load"
                                 ? InteriorModes::body_load
                                 : InteriorModes::none;
    prm.leave_subsection();

    require_input(n >= 5 && n <= 32,
                  "cmpm",
                  "fine nodes per direction",
                  std::to_string(n),
                  "must be in [5, 32]: n - 4 >= 1 interior fine nodes per "
                  "direction are needed for the local condensation");
    n_fine = static_cast<unsigned int>(n);
    require_input(empty_span_stiffness >= 0. && empty_span_stiffness <= 1e-2,
                  "cmpm",
                  "empty span stiffness",
                  to_input_string(empty_span_stiffness),
                  "must be in [0, 1e-2]");
    require_input(weak_node_regularization >= 0. &&
                    weak_node_regularization <= 1.,
                  "cmpm",
                  "weak node regularization",
                  to_input_string(weak_node_regularization),
                  "must be in [0, 1]");
    require_input(!(element_type == ElementType::multilinear &&
                    nodes_per_span != 1),
                  "cmpm",
                  "coarse node span",
                  node_span_to_string(nodes_per_span),
                  "the multilinear coarse element has its nodes at the "
                  "element corners only: use H");
  }



  std::string
  CmpmParameters::to_string(const ElementType type)
  {
    switch (type)
      {
        case ElementType::bspline:
          return "B-spline";
        case ElementType::boundary_bspline:
          return "boundary B-spline";
        default:
          return "multilinear";
      }
  }



  std::string
  CmpmParameters::node_span_to_string(const unsigned int nodes_per_span)
  {
    Assert(nodes_per_span >= 1 && nodes_per_span <= 3,
           ExcIndexRange(nodes_per_span, 1, 4));
    return nodes_per_span == 1 ? "H" : "H/" + std::to_string(nodes_per_span);
  }
} // namespace bfemp
