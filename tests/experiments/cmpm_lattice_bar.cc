// Seed 002 Section 8.1.3 reduced: the 2D analogue of the lattice bar
// (prm/cmpm/lattice_bar_2d{,_bspline,_fine}.prm: an 8 x 2 m lattice of
// 0.15 m struts around 64 square holes, E 1e5, nu 0.4, rho 10, the left face
// fixed, gravity 5, backward Euler with dt 0.025 s), run here to t = 1.0 s
// (the seed's first snapshot) on cMPM with boundary B-spline and with
// B-spline coarse elements and on BSMPM-fine, the reference (the same
// particles). The seed finds the two element types close (max r_u 2.5e-2
// and 2.1e-2), B-spline elements slightly more accurate, and boundary
// B-spline elements 3.2 times cheaper in the integrals (r = 98 against 125
// coarse nodes per element in 3D; 16 against 25 in 2D). Checked: max r_u of
// the B-spline elements at most that of the boundary B-spline elements and
// within a factor 3 of it, both below 0.1. Also bfemp's richer boundary
// B-spline elements (lattice_bar_2d_h3.prm: L = H/3, with factorization
// reuse and modified Newton): checked below 0.8 of the L = H/2 elements'
// max r_u (0.042 against 0.064 when this test was written; in 3D, on a
// 0.5 m slab of the bar, 0.022 against 0.059, doc/cmpm.md). Costs (assembly
// per Newton iteration of each) go to the console. About 60 s.

#include "../format.h"
#include "cmpm_runs.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  using bfemp_tests::format;
  const std::string prefix =
    std::string(BFEMP_SOURCE_DIR) + "/prm/cmpm/lattice_bar_2d";
  const std::string to_one_second = "subsection run\n  set end time = 1\nend\n";

  const auto boundary =
    cmpm_runs::run<2>(prefix + ".prm", "bar_boundary", to_one_second);
  const auto bspline =
    cmpm_runs::run<2>(prefix + "_bspline.prm", "bar_bspline", to_one_second);
  const auto h3 =
    cmpm_runs::run<2>(prefix + "_h3.prm", "bar_h3", to_one_second);
  const auto fine =
    cmpm_runs::run<2>(prefix + "_fine.prm", "bar_fine", to_one_second);
  cmpm_runs::print_cost("cMPM boundary B-spline", boundary);
  cmpm_runs::print_cost("cMPM B-spline", bspline);
  cmpm_runs::print_cost("cMPM boundary B-spline, L = H/3", h3);
  cmpm_runs::print_cost("BSMPM-fine", fine);
  std::cout << "assembly per Newton iteration, B-spline / boundary B-spline: "
            << (bspline.assembly / bspline.newton_iterations) /
                 (boundary.assembly / boundary.newton_iterations)
            << std::endl;

  const auto [boundary_u, boundary_sigma] =
    cmpm_runs::max_errors("bar_fine", "bar_boundary", true);
  const auto [bspline_u, bspline_sigma] =
    cmpm_runs::max_errors("bar_fine", "bar_bspline", true);
  dealii::deallog << "max r_u to t = 1 s: boundary B-spline "
                  << format("%.4f", boundary_u) << ", B-spline "
                  << format("%.4f", bspline_u)
                  << " (seed 3D: 0.025, 0.021); max r_sigma "
                  << format("%.4f", boundary_sigma) << ", "
                  << format("%.4f", bspline_sigma) << std::endl;
  const auto [h3_u, h3_sigma] =
    cmpm_runs::max_errors("bar_fine", "bar_h3", false);
  dealii::deallog << "boundary B-spline elements with L = H/3: max r_u "
                  << format("%.4f", h3_u) << ", max r_sigma "
                  << format("%.4f", h3_sigma) << ", unknowns "
                  << format("%.0f", h3.dofs) << std::endl;
  dealii::deallog << "unknowns: boundary B-spline "
                  << format("%.0f", boundary.dofs) << ", B-spline "
                  << format("%.0f", bspline.dofs) << ", BSMPM-fine "
                  << format("%.0f", fine.dofs) << " (means over the steps)"
                  << std::endl;
  bfemp_tests::check(boundary_u < 0.1 && bspline_u < 0.1,
                     "max r_u of both element types below 0.1");
  bfemp_tests::check(bspline_u <= boundary_u && boundary_u < 3. * bspline_u,
                     "B-spline elements at least as accurate, within a "
                     "factor 3 of the boundary B-spline elements");
  bfemp_tests::check(h3_u < 0.8 * boundary_u,
                     "L = H/3 below 0.8 of the L = H/2 boundary B-spline "
                     "elements' max r_u");
}
