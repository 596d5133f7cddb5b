#ifndef bfemp_tests_tests_h
#define bfemp_tests_tests_h

// Shared set-up of the unit tests: deallog writes into the file "output",
// which deal_ii_pickup_tests() compares with name.output through numdiff.

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>

namespace bfemp_tests
{
  inline std::ofstream &
  initlog()
  {
    static std::ofstream logfile("output");
    logfile << std::setprecision(8);
    dealii::deallog.attach(logfile, false);
    dealii::deallog.depth_console(0);
    return logfile;
  }

  /** A check that the output records; a failure also makes the test exit
   *  non-zero, so it fails even where numdiff tolerances would hide it. */
  inline void
  check(const bool condition, const std::string &what)
  {
    dealii::deallog << (condition ? "OK   " : "FAIL ") << what << std::endl;
    if (!condition)
      {
        std::cerr << "check failed: " << what << std::endl;
        std::exit(1);
      }
  }
} // namespace bfemp_tests

#endif
