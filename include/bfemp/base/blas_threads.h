#ifndef bfemp_base_blas_threads_h
#define bfemp_base_blas_threads_h

#include <string>

namespace bfemp
{
  /**
   * The threads of the BLAS behind CHOLMOD's supernodal factorization
   * (OpenBLAS on Debian), which bfemp sets itself instead of leaving them to
   * OpenBLAS: OpenBLAS starts one thread per core, and its threads keep
   * spinning after a BLAS call. On a machine with other busy processes
   * they take the cores that would do the work: with two busy processes on
   * two cores a 3D twist step ran 9 times slower with two BLAS threads than
   * with one (doc/performance.md "BLAS threads").
   *
   * The policy (`run/BLAS threads = auto`): one BLAS thread. Only when
   * `run/threads` = N > 1 is set, which says that N cores are the run's
   * own, does a factorization of more than parallel_flops floating-point
   * operations get N (1.1-1.7 times faster on a quiet machine). A number
   * instead of `auto` fixes the threads of every BLAS call. BLAS libraries
   * other than OpenBLAS cannot be told: describe() says so and nothing is
   * changed.
   */
  class BlasThreads
  {
  public:
    /**
     * A factorization of this many flops (CHOLMOD's count) or more is worth
     * more than one BLAS thread (measured: doc/performance.md).
     */
    static constexpr double parallel_flops = 1e9;

    /**
     * Sets the policy: @p fixed > 0 threads for every call, or (fixed = 0)
     * the auto policy with up to @p limit threads (`run/threads`, 0 counts
     * as 1) for large factorizations. Sets the BLAS to the threads of a
     * small call now.
     */
    static void
    configure(const unsigned int fixed, const unsigned int limit);

    /** Whether the BLAS in use takes a thread count (OpenBLAS does). */
    static bool
    controllable();

    /** The BLAS's thread count now; -1 if it cannot be told. */
    static int
    current();

    /** One line for the log: the BLAS and the threads it uses. */
    static std::string
    describe();

    /**
     * The BLAS threads of one factorization of @p flops, for its lifetime;
     * the previous count afterwards.
     */
    class Scope
    {
    public:
      explicit Scope(const double flops);
      ~Scope();
      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      int previous = 0;
    };
  };
} // namespace bfemp

#endif
