#ifndef bfemp_particles_body_parameters_h
#define bfemp_particles_body_parameters_h

#include <bfemp/material/material_parameters.h>
#include <bfemp/particles/shape_primitive.h>

#include <deal.II/base/parameter_handler.h>

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
    Tensor<1, dim>                   initial_velocity;
    MaterialParameters               material;

    /** Declares the entries of a body with @p n_primitives primitives. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int n_primitives);

    /** Reads only "number of primitives" (first pass of the reader). */
    static unsigned int
    parse_number_of_primitives(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const std::string &where);
  };
} // namespace bfemp

#endif
