#ifndef bfemp_fem_fem_body_parameters_h
#define bfemp_fem_fem_body_parameters_h

#include <bfemp/fem/fem_mesh_parameters.h>
#include <bfemp/fem/prescribed_motion_parameters.h>
#include <bfemp/material/material_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  /**
   * prm subsection "fem body i": a linear-simplex FEM body, its mesh
   * (subsection "mesh"), material, initial velocity and prescribed motion
   * (subsection "prescribed motion").
   */
  template <int dim>
  struct FemBodyParameters
  {
    FemMeshParameters<dim>          mesh;
    MaterialParameters              material;
    Tensor<1, dim>                  initial_velocity;
    PrescribedMotionParameters<dim> motion;

    static void
    declare_parameters(ParameterHandler &prm);

    /** @p prm_directory resolves relative mesh file names. */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &where,
                     const std::string &prm_directory);
  };
} // namespace bfemp

#endif
