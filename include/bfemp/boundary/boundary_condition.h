#ifndef bfemp_boundary_boundary_condition_h
#define bfemp_boundary_boundary_condition_h

#include <deal.II/base/tensor.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * What a grid boundary does to the velocity of a node inside it, relative
   * to the obstacle's velocity: sticky sets it equal; slip removes the normal
   * component; separable slip removes it only when the node approaches the
   * obstacle, and then applies Coulomb friction to the tangential part.
   */
  struct BoundaryCondition
  {
    enum class Type
    {
      sticky,
      slip,
      separable_slip
    };

    Type   type     = Type::slip;
    double friction = 0.;

    /** Parses "sticky", "slip" or "separable slip". */
    static Type
    parse_type(const std::string &name);

    /**
     * Projects the node velocity @p v. @p normal is the unit normal pointing
     * out of the obstacle, @p obstacle_velocity its rigid velocity.
     */
    template <int dim>
    void
    apply(Tensor<1, dim>       &v,
          const Tensor<1, dim> &normal,
          const Tensor<1, dim> &obstacle_velocity) const
    {
      Tensor<1, dim> relative = v - obstacle_velocity;
      if (type == Type::sticky)
        relative = 0;
      else
        {
          const double normal_speed = relative * normal;
          if (type == Type::slip || normal_speed < 0.)
            {
              relative -= normal_speed * normal;
              if (type == Type::separable_slip && friction > 0.)
                {
                  // Coulomb: the tangential speed drops by mu |v_n|, and
                  // stops if that is more than it has.
                  const double tangential_speed = relative.norm();
                  const double reduction        = -friction * normal_speed;
                  if (tangential_speed <= reduction)
                    relative = 0;
                  else
                    relative *= 1. - reduction / tangential_speed;
                }
            }
        }
      v = obstacle_velocity + relative;
    }
  };
} // namespace bfemp

#endif
