#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/fem/prescribed_motion.h>
#include <bfemp/fem/prescribed_motion_parameters.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace bfemp
{
  namespace
  {
    std::string
    trim(const std::string &text)
    {
      return Utilities::trim(text);
    }

    /** @p text as a finite number; false if it is anything else. */
    bool
    read_number(const std::string &text, double &value)
    {
      const std::string trimmed = trim(text);
      if (trimmed.empty())
        return false;
      char *end = nullptr;
      value     = std::strtod(trimmed.c_str(), &end);
      return end == trimmed.c_str() + trimmed.size() && std::isfinite(value);
    }

    bool
    is_identifier(const std::string &name)
    {
      if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) ||
                            name[0] == '_'))
        return false;
      for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
          return false;
      return true;
    }

    template <int dim>
    std::string
    keyframe_form()
    {
      return dim == 2 ? "'time: vx, vy, omega'" : "'time: vx, vy, vz, omega'";
    }

    std::map<std::string, double>
    parse_constants(const std::string &text, const std::string &where)
    {
      const std::string allowed_form =
        "the form is 'name=value, name=value' with names of letters, digits "
        "and '_' (not x, y, z or t) and numbers as values";
      std::map<std::string, double> constants = {{"pi", numbers::PI}};
      for (const std::string &piece : Utilities::split_string_list(text, ','))
        {
          if (piece.empty())
            continue;
          const std::size_t equal = piece.find('=');
          require_input(equal != std::string::npos,
                        where,
                        "constants",
                        text,
                        "'" + piece + "' has no '='; " + allowed_form);
          const std::string name = trim(piece.substr(0, equal));
          require_input(is_identifier(name) && name != "x" && name != "y" &&
                          name != "z" && name != "t",
                        where,
                        "constants",
                        text,
                        "'" + name + "' is not a valid constant name; " +
                          allowed_form);
          double value;
          require_input(read_number(piece.substr(equal + 1), value),
                        where,
                        "constants",
                        text,
                        "the value of '" + name + "' is not a number; " +
                          allowed_form);
          constants[name] = value;
        }
      return constants;
    }
  } // namespace



  template <int dim>
  PrescribedMotionParameters<dim>::PrescribedMotionParameters()
    : displacement(dim, "0")
    , constants{{"pi", numbers::PI}}
  {
    rotation_axis[2] = 1.;
  }



  template <int dim>
  std::vector<typename PrescribedMotionParameters<dim>::Keyframe>
  PrescribedMotionParameters<dim>::parse_keyframes(const std::string &text,
                                                   const std::string &where)
  {
    const std::string allowed_form =
      "the form is " + keyframe_form<dim>() +
      " [s: m/s, rad/s], keyframes separated by ';', e.g. '0: " +
      parameter_tools::components<dim>(1, 0, 0) +
      ", 0.5; 2: " + parameter_tools::components<dim>(0, 0, 0) + ", 0'";

    std::vector<Keyframe> keyframes;
    for (const std::string &piece : Utilities::split_string_list(text, ';'))
      {
        if (piece.empty()) // tolerate a trailing ';'
          continue;
        const std::string keyframe =
          "keyframe " + std::to_string(keyframes.size()) + " ('" + piece + "')";
        const std::size_t colon = piece.find(':');
        require_input(colon != std::string::npos,
                      where,
                      "keyframes",
                      text,
                      keyframe + " has no ':' after the time; " + allowed_form);

        Keyframe frame;
        require_input(read_number(piece.substr(0, colon), frame.time),
                      where,
                      "keyframes",
                      text,
                      keyframe + ": the time '" + trim(piece.substr(0, colon)) +
                        "' is not a number; " + allowed_form);

        const std::vector<std::string> numbers =
          Utilities::split_string_list(piece.substr(colon + 1), ',');
        require_input(numbers.size() == dim + 1,
                      where,
                      "keyframes",
                      text,
                      keyframe + " has " + std::to_string(numbers.size()) +
                        " numbers after the time, expected " +
                        std::to_string(dim + 1) + "; " + allowed_form);
        std::vector<double> values(dim + 1);
        for (unsigned int i = 0; i <= dim; ++i)
          require_input(read_number(numbers[i], values[i]),
                        where,
                        "keyframes",
                        text,
                        keyframe + ": '" + numbers[i] + "' is not a number; " +
                          allowed_form);
        for (unsigned int d = 0; d < dim; ++d)
          frame.velocity[d] = values[d];
        frame.angular_velocity = values[dim];

        if (!keyframes.empty())
          require_input(frame.time > keyframes.back().time,
                        where,
                        "keyframes",
                        text,
                        "keyframe times must increase strictly, but " +
                          keyframe + " at t = " + to_input_string(frame.time) +
                          " follows t = " +
                          to_input_string(keyframes.back().time));
        keyframes.push_back(frame);
      }
    require_input(!keyframes.empty(),
                  where,
                  "keyframes",
                  "'" + text + "'",
                  "a rigid motion needs at least one keyframe; " +
                    allowed_form);
    return keyframes;
  }



  template <int dim>
  void
  PrescribedMotionParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    prm.declare_entry("nodes",
                      "none",
                      Patterns::Selection("none|all|box|boundary id"),
                      "[-] The nodes whose motion is prescribed: none (a free "
                      "body), all, those whose rest position lies in the box "
                      "(faces included), or those on boundary facets with "
                      "'boundary id'.");
    declare_point<dim>(prm,
                       "box lower corner",
                       components<dim>(0, 0, 0),
                       "[m] nodes = box: lower corner");
    declare_point<dim>(prm,
                       "box upper corner",
                       components<dim>(0, 0, 0),
                       "[m] nodes = box: upper corner (>= lower corner; a "
                       "flat box selects the nodes of a plane)");
    prm.declare_entry("boundary id",
                      "0",
                      Patterns::Integer(0),
                      "[-] nodes = boundary id: the boundary id (gmsh physical "
                      "tag) of the facets whose nodes are prescribed.");
    prm.declare_entry("motion",
                      "fixed",
                      Patterns::Selection("fixed|expression|rigid"),
                      "[-] fixed: the nodes stay at rest; expression: x = X + "
                      "u(X, t) with 'displacement'; rigid: rotation and "
                      "translation with piecewise-constant velocities from "
                      "'keyframes'.");
    prm.declare_entry("displacement",
                      components<dim>(0, 0, 0),
                      Patterns::Anything(),
                      std::string("[m] motion = expression: u as ") +
                        std::to_string(dim) +
                        " comma-separated muParser expressions of the rest "
                        "position (" +
                        (dim == 2 ? "x, y" : "x, y, z") +
                        ") and the time t, e.g. '0.1*sin(2*pi*t)*x, 0'.");
    prm.declare_entry("constants",
                      "",
                      Patterns::Anything(),
                      "[-] motion = expression: constants for the "
                      "displacement, 'name=value, ...'; pi is always "
                      "defined.");
    declare_point<dim>(prm,
                       "rotation center",
                       components<dim>(0, 0, 0),
                       "[m] motion = rigid: the rest position c0 of the "
                       "center, which moves with the keyframe velocities");
    if (dim == 3)
      declare_point<dim>(prm,
                         "rotation axis",
                         components<dim>(0, 0, 1),
                         "[-] motion = rigid: the axis of the angular "
                         "velocity (nonzero; normalized)");
    prm.declare_entry(
      "keyframes",
      dim == 2 ? "0: 0, 0, 0" : "0: 0, 0, 0, 0",
      Patterns::Anything(),
      "[s: m/s, rad/s] motion = rigid: '" +
        std::string(dim == 2 ? "t: vx, vy, omega" : "t: vx, vy, vz, omega") +
        "; ...', from time t on (times increasing) the "
        "center moves with velocity v and the body turns "
        "with angular velocity omega" +
        (dim == 2 ? " (counter-clockwise)" : " about 'rotation axis'") +
        "; at rest before the first time.");
  }



  template <int dim>
  void
  PrescribedMotionParameters<dim>::parse_parameters(ParameterHandler  &prm,
                                                    const std::string &where)
  {
    using namespace parameter_tools;
    this->where = where;

    const std::string selection = prm.get("nodes");
    nodes                       = selection == "all"    ? NodeSelection::all
                                  : selection == "box"  ? NodeSelection::box
                                  : selection == "none" ? NodeSelection::none
                                                        : NodeSelection::boundary_id;
    box_lower_corner            = get_point<dim>(prm, "box lower corner");
    box_upper_corner            = get_point<dim>(prm, "box upper corner");
    const long id               = prm.get_integer("boundary id");
    require_input(id >= 0 &&
                    id < static_cast<long>(numbers::internal_face_boundary_id),
                  where,
                  "boundary id",
                  std::to_string(id),
                  "must be >= 0 and < " +
                    std::to_string(numbers::internal_face_boundary_id));
    boundary_id = static_cast<types::boundary_id>(id);

    const std::string kind = prm.get("motion");
    motion                 = kind == "fixed"        ? Motion::fixed
                             : kind == "expression" ? Motion::expression
                                                    : Motion::rigid;

    const std::string expression = prm.get("displacement");
    displacement = muparser_tools::split_top_level(expression, ',');
    constants    = parse_constants(prm.get("constants"), where);

    rotation_center  = get_point<dim>(prm, "rotation center");
    rotation_axis    = Tensor<1, 3>();
    rotation_axis[2] = 1.;
    if (dim == 3)
      {
        const Tensor<1, dim> axis = get_vector<dim>(prm, "rotation axis");
        if (motion == Motion::rigid)
          require_input(axis.norm() > 0.,
                        where,
                        "rotation axis",
                        to_input_string(Point<dim>(axis)),
                        "must be a nonzero vector");
        if (axis.norm() > 0.)
          for (unsigned int d = 0; d < dim; ++d)
            rotation_axis[d] = axis[d] / axis.norm();
      }

    keyframes.clear();
    if (motion == Motion::rigid)
      keyframes = parse_keyframes(prm.get("keyframes"), where);

    if (nodes == NodeSelection::box)
      for (unsigned int d = 0; d < dim; ++d)
        require_input(box_upper_corner[d] >= box_lower_corner[d],
                      where,
                      "box upper corner",
                      to_input_string(box_upper_corner),
                      "must be >= 'box lower corner' (" +
                        to_input_string(box_lower_corner) +
                        ") in every direction");

    if (motion == Motion::expression)
      {
        require_input(muparser_tools::parentheses_balanced(expression),
                      where,
                      "displacement",
                      expression,
                      "the parentheses are unbalanced; expected " +
                        std::to_string(dim) +
                        " comma-separated muParser expressions");
        require_input(displacement.size() == dim,
                      where,
                      "displacement",
                      expression,
                      "has " + std::to_string(displacement.size()) +
                        " comma-separated components, expected " +
                        std::to_string(dim) + " (functions of " +
                        (dim == 2 ? "x, y, t" : "x, y, z, t") + ")");
        for (unsigned int d = 0; d < dim; ++d)
          require_input(!displacement[d].empty(),
                        where,
                        "displacement",
                        expression,
                        "component " + std::to_string(d) +
                          " is empty; expected " + std::to_string(dim) +
                          " comma-separated expressions");
        // Compiles and evaluates the expressions once, so muParser's
        // syntax errors surface now (as InputError) rather than mid-run.
        const PrescribedMotion<dim> check(*this);
        (void)check;
      }
  }



  template struct PrescribedMotionParameters<2>;
  template struct PrescribedMotionParameters<3>;
} // namespace bfemp
