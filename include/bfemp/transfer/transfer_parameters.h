#ifndef bfemp_transfer_transfer_parameters_h
#define bfemp_transfer_transfer_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "transfer": the particle-grid transfer scheme. */
  struct TransferParameters
  {
    enum class Scheme
    {
      pic,
      flip,
      apic
    };

    Scheme scheme = Scheme::apic;
    /** FLIP only: v = theta v_PIC + (1 - theta) v_FLIP. */
    double pic_blend = 0.;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace bfemp

#endif
