// Entries that hold one muParser expression per component separate the
// components with commas, and so do muParser's functions of several
// arguments: '0, 5000*min(t/0.05, 1)' is two components, not three. The
// surface load's traction (the ramp that doc/parameters names as its
// example), a position field (initial velocity / displacement) and a
// prescribed FEM motion are read here with such functions and evaluated
// against the values worked out by hand; unbalanced parentheses and a wrong
// count are refused with messages that name the entry.

#include <bfemp/base/input_error.h>
#include <bfemp/base/position_field.h>
#include <bfemp/fem/prescribed_motion.h>
#include <bfemp/fem/prescribed_motion_parameters.h>
#include <bfemp/particles/surface_load.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <string>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  SurfaceLoad<dim>
  surface_load(const std::string &traction)
  {
    ParameterHandler prm;
    SurfaceLoad<dim>::declare_parameters(prm);
    prm.set("traction", traction);
    SurfaceLoad<dim> load;
    load.parse_parameters(prm, "body 0/surface load 0");
    return load;
  }

  /** The InputError message that @p read throws, or "" if it throws
   *  none. */
  template <typename Read>
  std::string
  refusal(const Read &read)
  {
    try
      {
        read();
      }
    catch (const InputError &error)
      {
        return error.what();
      }
    return "";
  }

  std::string
  traction_refusal(const std::string &traction)
  {
    return refusal([&]() { surface_load<2>(traction); });
  }

  std::string
  position_field_refusal(const std::string &text)
  {
    return refusal([&]() {
      PositionField<2> field;
      field.parse(text, "body 0", "initial velocity");
    });
  }

  template <int dim>
  double
  distance(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
  {
    return (a - b).norm();
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();

  // the ramp of doc/parameters' example: 2500 N/m^2 half-way, 5000 after
  {
    const SurfaceLoad<2> load = surface_load<2>("0, 5000*min(t/0.05, 1)");
    const double         half =
      distance(load.traction(0.025), Tensor<1, 2>({0., 2500.}));
    const double full = distance(load.traction(0.1), Tensor<1, 2>({0., 5000.}));
    deallog << "2D ramp: t(0.025) = " << load.traction(0.025)
            << ", t(0.1) = " << load.traction(0.1) << std::endl;
    bfemp_tests::check(half < 1e-9 && full < 1e-9,
                       "2D traction with min(t/0.05, 1) is two components");
  }
  {
    const SurfaceLoad<3> load =
      surface_load<3>("max(0, -1), 0, -1000*min(t, 2)");
    const double at_1 =
      distance(load.traction(1.), Tensor<1, 3>({0., 0., -1000.}));
    const double at_3 =
      distance(load.traction(3.), Tensor<1, 3>({0., 0., -2000.}));
    deallog << "3D: t(1) = " << load.traction(1.)
            << ", t(3) = " << load.traction(3.) << std::endl;
    bfemp_tests::check(at_1 < 1e-9 && at_3 < 1e-9,
                       "3D traction with max(0, -1) and min(t, 2)");
  }

  // a position field: 0.1 min(x, y) at (0.3, 0.2) is 0.02
  {
    PositionField<2> field;
    field.parse("0.1*min(x, y), 0", "body 0", "initial velocity");
    const double error =
      distance(field.value(Point<2>(0.3, 0.2)), Tensor<1, 2>({0.02, 0.}));
    deallog << "position field: u(0.3, 0.2) = "
            << field.value(Point<2>(0.3, 0.2)) << std::endl;
    bfemp_tests::check(!field.is_constant() && error < 1e-12,
                       "initial velocity with min(x, y) is two components");
  }

  // a prescribed FEM motion (its split was already aware of parentheses;
  // it now shares the helper)
  {
    PrescribedMotionParameters<2> parameters;
    ParameterHandler              prm;
    PrescribedMotionParameters<2>::declare_parameters(prm);
    prm.set("motion", "expression");
    prm.set("displacement", "0, -0.1*min(t, 0.5)");
    parameters.parse_parameters(prm, "body 0/prescribed motion 0");
    const PrescribedMotion<2> motion(parameters);
    const Point<2>            X(0.2, 0.4);
    const double              error =
      distance(motion.position(X, 1.) - X, Tensor<1, 2>({0., -0.05}));
    deallog << "prescribed motion: x(X, 1) - X = " << motion.position(X, 1.) - X
            << std::endl;
    bfemp_tests::check(error < 1e-12, "prescribed motion with min(t, 0.5)");
  }

  // refusals name the entry and what is wrong
  const std::string unbalanced = traction_refusal("0, 5000*min(t/0.05, 1");
  deallog << "refused: " << unbalanced << std::endl;
  bfemp_tests::check(unbalanced.find("entry 'traction'") != std::string::npos &&
                       unbalanced.find("unbalanced") != std::string::npos,
                     "unbalanced parentheses in a traction are refused");
  const std::string three = traction_refusal("0, min(t, 1), 2");
  deallog << "refused: " << three << std::endl;
  bfemp_tests::check(three.find("expected 2 comma-separated") !=
                       std::string::npos,
                     "three components of a 2D traction are refused");
  const std::string closing = position_field_refusal("min(x, y)), 0");
  deallog << "refused: " << closing << std::endl;
  bfemp_tests::check(closing.find("entry 'initial velocity'") !=
                         std::string::npos &&
                       closing.find("unbalanced") != std::string::npos,
                     "a stray ')' in a position field is refused");
}
