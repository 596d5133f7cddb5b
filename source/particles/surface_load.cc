#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/particles/surface_load.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace bfemp
{
  namespace
  {
    template <int dim>
    std::string
    face_names()
    {
      return dim == 2 ? "x-|x+|y-|y+" : "x-|x+|y-|y+|z-|z+";
    }
  } // namespace



  template <int dim>
  void
  SurfaceLoad<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("face",
                      "y+",
                      Patterns::Selection(face_names<dim>()),
                      "The face of the body's bounding box (at t = 0) that "
                      "carries the load.");
    prm.declare_entry(
      "traction",
      dim == 2 ? "0, 0" : "0, 0, 0",
      Patterns::Anything(),
      "[N/m^2] The traction on the face: " + std::to_string(dim) +
        " comma-separated muParser expressions of the time t [s] and pi, "
        "e.g. '0, -1000*min(t/0.1, 1)' for a downward pressure of 1 kPa "
        "on a y+ face, ramped over 0.1 s. A dead load: its direction does "
        "not turn with the surface. The face's total force, traction times "
        "the face's area (length in 2D), is spread evenly over the "
        "particles of the layer.");
    prm.declare_entry("layer depth",
                      "0",
                      Patterns::Double(0.),
                      "[m] The particles whose rest position lies within "
                      "this depth below the face carry the load; 0 means one "
                      "particle spacing (the outermost layer of particles).");
  }



  template <int dim>
  void
  SurfaceLoad<dim>::parse_parameters(ParameterHandler  &prm,
                                     const std::string &where)
  {
    using muparser_tools::CerrCapture;
    using muparser_tools::parser_message;
    face        = prm.get("face");
    direction   = face[0] - 'x';
    upper       = face[1] == '+';
    layer_depth = prm.get_double("layer depth");

    const std::string text = prm.get("traction");
    require_input(muparser_tools::parentheses_balanced(text),
                  where,
                  "traction",
                  text,
                  "the parentheses are unbalanced; expected " +
                    std::to_string(dim) + " comma-separated expressions of t");
    const std::vector<std::string> components =
      muparser_tools::split_top_level(text, ',');
    require_input(components.size() == dim,
                  where,
                  "traction",
                  text,
                  "expected " + std::to_string(dim) +
                    " comma-separated expressions of t");
    auto              parser = std::make_shared<FunctionParser<1>>(dim);
    const CerrCapture quiet;
    try
      {
        // one space variable that no expression may use, and the time
        parser->initialize("unused_,t",
                           components,
                           {{"pi", numbers::PI}},
                           /*time_dependent=*/true);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double value = parser->value(Point<1>(), d);
            if (!std::isfinite(value))
              throw InputError(
                "subsection '" + where + "', entry 'traction' = " + text +
                ": component " + std::to_string(d) + " is not finite at t = 0");
          }
      }
    catch (const ExceptionBase &exception)
      {
        throw InputError("subsection '" + where +
                         "', entry 'traction' = " + text +
                         ": not valid muParser expressions of t and pi: " +
                         parser_message(exception));
      }
    expressions = parser;
  }



  template <int dim>
  Tensor<1, dim>
  SurfaceLoad<dim>::traction(const double t) const
  {
    Tensor<1, dim> result;
    expressions->set_time(t);
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = expressions->value(Point<1>(), d);
    return result;
  }



  template struct SurfaceLoad<2>;
  template struct SurfaceLoad<3>;
} // namespace bfemp
