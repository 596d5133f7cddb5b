#ifndef bfemp_fem_fem_body_parameters_h
#define bfemp_fem_fem_body_parameters_h

#include <bfemp/fem/fem_mesh_parameters.h>
#include <bfemp/fem/prescribed_motion_parameters.h>
#include <bfemp/material/material_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace bfemp
{
  /**
   * prm subsection "fem body i": a linear-simplex FEM body, its mesh
   * (subsection "mesh"), material, initial velocity and prescribed motions:
   * subsection "prescribed motion" and, with "number of prescribed motions"
   * = k > 1, "prescribed motion 1" ... "prescribed motion k-1", each a node
   * selection with its own motion (a later selection wins for a node in
   * several).
   */
  template <int dim>
  struct FemBodyParameters
  {
    FemMeshParameters<dim> mesh;
    MaterialParameters     material;
    Tensor<1, dim>         initial_velocity;
    /** motions[0] is subsection "prescribed motion", motions[k] is
     *  "prescribed motion k". */
    std::vector<PrescribedMotionParameters<dim>> motions;

    /** Declares the entries with @p n_motions prescribed motions. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int n_motions = 1);

    /** Reads only "number of prescribed motions" (first pass). */
    static unsigned int
    parse_number_of_motions(ParameterHandler &prm);

    /** The subsection of motion @p k. */
    static std::string
    motion_subsection(const unsigned int k);

    /** @p prm_directory resolves relative mesh file names. */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &where,
                     const std::string &prm_directory);
  };
} // namespace bfemp

#endif
