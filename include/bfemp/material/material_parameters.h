#ifndef bfemp_material_material_parameters_h
#define bfemp_material_material_parameters_h

#include <bfemp/material/material.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  /** prm subsection "material" of a body. */
  struct MaterialParameters
  {
    std::string model          = "neo-Hookean";
    double      youngs_modulus = 1e6;
    double      poisson_ratio  = 0.3;
    double      density        = 1000.;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const std::string &where);

    ElasticModuli
    moduli() const;
  };
} // namespace bfemp

#endif
