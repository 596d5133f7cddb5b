#ifndef bfemp_particles_body_parameters_h
#define bfemp_particles_body_parameters_h

#include <bfemp/material/material_parameters.h>
#include <bfemp/particles/shape_primitive.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * prm subsection "body i": one MPM body, its shape (a sequence of
   * "primitive j" subsections), how it is sampled with particles, its
   * initial velocity and its material.
   */
  template <int dim>
  struct BodyParameters
  {
    std::vector<ShapePrimitive<dim>> primitives;
    unsigned int                     particles_per_direction = 2;
    bool                             jittered                = false;
    unsigned int                     jitter_seed             = 1;
    /** Entry "initial velocity" when it holds numbers only. */
    Tensor<1, dim> initial_velocity;
    /** Its components as written: numbers, or muParser expressions of the
     *  rest position (x, y, z) and pi. */
    std::vector<std::string> initial_velocity_expressions;
    MaterialParameters       material;

    /** Declares the entries of a body with @p n_primitives primitives. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int n_primitives);

    /** Reads only "number of primitives" (first pass of the reader). */
    static unsigned int
    parse_number_of_primitives(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const std::string &where);

    /**
     * The initial velocity of a particle at @p x: the constant, or the
     * expressions evaluated there (not checked for NaN: the caller names
     * the file and the point).
     */
    Tensor<1, dim>
    initial_velocity_at(const Point<dim> &x) const;

  private:
    /** Reads the entry "initial velocity" (numbers or expressions). */
    void
    parse_initial_velocity(const std::string &text, const std::string &where);

    /** The parsed expressions; null when the velocity is constant. */
    std::shared_ptr<FunctionParser<dim>> velocity_function;
  };
} // namespace bfemp

#endif
