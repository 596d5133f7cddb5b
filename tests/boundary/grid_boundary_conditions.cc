// Grid boundary conditions: what sticky, slip and separable slip (with and
// without Coulomb friction) do to a node velocity relative to a moving
// obstacle, and the analytic level sets (half-plane, box, sine wave): sign,
// distance where the level set is one, and a normal that is unit length,
// points out of the obstacle and is perpendicular to the sine curve.

#include <bfemp/base/input_error.h>
#include <bfemp/boundary/boundary_condition.h>
#include <bfemp/boundary/level_set.h>

#include <deal.II/base/numbers.h>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bool
  near(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
  {
    return (a - b).norm() < 1e-13 * (1. + b.norm());
  }

  Tensor<1, 2>
  vec(const double x, const double y)
  {
    Tensor<1, 2> v;
    v[0] = x;
    v[1] = y;
    return v;
  }

  Tensor<1, 2>
  applied(const BoundaryCondition::Type type,
          const double                  friction,
          Tensor<1, 2>                  v,
          const Tensor<1, 2>           &obstacle_velocity)
  {
    BoundaryCondition condition;
    condition.type     = type;
    condition.friction = friction;
    condition.apply(v, vec(0, 1), obstacle_velocity);
    return v;
  }

  void
  check_conditions()
  {
    using Type             = BoundaryCondition::Type;
    const Tensor<1, 2> v_o = vec(0.5, -0.25); // the obstacle moves
    bfemp_tests::check(near(applied(Type::sticky, 0, vec(3, -2), v_o), v_o),
                       "sticky: the node moves with the obstacle");
    bfemp_tests::check(near(applied(Type::slip, 0, vec(3, -2), v_o),
                            vec(3, -0.25)),
                       "slip: approaching normal velocity removed");
    bfemp_tests::check(near(applied(Type::slip, 0, vec(3, 2), v_o),
                            vec(3, -0.25)),
                       "slip: separating normal velocity removed too");
    bfemp_tests::check(near(applied(Type::separable_slip, 0, vec(3, 2), v_o),
                            vec(3, 2)),
                       "separable slip: a separating node is free");
    bfemp_tests::check(near(applied(Type::separable_slip, 0, vec(3, -2), v_o),
                            vec(3, -0.25)),
                       "separable slip: an approaching node slides");
    // Relative velocity (2.5, -1.75): friction 0.4 takes 0.4 * 1.75 = 0.7
    // off the tangential 2.5.
    bfemp_tests::check(
      near(applied(Type::separable_slip, 0.4, vec(3, -2), v_o),
           vec(0.5 + 1.8, -0.25)),
      "Coulomb friction reduces the sliding speed by mu |v_n|");
    bfemp_tests::check(near(applied(Type::separable_slip, 2., vec(3, -2), v_o),
                            v_o),
                       "Coulomb friction stops a node that slides too slowly");
  }

  LevelSet<2>
  level_set(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    LevelSet<2>::declare_parameters(prm);
    for (const auto &[entry, value] : entries)
      prm.set(entry, value);
    LevelSet<2> result;
    result.parse_parameters(prm, "level set 0");
    return result;
  }

  void
  check_level_sets()
  {
    const LevelSet<2> plane = level_set({{"type", "half-plane"},
                                         {"point", "0, 0.1"},
                                         {"normal", "0, 2"},
                                         {"velocity", "0, 1"}});
    bfemp_tests::check(std::abs(plane.value(Point<2>(0.3, 0.5), 0.) - 0.4) <
                         1e-14,
                       "half-plane: value is the signed distance");
    bfemp_tests::check(std::abs(plane.value(Point<2>(0.3, 0.5), 0.2) - 0.2) <
                         1e-14,
                       "half-plane: the plane moves with its velocity");
    bfemp_tests::check(near(plane.normal(Point<2>(0.3, 0.5), 0.), vec(0, 1)),
                       "half-plane: unit outward normal");

    const LevelSet<2> box = level_set(
      {{"type", "box"}, {"lower corner", "0, 0"}, {"upper corner", "1, 1"}});
    bfemp_tests::check(std::abs(box.value(Point<2>(1.3, 1.4), 0.) - 0.5) <
                         1e-14,
                       "box: distance from outside a corner");
    bfemp_tests::check(std::abs(box.value(Point<2>(0.9, 0.5), 0.) + 0.1) <
                         1e-14,
                       "box: negative distance to the nearest face inside");
    bfemp_tests::check(near(box.normal(Point<2>(0.9, 0.5), 0.), vec(1, 0)),
                       "box: normal through the nearest face inside");
    bfemp_tests::check(near(box.normal(Point<2>(1.3, 1.4), 0.), vec(0.6, 0.8)),
                       "box: normal away from the corner outside");

    for (const std::string side : {"below", "above"})
      {
        const LevelSet<2> wave = level_set({{"type", "sine wave"},
                                            {"amplitude", "0.025"},
                                            {"wavelength", "0.1"},
                                            {"offset", "0.2"},
                                            {"solid side", side}});
        const double      k    = 2. * numbers::PI / 0.1;
        bool              ok   = true;
        for (double x = 0.; x < 0.2; x += 0.013)
          {
            const double       y = 0.025 * std::cos(k * x) + 0.2;
            const Point<2>     on(x, y);
            const auto         n       = wave.normal(on, 0.);
            const Tensor<1, 2> tangent = vec(1., -0.025 * k * std::sin(k * x));
            const double       sign    = side == "below" ? 1. : -1.;
            ok = ok && std::abs(wave.value(on, 0.)) < 1e-14 &&
                 std::abs(n.norm() - 1.) < 1e-14 &&
                 std::abs(n * tangent) < 1e-13 &&
                 sign * wave.value(Point<2>(x, y + 0.01), 0.) > 0. &&
                 sign * wave.value(Point<2>(x, y - 0.01), 0.) < 0. &&
                 sign * n[1] > 0.;
          }
        bfemp_tests::check(ok,
                           "sine wave (solid " + side +
                             "): zero on the curve, unit normal "
                             "perpendicular to it and out of the solid");
      }
  }

  // Keyframes: at rest before t = 0.1, then (0, -1) m/s until 0.4, then
  // (-1, 0) until 0.9, then (0, 1): the path of BFEMP Section 6.2's
  // boundary. The half-plane y > 0.5 - d shows the vertical displacement d,
  // the velocity the keyframe in force.
  void
  check_keyframes()
  {
    const LevelSet<2> plane =
      level_set({{"type", "half-plane"},
                 {"point", "0, 0.5"},
                 {"normal", "0, 1"},
                 {"keyframes", "0.1: 0, -1, 0; 0.4: -1, 0, 0; 0.9: 0, 1, 0"}});
    const Point<2> x(0., 0.);
    const auto     height = [&](const double t) {
      return -plane.value(x, t); // the plane's height above x
    };
    bfemp_tests::check(std::abs(height(0.05) - 0.5) < 1e-14 &&
                         plane.velocity(0.05).norm() == 0.,
                       "keyframes: at rest before the first keyframe");
    bfemp_tests::check(std::abs(height(0.3) - 0.3) < 1e-14 &&
                         near(plane.velocity(0.3), vec(0, -1)),
                       "keyframes: moves down with the first velocity");
    bfemp_tests::check(std::abs(height(0.7) - 0.2) < 1e-14 &&
                         near(plane.velocity(0.7), vec(-1, 0)),
                       "keyframes: sideways motion keeps the height");
    bfemp_tests::check(std::abs(height(1.2) - 0.5) < 1e-14 &&
                         near(plane.velocity(1.2), vec(0, 1)),
                       "keyframes: the last velocity holds after its time");

    const LevelSet<2> wave =
      level_set({{"type", "sine wave"},
                 {"offset", "0.2"},
                 {"keyframes", "0: 0, -1, 0; 0.1: -1, 0, 0"}});
    // At t = 0.125 the curve moved by (-0.025, -0.1): the point that was on
    // the curve at x0 is now on it at x0 - 0.025.
    const double x0 = 0.013;
    const double y0 = 0.025 * std::cos(2. * numbers::PI * x0 / 0.1) + 0.2;
    bfemp_tests::check(std::abs(wave.value(Point<2>(x0 - 0.025, y0 - 0.1),
                                           0.125)) < 1e-14,
                       "keyframes: a sine wave translates along the path");

    for (const auto &[entries, what] :
         std::vector<std::pair<std::vector<std::pair<std::string, std::string>>,
                               std::string>>{
           {{{"keyframes", "0: 0, -1, 0.5"}}, "a rotating keyframe"},
           {{{"velocity", "1, 0"}, {"keyframes", "0: 0, -1, 0"}},
            "both velocity and keyframes"},
           {{{"keyframes", "0: 0, -1, 0; 0: 1, 0, 0"}},
            "keyframe times that do not increase"}})
      {
        bool refused = false;
        try
          {
            level_set(entries);
          }
        catch (const InputError &)
          {
            refused = true;
          }
        bfemp_tests::check(refused, "keyframes: refuses " + what);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  check_conditions();
  check_level_sets();
  check_keyframes();
}
