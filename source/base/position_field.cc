#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/base/position_field.h>

#include <cmath>
#include <cstdlib>

namespace bfemp
{
  template <int dim>
  void
  PositionField<dim>::parse(const std::string &text,
                            const std::string &where,
                            const std::string &entry)
  {
    using namespace muparser_tools;
    require_input(parentheses_balanced(text),
                  where,
                  entry,
                  text,
                  "the parentheses are unbalanced; expected " +
                    std::to_string(dim) +
                    " comma-separated numbers or expressions");
    components = split_top_level(text, ',');
    require_input(components.size() == dim,
                  where,
                  entry,
                  text,
                  "expected " + std::to_string(dim) +
                    " comma-separated numbers or expressions");
    function.reset();
    bool numbers_only = true;
    for (unsigned int d = 0; d < dim; ++d)
      {
        char *end    = nullptr;
        constant[d]  = std::strtod(components[d].c_str(), &end);
        numbers_only = numbers_only && end != components[d].c_str() &&
                       *end == '\0' && std::isfinite(constant[d]);
      }
    if (numbers_only)
      return;

    // muParser compiles at the first evaluation: syntax errors and unknown
    // names show up there, which is done here, at the grid's origin
    constant                 = Tensor<1, dim>();
    auto              parser = std::make_shared<FunctionParser<dim>>(dim);
    const CerrCapture quiet;
    try
      {
        parser->initialize(dim == 2 ? "x,y" : "x,y,z",
                           components,
                           {{"pi", numbers::PI}});
        for (unsigned int d = 0; d < dim; ++d)
          parser->value(Point<dim>(), d);
      }
    catch (const ExceptionBase &exception)
      {
        throw InputError("subsection '" + where + "', entry '" + entry +
                         "' = " + text +
                         ": not numbers, and muParser rejects it as "
                         "expressions of " +
                         (dim == 2 ? "x, y" : "x, y, z") +
                         " and pi: " + parser_message(exception));
      }
    catch (...)
      {
        throw InputError("subsection '" + where + "', entry '" + entry +
                         "' = " + text + ": cannot be evaluated by muParser");
      }
    function = parser;
  }



  template <int dim>
  bool
  PositionField<dim>::is_constant() const
  {
    return function == nullptr;
  }



  template <int dim>
  Tensor<1, dim>
  PositionField<dim>::value(const Point<dim> &x) const
  {
    if (!function)
      return constant;
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = function->value(x, d);
    return u;
  }



  template <int dim>
  Tensor<2, dim>
  PositionField<dim>::gradient(const Point<dim> &x, const double h) const
  {
    Tensor<2, dim> grad;
    if (!function)
      return grad;
    // (-u(x + 2h) + 8 u(x + h) - 8 u(x - h) + u(x - 2h)) / (12 h): exact
    // for polynomials up to degree 4
    for (unsigned int b = 0; b < dim; ++b)
      {
        Tensor<1, dim> step;
        step[b] = h;
        const Tensor<1, dim> difference =
          -value(x + 2. * step) + 8. * value(x + step) -
          8. * value(Point<dim>(x - step)) + value(Point<dim>(x - 2. * step));
        for (unsigned int a = 0; a < dim; ++a)
          grad[a][b] = difference[a] / (12. * h);
      }
    return grad;
  }



  template <int dim>
  const std::vector<std::string> &
  PositionField<dim>::expressions() const
  {
    return components;
  }



  template class PositionField<2>;
  template class PositionField<3>;
} // namespace bfemp
