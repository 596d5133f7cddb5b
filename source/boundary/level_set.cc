#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/boundary/level_set.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace bfemp
{
  template <int dim>
  void
  LevelSet<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    prm.declare_entry("type",
                      "half-plane",
                      Patterns::Selection("half-plane|box|sine wave"),
                      "[-] Obstacle shape.");
    prm.declare_entry("condition",
                      "slip",
                      Patterns::Selection("sticky|slip|separable slip"),
                      "[-] Condition on grid nodes inside the obstacle.");
    prm.declare_entry("friction",
                      "0",
                      Patterns::Double(0.),
                      "[-] Coulomb coefficient (separable slip only).");
    declare_point<dim>(prm,
                       "point",
                       components<dim>(0, 0.1, 0),
                       "[m] Half-plane: a point on the plane");
    declare_point<dim>(prm,
                       "normal",
                       components<dim>(0, 1, 0),
                       "[-] Half-plane: normal pointing out of the obstacle");
    declare_point<dim>(prm,
                       "lower corner",
                       components<dim>(0, 0, 0),
                       "[m] Box: lower corner");
    declare_point<dim>(prm,
                       "upper corner",
                       components<dim>(0.1, 0.1, 0.1),
                       "[m] Box: upper corner");
    prm.declare_entry("amplitude",
                      "0.025",
                      Patterns::Double(),
                      "[m] Sine wave: A in y = A cos(2 pi x / L) + c.");
    prm.declare_entry("wavelength",
                      "0.1",
                      Patterns::Double(),
                      "[m] Sine wave: L (> 0).");
    prm.declare_entry("offset", "0.1", Patterns::Double(), "[m] Sine wave: c.");
    prm.declare_entry("solid side",
                      "below",
                      Patterns::Selection("below|above"),
                      "[-] Sine wave: the obstacle is below or above the "
                      "curve.");
    declare_point<dim>(prm,
                       "velocity",
                       components<dim>(0, 0, 0),
                       "[m/s] Constant velocity of the obstacle");
    prm.declare_entry(
      "keyframes",
      "",
      Patterns::Anything(),
      "[s: m/s, rad/s] Instead of 'velocity': 't: vx, vy[, vz], 0; ...', "
      "from time t on (times increasing) the obstacle moves with velocity v; "
      "at rest before the first time. The form of an FEM body's rigid "
      "'keyframes'; the angular velocity must be 0 (level sets only "
      "translate). Empty: use 'velocity'.");
  }



  template <int dim>
  void
  LevelSet<dim>::parse_parameters(ParameterHandler  &prm,
                                  const std::string &where)
  {
    using namespace parameter_tools;
    const std::string name = prm.get("type");
    type                   = name == "half-plane" ? Type::half_plane
                             : name == "box"      ? Type::box
                                                  : Type::sine_wave;
    boundary_condition.type =
      BoundaryCondition::parse_type(prm.get("condition"));
    boundary_condition.friction = prm.get_double("friction");
    point                       = get_point<dim>(prm, "point");
    plane_normal                = get_vector<dim>(prm, "normal");
    lower_corner                = get_point<dim>(prm, "lower corner");
    upper_corner                = get_point<dim>(prm, "upper corner");
    amplitude                   = prm.get_double("amplitude");
    wavelength                  = prm.get_double("wavelength");
    offset                      = prm.get_double("offset");
    solid_below                 = prm.get("solid side") == "below";
    obstacle_velocity           = get_vector<dim>(prm, "velocity");
    keyframes.clear();
    if (!Utilities::trim(prm.get("keyframes")).empty())
      {
        require_input(obstacle_velocity.norm() == 0.,
                      where,
                      "velocity",
                      to_input_string(Point<dim>(obstacle_velocity)),
                      "must be zero when 'keyframes' is given (give one of "
                      "them)");
        keyframes =
          PrescribedMotionParameters<dim>::parse_keyframes(prm.get("keyframes"),
                                                           where);
        for (const auto &frame : keyframes)
          require_input(frame.angular_velocity == 0.,
                        where,
                        "keyframes",
                        prm.get("keyframes"),
                        "the angular velocity of every keyframe must be 0: "
                        "level sets only translate");
      }

    if (type == Type::half_plane)
      {
        require_input(plane_normal.norm() > 0.,
                      where,
                      "normal",
                      to_input_string(Point<dim>(plane_normal)),
                      "must be a nonzero vector");
        plane_normal /= plane_normal.norm();
      }
    if (type == Type::sine_wave)
      require_input(wavelength > 0.,
                    where,
                    "wavelength",
                    to_input_string(wavelength),
                    "must be > 0 [m]");
    if (type == Type::box)
      for (unsigned int d = 0; d < dim; ++d)
        require_input(upper_corner[d] > lower_corner[d],
                      where,
                      "upper corner",
                      to_input_string(upper_corner),
                      "must exceed 'lower corner' in every direction");
  }



  template <int dim>
  Tensor<1, dim>
  LevelSet<dim>::displacement(const double time) const
  {
    if (keyframes.empty())
      return time * obstacle_velocity;
    Tensor<1, dim> u;
    for (unsigned int k = 0; k < keyframes.size(); ++k)
      {
        const double begin = keyframes[k].time;
        const double end =
          k + 1 < keyframes.size() ? keyframes[k + 1].time : time;
        if (time <= begin)
          break;
        u += (std::min(time, end) - begin) * keyframes[k].velocity;
      }
    return u;
  }



  template <int dim>
  Point<dim>
  LevelSet<dim>::to_initial_frame(const Point<dim> &x, const double time) const
  {
    return x - displacement(time);
  }



  template <int dim>
  double
  LevelSet<dim>::value(const Point<dim> &x_now, const double time) const
  {
    const Point<dim> x = to_initial_frame(x_now, time);
    switch (type)
      {
        case Type::half_plane:
          return (x - point) * plane_normal;
        case Type::box:
          {
            // Signed distance to the box: positive outside.
            Tensor<1, dim> outside;
            double         inside = -std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double below = lower_corner[d] - x[d];
                const double above = x[d] - upper_corner[d];
                outside[d]         = std::max({below, above, 0.});
                inside             = std::max({inside, below, above});
              }
            return outside.norm() > 0. ? outside.norm() : inside;
          }
        case Type::sine_wave:
          {
            const double curve =
              amplitude * std::cos(2. * numbers::PI * x[0] / wavelength) +
              offset;
            return solid_below ? x[1] - curve : curve - x[1];
          }
      }
    return 1.;
  }



  template <int dim>
  Tensor<1, dim>
  LevelSet<dim>::normal(const Point<dim> &x_now, const double time) const
  {
    if (type == Type::half_plane)
      return plane_normal;

    const Point<dim> x = to_initial_frame(x_now, time);
    Tensor<1, dim>   n;
    if (type == Type::sine_wave)
      {
        const double k = 2. * numbers::PI / wavelength;
        n[0]           = amplitude * k * std::sin(k * x[0]);
        n[1]           = 1.;
        if (!solid_below)
          n *= -1.;
      }
    else
      {
        // Box: away from the nearest point of the box, or out through the
        // nearest face from inside.
        const Point<dim> center = 0.5 * (lower_corner + upper_corner);
        double           best   = -std::numeric_limits<double>::max();
        unsigned int     face   = 0;
        bool             out    = false;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double below = lower_corner[d] - x[d];
            const double above = x[d] - upper_corner[d];
            n[d] = below > 0. ? -below : (above > 0. ? above : 0.);
            out  = out || below > 0. || above > 0.;
            if (std::max(below, above) > best)
              {
                best = std::max(below, above);
                face = d;
              }
          }
        if (!out)
          {
            n       = 0;
            n[face] = x[face] > center[face] ? 1. : -1.;
          }
      }
    return n / n.norm();
  }



  template <int dim>
  const BoundaryCondition &
  LevelSet<dim>::condition() const
  {
    return boundary_condition;
  }



  template <int dim>
  Tensor<1, dim>
  LevelSet<dim>::velocity(const double time) const
  {
    if (keyframes.empty())
      return obstacle_velocity;
    Tensor<1, dim> v; // at rest before the first keyframe
    for (const auto &frame : keyframes)
      if (time >= frame.time)
        v = frame.velocity;
    return v;
  }



  template class LevelSet<2>;
  template class LevelSet<3>;
} // namespace bfemp
