#include <bfemp/base/parameter_tools.h>
#include <bfemp/fem/fem_body_parameters.h>

namespace bfemp
{
  template <int dim>
  void
  FemBodyParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    declare_point<dim>(prm,
                       "initial velocity",
                       components<dim>(0, 0, 0),
                       "[m/s] Initial velocity of every node");
    MaterialParameters::declare_parameters(prm);
    prm.enter_subsection("mesh");
    FemMeshParameters<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("prescribed motion");
    PrescribedMotionParameters<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }



  template <int dim>
  void
  FemBodyParameters<dim>::parse_parameters(ParameterHandler  &prm,
                                           const std::string &where,
                                           const std::string &prm_directory)
  {
    initial_velocity =
      parameter_tools::get_vector<dim>(prm, "initial velocity");
    material.parse_parameters(prm, where);
    prm.enter_subsection("mesh");
    mesh.parse_parameters(prm, where + "/mesh", prm_directory);
    prm.leave_subsection();
    prm.enter_subsection("prescribed motion");
    motion.parse_parameters(prm, where + "/prescribed motion");
    prm.leave_subsection();
  }



  template struct FemBodyParameters<2>;
  template struct FemBodyParameters<3>;
} // namespace bfemp
