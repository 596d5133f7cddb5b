#ifndef bfemp_tests_tests_h
#define bfemp_tests_tests_h

// Shared set-up of the unit tests: deallog writes into the file "output",
// which deal_ii_pickup_tests() compares with name.output through numdiff.

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <random>
#include <string>

#include "format.h"

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

  /**
   * Uniform random numbers from a seeded std::mt19937. The standard fixes
   * the engine's output sequence (unlike the distributions'), so a test
   * draws the same values with every compiler.
   */
  class RandomNumbers
  {
  public:
    explicit RandomNumbers(const unsigned int seed)
      : engine(seed)
    {}

    double
    uniform(const double low, const double high)
    {
      return low + (high - low) * (engine() / 4294967295.);
    }

    /** Components uniform in [-amplitude, amplitude]. */
    template <int dim>
    dealii::Tensor<1, dim>
    vector(const double amplitude)
    {
      dealii::Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = uniform(-amplitude, amplitude);
      return v;
    }

    /** Entries uniform in [-amplitude, amplitude], row by row. */
    template <int dim>
    dealii::Tensor<2, dim>
    tensor(const double amplitude)
    {
      dealii::Tensor<2, dim> A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          A[i][j] = uniform(-amplitude, amplitude);
      return A;
    }

  private:
    std::mt19937 engine;
  };

  /** The rotation by @p angle in the plane (2D; the axis is ignored). */
  inline dealii::Tensor<2, 2>
  rotation(const double angle, const dealii::Tensor<1, 2> &)
  {
    dealii::Tensor<2, 2> Q;
    Q[0][0] = std::cos(angle);
    Q[0][1] = -std::sin(angle);
    Q[1][0] = std::sin(angle);
    Q[1][1] = std::cos(angle);
    return Q;
  }

  /** The rotation by @p angle about the unit axis @p n (Rodrigues). */
  inline dealii::Tensor<2, 3>
  rotation(const double angle, const dealii::Tensor<1, 3> &n)
  {
    dealii::Tensor<2, 3> K;
    K[0][1] = -n[2];
    K[0][2] = n[1];
    K[1][0] = n[2];
    K[1][2] = -n[0];
    K[2][0] = -n[1];
    K[2][1] = n[0];
    return dealii::unit_symmetric_tensor<3>() + std::sin(angle) * K +
           (1. - std::cos(angle)) * K * K;
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

  /** "3.1e-09 (bound 1e-06)": a measured value at two significant digits
   *  and the bound a check compares it with, for the line that records the
   *  check. */
  inline std::string
  measured(const double value, const double bound)
  {
    return format("%.1e", value) + " (bound " + format("%g", bound) + ")";
  }

  /** The check "@p value <= @p bound" (a NaN fails), recorded as
   *  "what 3.1e-09 (bound 1e-06)": the output holds the measured value, so
   *  a drift within the bound shows in the comparison with the .output
   *  file. */
  inline void
  check_below(const double value, const double bound, const std::string &what)
  {
    check(value <= bound, what + " " + measured(value, bound));
  }

#if defined(BFEMP_SOURCE_DIR) && defined(BFEMP_BINARY_DIR)
  /** Runs the study script doc/experiments/@p script on this build's bfemp,
   *  quietly, with its work folder @p folder (removed first: the scripts
   *  resume from the results they find there, which may come from an
   *  earlier build) and @p arguments; its output goes to @p folder.log.
   *  True if it exited with status 0. */
  inline bool
  run_study(const std::string &script,
            const std::string &folder,
            const std::string &arguments = "")
  {
    const std::string command =
      "rm -rf " + folder + " && /usr/bin/python3 " + BFEMP_SOURCE_DIR +
      "/doc/experiments/" + script + " --quiet --out " + folder + " --bfemp " +
      BFEMP_BINARY_DIR + "/bfemp " + arguments + " > " + folder + ".log 2>&1";
    return std::system(command.c_str()) == 0;
  }
#endif
} // namespace bfemp_tests

#endif
