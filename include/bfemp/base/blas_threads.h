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
   * operations get N (1.1-1.7 times faster on a quiet machine), and so do
   * the triangular solves with a factor whose solves take more than
   * parallel_solve_flops (1.25 times faster on the full twist). A number
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
     * A pair of triangular solves (4 nnz(L) flops) of this many flops or
     * more is worth more than one thread: CHOLMOD's supernodal solves are
     * BLAS-2 calls on the supernodes, and those of a 3D factor are large.
     * On the full twist (nnz(L) about 5e7) two threads cut the solve time
     * by a fifth (doc/performance.md "BLAS threads").
     */
    static constexpr double parallel_solve_flops = 1e8;

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
     * The BLAS threads of one factorization or solve, for its lifetime;
     * the previous count afterwards.
     */
    class Scope
    {
    public:
      /** A factorization of @p flops, or (@p solve) a pair of triangular
       *  solves of @p flops. */
      explicit Scope(const double flops, const bool solve = false);
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
