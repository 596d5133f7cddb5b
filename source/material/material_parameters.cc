#include <bfemp/base/input_error.h>
#include <bfemp/material/material_parameters.h>

namespace bfemp
{
  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("material");
    prm.declare_entry("model",
                      "neo-Hookean",
                      Patterns::Selection(
                        "neo-Hookean|linear elastic|fixed corotated"),
                      "[-] Elastic energy density: neo-Hookean (BFEMP eq. "
                      "7), linear elastic (small strain), fixed corotated.");
    prm.declare_entry("Young's modulus",
                      "1e6",
                      Patterns::Double(),
                      "[Pa] Young's modulus E (> 0).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(),
                      "[-] Poisson's ratio nu, -1 < nu < 0.5 (2D uses plane "
                      "strain).");
    prm.declare_entry("density",
                      "1000",
                      Patterns::Double(),
                      "[kg/m^dim] Rest mass density (> 0); per unit area in "
                      "2D, as in the BFEMP paper.");
    prm.leave_subsection();
  }



  void
  MaterialParameters::parse_parameters(ParameterHandler  &prm,
                                       const std::string &where)
  {
    prm.enter_subsection("material");
    model          = prm.get("model");
    youngs_modulus = prm.get_double("Young's modulus");
    poisson_ratio  = prm.get_double("Poisson's ratio");
    density        = prm.get_double("density");
    prm.leave_subsection();

    const std::string subsection = where + "/material";
    require_input(youngs_modulus > 0.,
                  subsection,
                  "Young's modulus",
                  to_input_string(youngs_modulus),
                  "must be > 0 [Pa]");
    require_input(poisson_ratio > -1. && poisson_ratio < 0.5,
                  subsection,
                  "Poisson's ratio",
                  to_input_string(poisson_ratio),
                  "must satisfy -1 < nu < 0.5");
    require_input(density > 0.,
                  subsection,
                  "density",
                  to_input_string(density),
                  "must be > 0");
  }



  ElasticModuli
  MaterialParameters::moduli() const
  {
    return ElasticModuli::from_young_poisson(youngs_modulus, poisson_ratio);
  }
} // namespace bfemp
