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
  /** |a - b| / (1 + |b|), checked against 1e-13 by check_near(). */
  double
  deviation(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
  {
    return (a - b).norm() / (1. + b.norm());
  }

  void
  check_near(const Tensor<1, 2> &a,
             const Tensor<1, 2> &b,
             const std::string  &what)
  {
    bfemp_tests::check_below(deviation(a, b),
                             1e-13,
                             what +
                               ": |computed - expected| / (1 + |expected|)");
  }

  /** A value's distance from the expected one, checked against 1e-14. */
  void
  check_value(const double       value,
              const double       expected,
              const std::string &what)
  {
    bfemp_tests::check_below(std::abs(value - expected),
                             1e-14,
                             what + ": error");
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
    check_near(applied(Type::sticky, 0, vec(3, -2), v_o),
               v_o,
               "sticky: the node moves with the obstacle");
    check_near(applied(Type::slip, 0, vec(3, -2), v_o),
               vec(3, -0.25),
               "slip: approaching normal velocity removed");
    check_near(applied(Type::slip, 0, vec(3, 2), v_o),
               vec(3, -0.25),
               "slip: separating normal velocity removed too");
    check_near(applied(Type::separable_slip, 0, vec(3, 2), v_o),
               vec(3, 2),
               "separable slip: a separating node is free");
    check_near(applied(Type::separable_slip, 0, vec(3, -2), v_o),
               vec(3, -0.25),
               "separable slip: an approaching node slides");
    // Relative velocity (2.5, -1.75): friction 0.4 takes 0.4 * 1.75 = 0.7
    // off the tangential 2.5.
    check_near(applied(Type::separable_slip, 0.4, vec(3, -2), v_o),
               vec(0.5 + 1.8, -0.25),
               "Coulomb friction reduces the sliding speed by mu |v_n|");
    check_near(applied(Type::separable_slip, 2., vec(3, -2), v_o),
               v_o,
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
    check_value(plane.value(Point<2>(0.3, 0.5), 0.),
                0.4,
                "half-plane: value is the signed distance");
    check_value(plane.value(Point<2>(0.3, 0.5), 0.2),
                0.2,
                "half-plane: the plane moves with its velocity");
    check_near(plane.normal(Point<2>(0.3, 0.5), 0.),
               vec(0, 1),
               "half-plane: unit outward normal");

    const LevelSet<2> box = level_set(
      {{"type", "box"}, {"lower corner", "0, 0"}, {"upper corner", "1, 1"}});
    check_value(box.value(Point<2>(1.3, 1.4), 0.),
                0.5,
                "box: distance from outside a corner");
    check_value(box.value(Point<2>(0.9, 0.5), 0.),
                -0.1,
                "box: negative distance to the nearest face inside");
    check_near(box.normal(Point<2>(0.9, 0.5), 0.),
               vec(1, 0),
               "box: normal through the nearest face inside");
    check_near(box.normal(Point<2>(1.3, 1.4), 0.),
               vec(0.6, 0.8),
               "box: normal away from the corner outside");

    for (const std::string side : {"below", "above"})
      {
        const LevelSet<2> wave      = level_set({{"type", "sine wave"},
                                                 {"amplitude", "0.025"},
                                                 {"wavelength", "0.1"},
                                                 {"offset", "0.2"},
                                                 {"solid side", side}});
        const double      k         = 2. * numbers::PI / 0.1;
        double            max_value = 0., max_length = 0., max_tangential = 0.;
        unsigned int      n_samples = 0, n_wrong_side = 0;
        for (double x = 0.; x < 0.2; x += 0.013, ++n_samples)
          {
            const double       y = 0.025 * std::cos(k * x) + 0.2;
            const Point<2>     on(x, y);
            const auto         n       = wave.normal(on, 0.);
            const Tensor<1, 2> tangent = vec(1., -0.025 * k * std::sin(k * x));
            const double       sign    = side == "below" ? 1. : -1.;
            max_value      = std::max(max_value, std::abs(wave.value(on, 0.)));
            max_length     = std::max(max_length, std::abs(n.norm() - 1.));
            max_tangential = std::max(max_tangential, std::abs(n * tangent));
            n_wrong_side +=
              !(sign * wave.value(Point<2>(x, y + 0.01), 0.) > 0. &&
                sign * wave.value(Point<2>(x, y - 0.01), 0.) < 0. &&
                sign * n[1] > 0.);
          }
        bfemp_tests::check(
          max_value < 1e-14 && max_length < 1e-14 && max_tangential < 1e-13 &&
            n_wrong_side == 0,
          "sine wave (solid " + side +
            "): zero on the curve, unit normal "
            "perpendicular to it and out of the solid: "
            "largest |phi| " +
            bfemp_tests::measured(max_value, 1e-14) + ", ||n| - 1| " +
            bfemp_tests::measured(max_length, 1e-14) + ", |n . t| " +
            bfemp_tests::measured(max_tangential, 1e-13) +
            ", wrong sign or side at " + std::to_string(n_wrong_side) + " of " +
            std::to_string(n_samples) + " points");
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
    // The height against the expected one (to 1e-14) and the velocity
    // against the keyframe's (to 1e-13 (1 + |v|), exactly zero at rest).
    const auto check_motion = [&](const double        t,
                                  const double        expected_height,
                                  const Tensor<1, 2> &expected_velocity,
                                  const std::string  &what) {
      const double height_error = std::abs(height(t) - expected_height);
      const double velocity_error =
        deviation(plane.velocity(t), expected_velocity);
      const double velocity_bound = expected_velocity.norm() == 0. ? 0. : 1e-13;
      bfemp_tests::check(
        height_error < 1e-14 && velocity_error <= velocity_bound,
        "keyframes: " + what + ": height error " +
          bfemp_tests::measured(height_error, 1e-14) + ", velocity error " +
          bfemp_tests::measured(velocity_error, velocity_bound));
    };
    check_motion(0.05, 0.5, vec(0, 0), "at rest before the first keyframe");
    check_motion(0.3, 0.3, vec(0, -1), "moves down with the first velocity");
    check_motion(0.7, 0.2, vec(-1, 0), "sideways motion keeps the height");
    check_motion(1.2, 0.5, vec(0, 1), "the last velocity holds after its time");

    const LevelSet<2> wave =
      level_set({{"type", "sine wave"},
                 {"offset", "0.2"},
                 {"keyframes", "0: 0, -1, 0; 0.1: -1, 0, 0"}});
    // At t = 0.125 the curve moved by (-0.025, -0.1): the point that was on
    // the curve at x0 is now on it at x0 - 0.025.
    const double x0 = 0.013;
    const double y0 = 0.025 * std::cos(2. * numbers::PI * x0 / 0.1) + 0.2;
    check_value(wave.value(Point<2>(x0 - 0.025, y0 - 0.1), 0.125),
                0.,
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
