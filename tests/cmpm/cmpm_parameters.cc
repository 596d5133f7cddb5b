// prm subsection "cmpm": defaults as the seed's (boundary B-spline, L = H/2,
// n = 7), each setting parsed, and each impossible value refused with a
// message naming the subsection and entry.

#include <bfemp/base/input_error.h>
#include <bfemp/cmpm/cmpm_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  CmpmParameters
  parse(const std::string &input)
  {
    ParameterHandler prm;
    CmpmParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection cmpm\n" + input + "\nend\n");
    CmpmParameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }

  void
  refused(const std::string &input, const std::string &entry)
  {
    try
      {
        parse(input);
        bfemp_tests::check(false, "refused: " + input);
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        deallog << message << std::endl;
        bfemp_tests::check(message.find(entry) != std::string::npos &&
                             message.find("cmpm") != std::string::npos,
                           "refused, naming cmpm/" + entry);
      }
  }

  /** Refused by the entry's pattern, when deal.II reads the text (the scene
   *  reader adds the file and line, tests/input). */
  void
  refused_by_pattern(const std::string &input, const std::string &entry)
  {
    try
      {
        parse(input);
        bfemp_tests::check(false, "refused: " + input);
      }
    catch (const InputError &)
      {
        bfemp_tests::check(false, "refused by the pattern: " + input);
      }
    catch (const std::exception &error)
      {
        bfemp_tests::check(std::string(error.what()).find(entry) !=
                             std::string::npos,
                           "refused by the entry's pattern, naming " + entry +
                             ": " + input);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  const CmpmParameters defaults = parse("");
  bfemp_tests::check(!defaults.enabled &&
                       defaults.element_type ==
                         CmpmParameters::ElementType::boundary_bspline &&
                       defaults.nodes_per_span == 2 && defaults.n_fine == 7 &&
                       defaults.empty_span_stiffness == 1e-6 &&
                       defaults.weak_node_regularization == 1e-2,
                     "defaults: off, boundary B-spline, L = H/2, n = 7, "
                     "empty span stiffness 1e-6, weak node regularization "
                     "1e-2");

  const CmpmParameters set = parse("set enabled = true\n"
                                   "set coarse element type = B-spline\n"
                                   "set coarse node span = H\n"
                                   "set fine nodes per direction = 5\n"
                                   "set empty span stiffness = 1e-4\n"
                                   "set weak node regularization = 0");
  bfemp_tests::check(
    set.enabled && set.element_type == CmpmParameters::ElementType::bspline &&
      set.nodes_per_span == 1 && set.n_fine == 5 &&
      set.empty_span_stiffness == 1e-4 && set.weak_node_regularization == 0.,
    "every entry parsed");

  refused_by_pattern("set fine nodes per direction = 4",
                     "fine nodes per direction");
  refused_by_pattern("set fine nodes per direction = 40",
                     "fine nodes per direction");
  refused("set empty span stiffness = -1e-6", "empty span stiffness");
  refused("set empty span stiffness = 0.5", "empty span stiffness");
  refused("set weak node regularization = -0.1", "weak node regularization");
  refused("set weak node regularization = 2", "weak node regularization");
  refused("set coarse element type = multilinear\n"
          "set coarse node span = H/2",
          "coarse node span");
  bfemp_tests::check(parse("set coarse node span = H/3").nodes_per_span == 3,
                     "coarse node span = H/3: three spacings per element "
                     "edge (seed 002 Section 8.2.1)");
  refused_by_pattern("set coarse node span = H/4", "coarse node span");
}
