#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/particles/body_parameters.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdlib>

namespace bfemp
{
  template <int dim>
  void
  BodyParameters<dim>::declare_parameters(ParameterHandler  &prm,
                                          const unsigned int n_primitives)
  {
    using namespace parameter_tools;
    prm.declare_entry("number of primitives",
                      "1",
                      Patterns::Integer(1),
                      "[-] Number of 'primitive j' subsections (j = 0, 1, "
                      "...) whose union/difference is the body's shape.");
    prm.declare_entry("particles per cell",
                      "2",
                      Patterns::Integer(1, 10),
                      "[-] Particles per grid cell and direction (2 gives 4 "
                      "per cell in 2D, 8 in 3D).");
    prm.declare_entry("sampling",
                      "regular",
                      Patterns::Selection("regular|jittered"),
                      "[-] regular: sub-cell centres; jittered: one random "
                      "point per sub-cell.");
    prm.declare_entry("jitter seed",
                      "1",
                      Patterns::Integer(0),
                      "[-] Seed of the jittered sampling (runs are "
                      "reproducible).");
    prm.declare_entry(
      "initial velocity",
      components<dim>(0, 0, 0),
      Patterns::Anything(),
      std::string("[m/s] Initial velocity of the particles: ") +
        std::to_string(dim) +
        " comma-separated numbers, or muParser expressions of the rest "
        "position " +
        (dim == 2 ? "x, y" : "x, y, z") +
        " (and pi), e.g. a rotating disk: -2*(y - 0.5), 2*(x - 0.5)");
    MaterialParameters::declare_parameters(prm);
    for (unsigned int j = 0; j < n_primitives; ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        ShapePrimitive<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  unsigned int
  BodyParameters<dim>::parse_number_of_primitives(ParameterHandler &prm)
  {
    return prm.get_integer("number of primitives");
  }



  template <int dim>
  void
  BodyParameters<dim>::parse_initial_velocity(const std::string &text,
                                              const std::string &where)
  {
    using namespace muparser_tools;
    initial_velocity_expressions = Utilities::split_string_list(text, ',');
    require_input(initial_velocity_expressions.size() == dim,
                  where,
                  "initial velocity",
                  text,
                  "expected " + std::to_string(dim) +
                    " comma-separated numbers or expressions");
    velocity_function.reset();
    bool constant = true;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const std::string &component = initial_velocity_expressions[d];
        char              *end       = nullptr;
        initial_velocity[d]          = std::strtod(component.c_str(), &end);
        constant = constant && end != component.c_str() && *end == '\0' &&
                   std::isfinite(initial_velocity[d]);
      }
    if (constant)
      return;

    // muParser compiles at the first evaluation: syntax errors and unknown
    // names show up there, which is done here, at the grid's origin
    initial_velocity         = Tensor<1, dim>();
    auto              parser = std::make_shared<FunctionParser<dim>>(dim);
    const CerrCapture quiet;
    try
      {
        parser->initialize(dim == 2 ? "x,y" : "x,y,z",
                           initial_velocity_expressions,
                           {{"pi", numbers::PI}});
        for (unsigned int d = 0; d < dim; ++d)
          parser->value(Point<dim>(), d);
      }
    catch (const ExceptionBase &exception)
      {
        throw InputError("subsection '" + where +
                         "', entry 'initial velocity' = " + text +
                         ": not numbers, and muParser rejects it as "
                         "expressions of " +
                         (dim == 2 ? "x, y" : "x, y, z") +
                         " and pi: " + parser_message(exception));
      }
    catch (...)
      {
        throw InputError("subsection '" + where +
                         "', entry 'initial velocity' = " + text +
                         ": cannot be evaluated by muParser");
      }
    velocity_function = parser;
  }



  template <int dim>
  Tensor<1, dim>
  BodyParameters<dim>::initial_velocity_at(const Point<dim> &x) const
  {
    if (!velocity_function)
      return initial_velocity;
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = velocity_function->value(x, d);
    return v;
  }



  template <int dim>
  void
  BodyParameters<dim>::parse_parameters(ParameterHandler  &prm,
                                        const std::string &where)
  {
    using namespace parameter_tools;
    particles_per_direction = prm.get_integer("particles per cell");
    jittered                = prm.get("sampling") == "jittered";
    jitter_seed             = prm.get_integer("jitter seed");
    parse_initial_velocity(prm.get("initial velocity"), where);
    material.parse_parameters(prm, where);

    primitives.resize(prm.get_integer("number of primitives"));
    for (unsigned int j = 0; j < primitives.size(); ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        primitives[j].parse_parameters(prm,
                                       where + "/" + numbered("primitive", j));
        prm.leave_subsection();
      }
    require_input(!primitives[0].subtract,
                  where + "/primitive 0",
                  "operation",
                  "subtract",
                  "the first primitive must add material");
  }



  template struct BodyParameters<2>;
  template struct BodyParameters<3>;
} // namespace bfemp
