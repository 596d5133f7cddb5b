// Prescribed motion of FEM nodes (prm subsection "prescribed motion"),
// parsed from prm text in 2D and 3D: node selection (none, all, box with
// its faces, boundary id); fixed motion; rigid keyframes against
// hand-computed rotations and translations, velocity against a finite
// difference of the position, distances between moved nodes preserved;
// expressions against the analytic position and velocity (also at t = 0,
// where the difference is one-sided, and with constants); concurrent
// evaluation at different times from several threads; and the messages of
// bad input.

#include <bfemp/base/input_error.h>
#include <bfemp/fem/prescribed_motion.h>
#include <bfemp/fem/prescribed_motion_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  const std::string where = "fem body 0/prescribed motion";

  /** The parameters from the entries in @p entries ("set a = b" lines). */
  template <int dim>
  PrescribedMotionParameters<dim>
  parse(const std::string &entries)
  {
    ParameterHandler prm;
    prm.enter_subsection("prescribed motion");
    PrescribedMotionParameters<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection prescribed motion\n" + entries +
                                "\nend\n");
    PrescribedMotionParameters<dim> parameters;
    prm.enter_subsection("prescribed motion");
    parameters.parse_parameters(prm, where);
    prm.leave_subsection();
    return parameters;
  }

  template <int dim>
  PrescribedMotion<dim>
  motion(const std::string &entries)
  {
    return PrescribedMotion<dim>(parse<dim>(entries));
  }

  /** Prints the InputError that parsing @p entries must raise. */
  template <int dim>
  void
  print_error(const std::string &entries)
  {
    try
      {
        motion<dim>(entries);
        bfemp_tests::check(false, "no InputError for: " + entries);
      }
    catch (const InputError &error)
      {
        deallog << dim << "D: " << error.what() << std::endl;
      }
  }

  template <int dim>
  double
  distance(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
  {
    return (a - b).norm();
  }

  /** |v - (x(t + h) - x(t - h)) / 2h| / (|v| + 1) over a few nodes. */
  template <int dim>
  double
  velocity_vs_difference(const PrescribedMotion<dim>   &m,
                         const std::vector<Point<dim>> &nodes,
                         const double                   t)
  {
    const double h     = 1e-6;
    double       error = 0.;
    for (const Point<dim> &X : nodes)
      {
        const Tensor<1, dim> difference =
          (m.position(X, t + h) - m.position(X, t - h)) / (2. * h);
        error = std::max(error,
                         distance(m.velocity(X, t), difference) /
                           (m.velocity(X, t).norm() + 1.));
      }
    return error;
  }

  /** max | |x_a - x_b| - |X_a - X_b| | over all pairs. */
  template <int dim>
  double
  rigidity_defect(const PrescribedMotion<dim>   &m,
                  const std::vector<Point<dim>> &nodes,
                  const double                   t)
  {
    double defect = 0.;
    for (const Point<dim> &a : nodes)
      for (const Point<dim> &b : nodes)
        defect = std::max(defect,
                          std::abs(m.position(a, t).distance(m.position(b, t)) -
                                   a.distance(b)));
    return defect;
  }

  void
  node_selection()
  {
    const std::vector<types::boundary_id> interior;
    {
      const PrescribedMotion<2> m = motion<2>("");
      bfemp_tests::check(!m.active() &&
                           !m.selects(Point<2>(0.5, 0.5),
                                      std::vector<types::boundary_id>{1}),
                         "2D default: a free body, no node selected");
      bfemp_tests::check(m.position(Point<2>(0.5, 0.5), 3.) ==
                             Point<2>(0.5, 0.5) &&
                           m.velocity(Point<2>(0.5, 0.5), 3.).norm() == 0.,
                         "2D default: motion fixed");
      const PrescribedMotion<3> m3 = motion<3>("");
      bfemp_tests::check(!m3.active() && !m3.selects(Point<3>(), interior),
                         "3D default: a free body");
      const PrescribedMotion<3> free_default;
      bfemp_tests::check(!free_default.active(),
                         "default-constructed motion is inactive");
    }
    {
      const PrescribedMotion<2> m = motion<2>("set nodes = all");
      bfemp_tests::check(m.active() && m.selects(Point<2>(7, -3), interior),
                         "2D nodes = all selects every node");
    }
    {
      const PrescribedMotion<2> m = motion<2>("set nodes = box\n"
                                              "set box lower corner = 0, 0\n"
                                              "set box upper corner = 1, 0.5");
      bfemp_tests::check(m.active() && m.selects(Point<2>(0.5, 0.25), interior),
                         "2D box: inside");
      bfemp_tests::check(m.selects(Point<2>(1, 0.5), interior) &&
                           m.selects(Point<2>(0, 0.2), interior),
                         "2D box: corner and face included");
      bfemp_tests::check(m.selects(Point<2>(1. + 1e-14, 0.5 - 1e-15), interior),
                         "2D box: a node 1e-14 outside a face (rounding of a "
                         "mesh file) is included");
      bfemp_tests::check(!m.selects(Point<2>(1.01, 0.2), interior) &&
                           !m.selects(Point<2>(0.5, -1e-6), interior),
                         "2D box: outside");
    }
    {
      const PrescribedMotion<3> m = motion<3>("set nodes = box\n"
                                              "set box lower corner = 0, 0, 0\n"
                                              "set box upper corner = 0, 1, 1");
      bfemp_tests::check(m.selects(Point<3>(0, 0.5, 1), interior) &&
                           !m.selects(Point<3>(1e-3, 0.5, 0.5), interior),
                         "3D flat box: selects the nodes of the plane x = 0");
    }
    {
      const PrescribedMotion<3> m = motion<3>("set nodes = boundary id\n"
                                              "set boundary id = 3");
      const std::vector<types::boundary_id> on_1_and_3 = {1, 3}, on_2 = {2};
      bfemp_tests::check(m.selects(Point<3>(), on_1_and_3) &&
                           !m.selects(Point<3>(), on_2) &&
                           !m.selects(Point<3>(), interior),
                         "3D boundary id 3: only nodes on a facet with id 3");
      bfemp_tests::check(
        m.selects(Point<3>(), std::set<types::boundary_id>{3}) &&
          !m.selects(Point<3>(), std::set<types::boundary_id>{0, 4}),
        "3D boundary id 3: ids given as a set");
    }
  }

  void
  fixed_motion()
  {
    const PrescribedMotion<3> m = motion<3>("set nodes = all\n"
                                            "set motion = fixed\n"
                                            "set displacement = 1, 2, 3");
    const Point<3>            X(0.1, 0.2, 0.3);
    bfemp_tests::check(m.position(X, 0.) == X && m.position(X, 10.) == X &&
                         m.velocity(X, 5.).norm() == 0.,
                       "3D fixed: x = X, v = 0 (displacement ignored)");
  }

  void
  rigid_2d()
  {
    // center (1, 1) moves with (1, 0) and the body turns with 0.5 rad/s
    // from t = 0; at rest from t = 2
    const PrescribedMotion<2> m =
      motion<2>("set nodes = all\n"
                "set motion = rigid\n"
                "set rotation center = 1, 1\n"
                "set keyframes = 0: 1, 0, 0.5; 2: 0, 0, 0");
    const Point<2> X(2, 1); // (1, 0) from the center
    bfemp_tests::check(m.position(X, -1.) == X &&
                         m.velocity(X, -1.).norm() == 0.,
                       "2D rigid: at rest before the first keyframe");

    const Point<2> at_1(2. + std::cos(0.5), 1. + std::sin(0.5));
    bfemp_tests::check(m.position(X, 1.).distance(at_1) < 1e-14,
                       "2D rigid: t = 1, center (2, 1), angle 0.5");
    const Tensor<1, 2> v_1({1. - 0.5 * std::sin(0.5), 0.5 * std::cos(0.5)});
    bfemp_tests::check(distance(m.velocity(X, 1.), v_1) < 1e-14,
                       "2D rigid: t = 1, velocity v + omega e_z x (x - c)");

    const Point<2> at_3(3. + std::cos(1.), 1. + std::sin(1.));
    bfemp_tests::check(m.position(X, 3.).distance(at_3) < 1e-14 &&
                         m.velocity(X, 3.).norm() == 0.,
                       "2D rigid: t = 3, at rest at center (3, 1), angle 1");
    bfemp_tests::check(m.position(X, 2. - 1e-13).distance(m.position(X, 2.)) <
                         1e-12,
                       "2D rigid: position continuous at a keyframe");

    const std::vector<Point<2>> nodes    = {Point<2>(2, 1),
                                            Point<2>(0, 0),
                                            Point<2>(1.3, -0.4),
                                            Point<2>(-2, 3)};
    double                      fd_error = 0., defect = 0.;
    for (const double t : {0.3, 1.1, 1.9, 2.5, 7.})
      {
        fd_error = std::max(fd_error, velocity_vs_difference(m, nodes, t));
        defect   = std::max(defect, rigidity_defect(m, nodes, t));
      }
    bfemp_tests::check(fd_error < 1e-7,
                       "2D rigid: velocity matches the difference of x");
    bfemp_tests::check(defect < 1e-13,
                       "2D rigid: distances between nodes preserved");

    const PrescribedMotion<2> late = motion<2>("set nodes = all\n"
                                               "set motion = rigid\n"
                                               "set keyframes = 0.5: 0, 1, 0;");
    bfemp_tests::check(late.position(X, 0.25) == X &&
                         late.position(X, 1.).distance(X + Point<2>(0, 0.5)) <
                           1e-15,
                       "2D rigid: first keyframe at t = 0.5, trailing ';'");
  }

  void
  rigid_3d()
  {
    // about z (axis given unnormalized), lift with 1 m/s for 1 s while
    // turning at 0.5 rad/s, then move along x without turning
    const PrescribedMotion<3> m =
      motion<3>("set nodes = all\n"
                "set motion = rigid\n"
                "set rotation axis = 0, 0, 2\n"
                "set keyframes = 0: 0, 0, 1, 0.5; 1: 1, 0, 0, 0");
    const Point<3> X(1, 0, 0);
    bfemp_tests::check(m.position(X, 1.).distance(
                         Point<3>(std::cos(0.5), std::sin(0.5), 1.)) < 1e-14,
                       "3D rigid: t = 1, center (0, 0, 1), angle 0.5 about z");
    bfemp_tests::check(m.position(X, 2.).distance(
                         Point<3>(1. + std::cos(0.5), std::sin(0.5), 1.)) <
                         1e-14,
                       "3D rigid: t = 2, center (1, 0, 1), angle 0.5 about z");

    // a third of a turn about (1, 1, 1) maps e_x to e_y
    const PrescribedMotion<3> third =
      motion<3>("set nodes = all\n"
                "set motion = rigid\n"
                "set rotation center = 1, 1, 1\n"
                "set rotation axis = 1, 1, 1\n"
                "set keyframes = 0: 0, 0, 0, 2.0943951023931954923");
    bfemp_tests::check(
      third.position(Point<3>(2, 1, 1), 1.).distance(Point<3>(1, 2, 1)) < 1e-14,
      "3D rigid: a third of a turn about (1, 1, 1) maps "
      "e_x to e_y");

    const PrescribedMotion<3> tumbling =
      motion<3>("set nodes = all\n"
                "set motion = rigid\n"
                "set rotation center = 0.2, 0.1, -0.3\n"
                "set rotation axis = 0.3, -1, 0.5\n"
                "set keyframes = 0: 0.1, 0.2, -0.3, 2; 0.7: -1, 0, 0.5, -3; "
                "1.5: 0, 0, 0, 0.1");
    const std::vector<Point<3>> nodes    = {Point<3>(1, 0, 0),
                                            Point<3>(0, 1, 0.5),
                                            Point<3>(-0.3, 0.2, 2),
                                            Point<3>(0.2, 0.1, -0.3)};
    double                      fd_error = 0., defect = 0.;
    for (const double t : {0.3, 0.9, 1.2, 2.5, 10.})
      {
        fd_error =
          std::max(fd_error, velocity_vs_difference(tumbling, nodes, t));
        defect = std::max(defect, rigidity_defect(tumbling, nodes, t));
      }
    bfemp_tests::check(fd_error < 1e-7,
                       "3D rigid: velocity matches the difference of x");
    bfemp_tests::check(defect < 1e-13,
                       "3D rigid: distances between nodes preserved");
    const Point<3> center(0.2, 0.1, -0.3);
    bfemp_tests::check(
      tumbling.position(center, 1.)
          .distance(center + Point<3>(0.1 * 0.7 - 1. * 0.3,
                                      0.2 * 0.7,
                                      -0.3 * 0.7 + 0.15)) < 1e-14,
      "3D rigid: the center moves with the integrated velocities");
  }

  void
  expression_2d()
  {
    const PrescribedMotion<2> m =
      motion<2>("set nodes = all\n"
                "set motion = expression\n"
                "set displacement = 0.1*sin(2*pi*t)*x, 0.05*t*t*y");
    const Point<2> X(0.5, 2);
    double         position_error = 0., velocity_error = 0.;
    for (const double t : {0., 1e-7, 0.3, 1.25, 100.})
      {
        const Point<2>     x(X[0] + 0.1 * std::sin(2. * M_PI * t) * X[0],
                         X[1] + 0.05 * t * t * X[1]);
        const Tensor<1, 2> v(
          {0.1 * 2. * M_PI * std::cos(2. * M_PI * t) * X[0], 0.1 * t * X[1]});
        position_error = std::max(position_error, m.position(X, t).distance(x));
        velocity_error =
          std::max(velocity_error,
                   distance(m.velocity(X, t), v) / (1. + v.norm()));
      }
    bfemp_tests::check(position_error < 1e-12,
                       "2D expression: x = X + u(X, t)");
    bfemp_tests::check(velocity_error < 1e-6,
                       "2D expression: velocity = du/dt (t = 0 one-sided, "
                       "t = 0.3, 1.25, 100)");

    const PrescribedMotion<2> with_constants =
      motion<2>("set nodes = all\n"
                "set motion = expression\n"
                "set constants = a=0.1, w=3\n"
                "set displacement = a*sin(w*t)*x, min(x, y)*t");
    const Point<2> x(0.5 + 0.1 * std::sin(3. * 0.4) * 0.5, 2. + 0.5 * 0.4);
    bfemp_tests::check(with_constants.position(X, 0.4).distance(x) < 1e-14,
                       "2D expression: constants, and a comma inside min(x, "
                       "y) does not split the components");

    const PrescribedMotion<2> root = motion<2>("set nodes = all\n"
                                               "set motion = expression\n"
                                               "set displacement = sqrt(t), 0");
    bfemp_tests::check(std::isfinite(root.velocity(X, 0.)[0]),
                       "2D expression: the velocity at t = 0 never evaluates "
                       "u at t < 0");
  }

  void
  expression_3d()
  {
    const PrescribedMotion<3> m =
      motion<3>("set nodes = box\n"
                "set box lower corner = 0, 0, 0\n"
                "set box upper corner = 1, 1, 1\n"
                "set motion = expression\n"
                "set displacement = 0.1*sin(2*pi*t)*x, 0, z*t^2");
    const Point<3>     X(0.5, 0.2, 0.8);
    const double       t = 0.7;
    const Point<3>     x(X[0] + 0.1 * std::sin(2. * M_PI * t) * X[0],
                     X[1],
                     X[2] + X[2] * t * t);
    const Tensor<1, 3> v(
      {0.2 * M_PI * std::cos(2. * M_PI * t) * X[0], 0., 2. * X[2] * t});
    bfemp_tests::check(m.position(X, t).distance(x) < 1e-14,
                       "3D expression: x = X + u(X, t)");
    bfemp_tests::check(distance(m.velocity(X, t), v) < 1e-8,
                       "3D expression: velocity = du/dt");
  }

  /** Positions evaluated by 4 threads at different times equal the serial
   *  ones (FunctionParser's time is not shared state here). */
  template <int dim>
  void
  concurrent_evaluation(const std::string &entries)
  {
    const PrescribedMotion<dim> m = motion<dim>(entries);
    const unsigned int          n = 2000;
    Point<dim>                  X;
    for (unsigned int d = 0; d < dim; ++d)
      X[d] = 0.3 + 0.1 * d;
    std::vector<Point<dim>> serial(n), concurrent(n);
    for (unsigned int i = 0; i < n; ++i)
      serial[i] = m.position(X, 0.001 * i);
    std::vector<std::thread> threads;
    for (unsigned int thread = 0; thread < 4; ++thread)
      threads.emplace_back([&, thread]() {
        for (unsigned int i = thread; i < n; i += 4)
          concurrent[i] = m.position(X, 0.001 * i);
      });
    for (std::thread &thread : threads)
      thread.join();
    bfemp_tests::check(serial == concurrent,
                       std::to_string(dim) +
                         "D expression: 4 threads at different times agree "
                         "with the serial evaluation");
  }

  void
  bad_input()
  {
    const std::string rigid = "set nodes = all\nset motion = rigid\n";
    print_error<2>(rigid + "set keyframes = 0: 1, 0");
    print_error<3>(rigid + "set keyframes = 0: 1, 0, 0, 0, 1");
    print_error<2>(rigid + "set keyframes = 0 1, 0, 0");
    print_error<2>(rigid + "set keyframes = 0: 1, a, 0");
    print_error<2>(rigid + "set keyframes = zero: 1, 0, 0");
    print_error<2>(rigid + "set keyframes = 0: 1, 0, 0; 0: 0, 0, 0");
    print_error<2>(rigid + "set keyframes = 2: 1, 0, 0; 1: 0, 0, 0");
    print_error<2>(rigid + "set keyframes = ");
    print_error<3>(rigid + "set rotation axis = 0, 0, 0");

    const std::string expression = "set nodes = all\nset motion = expression\n";
    print_error<2>(expression + "set displacement = 0.1*x");
    print_error<3>(expression + "set displacement = 0.1*x, 0, 0, t");
    print_error<2>(expression + "set displacement = 0.1*x, ");
    print_error<2>(expression + "set displacement = 0.1*x, y*");
    print_error<2>(expression + "set displacement = w*x, 0");
    print_error<3>(expression + "set displacement = z*t, sin(x, 0");
    print_error<2>(expression + "set displacement = (x+1, 0");
    print_error<2>(expression + "set constants = a 0.1");
    print_error<2>(expression + "set constants = 2a=1");
    print_error<2>(expression + "set constants = t=1");
    print_error<2>(expression + "set constants = a=b");

    print_error<2>("set nodes = box\n"
                   "set box lower corner = 0, 0\n"
                   "set box upper corner = 1, -1");
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  node_selection();
  fixed_motion();
  rigid_2d();
  rigid_3d();
  expression_2d();
  expression_3d();
  concurrent_evaluation<2>("set nodes = all\nset motion = expression\n"
                           "set displacement = 0.1*sin(2*pi*t)*x, t*y");
  concurrent_evaluation<3>("set nodes = all\nset motion = expression\n"
                           "set displacement = 0.1*sin(2*pi*t)*x, t*y, z*t*t");
  bad_input();
}
