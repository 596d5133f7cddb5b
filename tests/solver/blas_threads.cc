// BlasThreads, the BLAS thread policy around CHOLMOD's factorization
// (doc/performance.md "BLAS threads"), on Debian's OpenBLAS:
// - the BLAS is OpenBLAS and takes a thread count;
// - auto with run/threads = 0: one thread, also inside a large
//   factorization's scope;
// - auto with run/threads = 2: one thread, two inside the scope of a
//   factorization above BlasThreads::parallel_flops, one in a small one's,
//   and one again after the scope;
// - a fixed count: that count everywhere, scopes change nothing;
// - 'run/BLAS threads' parses 'auto' as 0 and a number as itself.

#include <bfemp/base/blas_threads.h>
#include <bfemp/base/run_parameters.h>

#include "tests.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;

namespace
{
  /** Threads inside the scope of a factorization (or, with @p solve, of
   *  triangular solves) of @p flops. */
  int
  inside(const double flops, const bool solve = false)
  {
    const BlasThreads::Scope scope(flops, solve);
    return BlasThreads::current();
  }

  void
  report(const std::string &what,
         const int          outside,
         const int          small,
         const int          large,
         const int          expected_outside,
         const int          expected_large)
  {
    deallog << what << ": " << outside << " thread(s), " << small
            << " in a 1e6-flop factorization, " << large
            << " in a 1e10-flop one" << std::endl;
    check(outside == expected_outside && small == expected_outside &&
            large == expected_large && BlasThreads::current() == outside,
          what + ": as the policy says, and restored after each scope");
  }

  unsigned int
  parse_blas_threads(const std::string &value)
  {
    ParameterHandler prm;
    RunParameters::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection run\n  set BLAS threads = " + value + "\nend\n");
    RunParameters run;
    run.parse_parameters(prm);
    return run.blas_threads;
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  check(BlasThreads::controllable(), "the BLAS is OpenBLAS");

  BlasThreads::configure(0, 0);
  report("auto, run/threads = 0",
         BlasThreads::current(),
         inside(1e6),
         inside(1e10),
         1,
         1);
  BlasThreads::configure(0, 2);
  report("auto, run/threads = 2",
         BlasThreads::current(),
         inside(1e6),
         inside(1e10),
         1,
         2);
  // solves: their own threshold (1e8 flops), below a factorization's
  const int small_solve = inside(1e7, true), large_solve = inside(5e8, true);
  deallog << "auto, run/threads = 2: " << small_solve << " in 1e7-flop solves, "
          << large_solve << " in 5e8-flop ones" << std::endl;
  check(small_solve == 1 && large_solve == 2 && BlasThreads::current() == 1,
        "auto, run/threads = 2: solves as the policy says, restored");
  BlasThreads::configure(3, 2);
  report("fixed 3", BlasThreads::current(), inside(1e6), inside(1e10), 3, 3);

  check(parse_blas_threads("auto") == 0 && parse_blas_threads("2") == 2,
        "'run/BLAS threads': auto is 0, a number is itself");
}
