#ifndef bfemp_boundary_level_set_h
#define bfemp_boundary_level_set_h

#include <bfemp/boundary/boundary_condition.h>
#include <bfemp/fem/prescribed_motion_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

namespace bfemp
{
  /**
   * An analytic rigid obstacle acting on the grid, prm subsection "level set
   * i" of "boundaries": a half-plane, a solid box, or the region below (or
   * above) the sine wave y = A cos(2 pi x / L) + c. phi(x) <= 0 inside the
   * obstacle; grid nodes there get the boundary condition. The obstacle
   * translates with a constant velocity or with the piecewise-constant
   * velocities of keyframes (the form of an FEM body's rigid motion, without
   * rotation), so the level-set boundary of BFEMP Section 6.2 can follow
   * the same path as the FEM boundary it is compared with.
   */
  template <int dim>
  class LevelSet
  {
  public:
    enum class Type
    {
      half_plane,
      box,
      sine_wave
    };

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const std::string &where);

    /** phi(x, t): negative inside the obstacle. */
    double
    value(const Point<dim> &x, const double time) const;

    /** Unit normal pointing out of the obstacle at x. */
    Tensor<1, dim>
    normal(const Point<dim> &x, const double time) const;

    const BoundaryCondition &
    condition() const;

    /** The obstacle's velocity at @p time. */
    Tensor<1, dim>
    velocity(const double time) const;

  private:
    /** How far the obstacle has moved since t = 0. */
    Tensor<1, dim>
    displacement(const double time) const;

    /** x moved back to the obstacle's position at t = 0. */
    Point<dim>
    to_initial_frame(const Point<dim> &x, const double time) const;

    Type              type = Type::half_plane;
    BoundaryCondition boundary_condition;
    Point<dim>        point;
    Tensor<1, dim>    plane_normal;
    Point<dim>        lower_corner, upper_corner;
    double            amplitude = 0., wavelength = 1., offset = 0.;
    bool              solid_below = true;
    Tensor<1, dim>    obstacle_velocity;
    /** Entry "keyframes" (translation only); empty: constant velocity. */
    std::vector<typename PrescribedMotionParameters<dim>::Keyframe> keyframes;
  };
} // namespace bfemp

#endif
