#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/fem/prescribed_motion.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace bfemp
{
  /**
   * The displacement u(X, t) as a FunctionParser that is evaluated at an
   * explicit time. FunctionParser::value() takes the time from the
   * object's FunctionTime state; the protected do_value(p, t, component) it
   * forwards to reads only the per-thread muParser objects and const data,
   * so concurrent calls at different times are safe.
   */
  template <int dim>
  class PrescribedMotion<dim>::Expression : public FunctionParser<dim>
  {
  public:
    Expression()
      : FunctionParser<dim>(dim)
    {}

    double
    value_at(const Point<dim>  &rest_position,
             const double       t,
             const unsigned int component) const
    {
      return this->do_value(rest_position, t, component);
    }
  };



  namespace
  {
    using muparser_tools::CerrCapture;
    using muparser_tools::parser_message;

    std::string
    joined(const std::vector<std::string> &expressions)
    {
      std::string result;
      for (unsigned int d = 0; d < expressions.size(); ++d)
        result += (d > 0 ? ", " : "") + expressions[d];
      return result;
    }
  } // namespace



  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion() = default;



  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion(
    const PrescribedMotionParameters<dim> &parameters)
    : parameters(parameters)
  {
    using Motion             = typename PrescribedMotionParameters<dim>::Motion;
    const std::string &where = parameters.where;

    if (parameters.motion == Motion::expression)
      {
        const std::string expression = joined(parameters.displacement);
        require_input(parameters.displacement.size() == dim,
                      where,
                      "displacement",
                      expression,
                      "expected " + std::to_string(dim) +
                        " comma-separated components");
        auto parser = std::make_shared<Expression>();
        {
          const CerrCapture quiet;
          try
            {
              parser->initialize(dim == 2 ? "x,y,t" : "x,y,z,t",
                                 parameters.displacement,
                                 parameters.constants,
                                 /*time_dependent=*/true);
            }
          catch (const ExceptionBase &exception)
            {
              throw InputError(
                "subsection '" + where +
                "', entry 'displacement' = " + expression +
                ": muParser rejects it: " + parser_message(exception));
            }
          // muParser compiles an expression at its first evaluation, which
          // is where syntax errors and unknown names show up.
          for (unsigned int d = 0; d < dim; ++d)
            try
              {
                parser->value_at(Point<dim>(), 0., d);
              }
            catch (const ExceptionBase &exception)
              {
                throw InputError(
                  "subsection '" + where +
                  "', entry 'displacement' = " + expression + ": component " +
                  std::to_string(d) + " ('" + parameters.displacement[d] +
                  "') is not a valid muParser expression of " +
                  (dim == 2 ? "x, y, t" : "x, y, z, t") +
                  " and the constants (pi" +
                  (parameters.constants.size() > 1 ? ", ..." : "") +
                  "): " + parser_message(exception));
              }
            catch (...)
              {
                throw InputError(
                  "subsection '" + where +
                  "', entry 'displacement' = " + expression + ": component " +
                  std::to_string(d) + " ('" + parameters.displacement[d] +
                  "') cannot be evaluated by muParser (check the names in "
                  "'constants')");
              }
        }
        displacement = parser;
      }

    if (parameters.motion == Motion::rigid)
      {
        require_input(!parameters.keyframes.empty(),
                      where,
                      "keyframes",
                      "''",
                      "a rigid motion needs at least one keyframe");
        center_displacement_at_keyframe.resize(parameters.keyframes.size());
        angle_at_keyframe.resize(parameters.keyframes.size(), 0.);
        for (unsigned int k = 1; k < parameters.keyframes.size(); ++k)
          {
            const auto  &previous = parameters.keyframes[k - 1];
            const double duration =
              parameters.keyframes[k].time - previous.time;
            require_input(duration > 0.,
                          where,
                          "keyframes",
                          to_input_string(parameters.keyframes[k].time),
                          "keyframe times must increase strictly");
            center_displacement_at_keyframe[k] =
              center_displacement_at_keyframe[k - 1] +
              duration * previous.velocity;
            angle_at_keyframe[k] =
              angle_at_keyframe[k - 1] + duration * previous.angular_velocity;
          }
        if (dim == 3)
          require_input(std::abs(parameters.rotation_axis.norm() - 1.) < 1e-12,
                        where,
                        "rotation axis",
                        to_input_string(Point<3>(parameters.rotation_axis)),
                        "must be a unit vector (parse_parameters normalizes "
                        "it)");
      }
  }



  template <int dim>
  bool
  PrescribedMotion<dim>::active() const
  {
    return parameters.nodes !=
           PrescribedMotionParameters<dim>::NodeSelection::none;
  }



  template <int dim>
  bool
  PrescribedMotion<dim>::selects(
    const Point<dim>                      &rest_position,
    const std::vector<types::boundary_id> &node_boundary_ids) const
  {
    using NodeSelection =
      typename PrescribedMotionParameters<dim>::NodeSelection;
    switch (parameters.nodes)
      {
        case NodeSelection::none:
          return false;
        case NodeSelection::all:
          return true;
        case NodeSelection::box:
          {
            const double tolerance =
              std::max(1e-10 * parameters.box_upper_corner.distance(
                                 parameters.box_lower_corner),
                       1e-12);
            for (unsigned int d = 0; d < dim; ++d)
              if (rest_position[d] <
                    parameters.box_lower_corner[d] - tolerance ||
                  rest_position[d] > parameters.box_upper_corner[d] + tolerance)
                return false;
            return true;
          }
        case NodeSelection::boundary_id:
          return std::find(node_boundary_ids.begin(),
                           node_boundary_ids.end(),
                           parameters.boundary_id) != node_boundary_ids.end();
      }
    return false;
  }



  template <int dim>
  bool
  PrescribedMotion<dim>::selects(
    const Point<dim>                   &rest_position,
    const std::set<types::boundary_id> &node_boundary_ids) const
  {
    return selects(rest_position,
                   std::vector<types::boundary_id>(node_boundary_ids.begin(),
                                                   node_boundary_ids.end()));
  }



  template <int dim>
  Tensor<1, dim>
  PrescribedMotion<dim>::expression_displacement(
    const Point<dim> &rest_position,
    const double      t) const
  {
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      {
        u[d] = displacement->value_at(rest_position, t, d);
        if (!std::isfinite(u[d]))
          throw InputError(
            "subsection '" + parameters.where +
            "', entry 'displacement': component " + std::to_string(d) + " ('" +
            parameters.displacement[d] +
            "') is not finite at the rest position (" +
            to_input_string(rest_position) + ") and t = " + to_input_string(t));
      }
    return u;
  }



  template <int dim>
  bool
  PrescribedMotion<dim>::rigid_state(const double    t,
                                     unsigned int   &keyframe,
                                     Tensor<1, dim> &center_displacement,
                                     double         &angle) const
  {
    const auto &keyframes = parameters.keyframes;
    // the first keyframe with time > t; the one before it applies
    const auto next =
      std::upper_bound(keyframes.begin(),
                       keyframes.end(),
                       t,
                       [](const double time, const auto &frame) {
                         return time < frame.time;
                       });
    if (next == keyframes.begin())
      return false;
    keyframe             = (next - keyframes.begin()) - 1;
    const double elapsed = t - keyframes[keyframe].time;
    center_displacement  = center_displacement_at_keyframe[keyframe] +
                          elapsed * keyframes[keyframe].velocity;
    angle = angle_at_keyframe[keyframe] +
            elapsed * keyframes[keyframe].angular_velocity;
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  PrescribedMotion<dim>::rotate(const Tensor<1, dim> &a,
                                const double          angle) const
  {
    const double   c = std::cos(angle), s = std::sin(angle);
    Tensor<1, dim> result;
    if constexpr (dim == 2)
      {
        result[0] = c * a[0] - s * a[1];
        result[1] = s * a[0] + c * a[1];
      }
    else
      {
        // Rodrigues: R a = a cos + (n x a) sin + n (n . a)(1 - cos)
        const Tensor<1, 3> &n = parameters.rotation_axis;
        result = c * a + s * cross_product_3d(n, a) + ((1. - c) * (n * a)) * n;
      }
    return result;
  }



  template <int dim>
  Tensor<1, dim>
  PrescribedMotion<dim>::axis_cross(const Tensor<1, dim> &a) const
  {
    Tensor<1, dim> result;
    if constexpr (dim == 2)
      {
        result[0] = -a[1];
        result[1] = a[0];
      }
    else
      result = cross_product_3d(parameters.rotation_axis, a);
    return result;
  }



  template <int dim>
  Point<dim>
  PrescribedMotion<dim>::position(const Point<dim> &rest_position,
                                  const double      t) const
  {
    using Motion = typename PrescribedMotionParameters<dim>::Motion;
    switch (parameters.motion)
      {
        case Motion::fixed:
          return rest_position;
        case Motion::expression:
          return rest_position + expression_displacement(rest_position, t);
        case Motion::rigid:
          {
            unsigned int   keyframe;
            Tensor<1, dim> center_displacement;
            double         angle;
            if (!rigid_state(t, keyframe, center_displacement, angle))
              return rest_position;
            return parameters.rotation_center + center_displacement +
                   rotate(rest_position - parameters.rotation_center, angle);
          }
      }
    return rest_position;
  }



  template <int dim>
  Tensor<1, dim>
  PrescribedMotion<dim>::velocity(const Point<dim> &rest_position,
                                  const double      t) const
  {
    using Motion = typename PrescribedMotionParameters<dim>::Motion;
    switch (parameters.motion)
      {
        case Motion::fixed:
          return Tensor<1, dim>();
        case Motion::expression:
          {
            const double h = 1e-6 * std::max(1., std::abs(t));
            if (t >= 0. && t < h)
              return (-3. * expression_displacement(rest_position, t) +
                      4. * expression_displacement(rest_position, t + h) -
                      expression_displacement(rest_position, t + 2. * h)) /
                     (2. * h);
            return (expression_displacement(rest_position, t + h) -
                    expression_displacement(rest_position, t - h)) /
                   (2. * h);
          }
        case Motion::rigid:
          {
            unsigned int   keyframe;
            Tensor<1, dim> center_displacement;
            double         angle;
            if (!rigid_state(t, keyframe, center_displacement, angle))
              return Tensor<1, dim>();
            const auto &frame = parameters.keyframes[keyframe];
            return frame.velocity +
                   frame.angular_velocity *
                     axis_cross(
                       rotate(rest_position - parameters.rotation_center,
                              angle));
          }
      }
    return Tensor<1, dim>();
  }



  template <int dim>
  const PrescribedMotionParameters<dim> &
  PrescribedMotion<dim>::get_parameters() const
  {
    return parameters;
  }



  template class PrescribedMotion<2>;
  template class PrescribedMotion<3>;
} // namespace bfemp
