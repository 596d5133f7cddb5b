#include <bfemp/base/blas_threads.h>

#include <algorithm>
#include <dlfcn.h>

namespace bfemp
{
  namespace
  {
    // OpenBLAS's thread control, looked up at run time: Debian's BLAS is
    // chosen by the alternatives system, so the library linked at build
    // time need not be OpenBLAS.
    using SetThreads = void (*)(int);
    using GetThreads = int (*)();
    using GetConfig  = char *(*)();

    struct OpenBlas
    {
      SetThreads set    = nullptr;
      GetThreads get    = nullptr;
      GetConfig  config = nullptr;

      OpenBlas()
      {
        set = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        get = reinterpret_cast<GetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        config = reinterpret_cast<GetConfig>(
          dlsym(RTLD_DEFAULT, "openblas_get_config"));
      }
    };

    const OpenBlas &
    openblas()
    {
      static const OpenBlas library;
      return library;
    }

    // the policy set by configure()
    unsigned int fixed_threads = 0;
    unsigned int thread_limit  = 1;
  } // namespace



  void
  BlasThreads::configure(const unsigned int fixed, const unsigned int limit)
  {
    fixed_threads = fixed;
    thread_limit  = std::max(1u, limit);
    if (controllable())
      openblas().set(static_cast<int>(fixed > 0 ? fixed : 1));
  }



  bool
  BlasThreads::controllable()
  {
    return openblas().set != nullptr && openblas().get != nullptr;
  }



  int
  BlasThreads::current()
  {
    return controllable() ? openblas().get() : -1;
  }



  std::string
  BlasThreads::describe()
  {
    if (!controllable())
      return "BLAS: not OpenBLAS, its threads are left as they are";
    std::string name = "OpenBLAS";
    if (openblas().config != nullptr)
      name = openblas().config();
    if (fixed_threads > 0)
      return "BLAS: " + name + ", " + std::to_string(fixed_threads) +
             " thread(s) ('run/BLAS threads')";
    if (thread_limit == 1)
      return "BLAS: " + name +
             ", 1 thread ('run/BLAS threads = auto'; set 'run/threads' on a "
             "machine of your own to use more in large factorizations)";
    return "BLAS: " + name + ", 1 thread, " + std::to_string(thread_limit) +
           " in factorizations above 1e9 flops and solves above 1e8 "
           "('run/BLAS threads = auto', 'run/threads')";
  }



  BlasThreads::Scope::Scope(const double flops, const bool solve)
  {
    if (!controllable() || fixed_threads > 0)
      return;
    previous = openblas().get();
    if (flops >= (solve ? parallel_solve_flops : parallel_flops))
      openblas().set(static_cast<int>(thread_limit));
  }



  BlasThreads::Scope::~Scope()
  {
    if (previous > 0)
      openblas().set(previous);
  }
} // namespace bfemp
