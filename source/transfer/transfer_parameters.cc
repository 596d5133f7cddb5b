#include <bfemp/base/input_error.h>
#include <bfemp/transfer/transfer_parameters.h>

namespace bfemp
{
  void
  TransferParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("transfer");
    prm.declare_entry("scheme",
                      "APIC",
                      Patterns::Selection("PIC|FLIP|APIC"),
                      "[-] Particle-grid transfer: PIC, FLIP or APIC (BFEMP "
                      "Tables 2, 3, 1).");
    prm.declare_entry("FLIP PIC blend",
                      "0",
                      Patterns::Double(),
                      "[-] FLIP only: fraction theta of the PIC velocity in "
                      "v_p = theta v_PIC + (1 - theta) v_FLIP, 0 <= theta <= "
                      "1.");
    prm.leave_subsection();
  }



  void
  TransferParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("transfer");
    const std::string name = prm.get("scheme");
    scheme                 = name == "PIC"    ? Scheme::pic
                             : name == "FLIP" ? Scheme::flip
                                              : Scheme::apic;
    pic_blend              = prm.get_double("FLIP PIC blend");
    prm.leave_subsection();
    require_input(pic_blend >= 0. && pic_blend <= 1.,
                  "transfer",
                  "FLIP PIC blend",
                  to_input_string(pic_blend),
                  "must lie in [0, 1]");
  }
} // namespace bfemp
