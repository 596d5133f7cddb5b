#include <bfemp/base/parameter_tools.h>
#include <bfemp/fem/fem_body_parameters.h>

namespace bfemp
{
  template <int dim>
  void
  FemBodyParameters<dim>::declare_parameters(ParameterHandler  &prm,
                                             const unsigned int n_motions)
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
    prm.declare_entry("number of prescribed motions",
                      "1",
                      Patterns::Integer(1),
                      "[-] Node selections with their own motion: subsection "
                      "'prescribed motion', then 'prescribed motion 1', ... "
                      "(e.g. one end clamped, the other pulled). A node in "
                      "several selections follows the last.");
    for (unsigned int k = 0; k < n_motions; ++k)
      {
        prm.enter_subsection(motion_subsection(k));
        PrescribedMotionParameters<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  unsigned int
  FemBodyParameters<dim>::parse_number_of_motions(ParameterHandler &prm)
  {
    return prm.get_integer("number of prescribed motions");
  }



  template <int dim>
  std::string
  FemBodyParameters<dim>::motion_subsection(const unsigned int k)
  {
    return k == 0 ? std::string("prescribed motion")
                  : parameter_tools::numbered("prescribed motion", k);
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
    motions.resize(prm.get_integer("number of prescribed motions"));
    for (unsigned int k = 0; k < motions.size(); ++k)
      {
        prm.enter_subsection(motion_subsection(k));
        motions[k].parse_parameters(prm, where + "/" + motion_subsection(k));
        prm.leave_subsection();
      }
  }



  template struct FemBodyParameters<2>;
  template struct FemBodyParameters<3>;
} // namespace bfemp
