#ifndef bfemp_benchmarks_machine_info_h
#define bfemp_benchmarks_machine_info_h

// What every benchmark records next to its figures: the machine, the build,
// the load, the git state, and the JSON quoting it writes them with. Shared
// by explicit_throughput.cc and implicit_newton.cc.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <sys/resource.h>

#ifndef BFEMP_SOURCE_DIR
#  define BFEMP_SOURCE_DIR "."
#endif

namespace machine_info
{
  inline double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }

  /** The standard output of a shell command, trailing blanks removed. */
  inline std::string
  run_command(const std::string &command)
  {
    std::string result;
    if (FILE *pipe = popen(command.c_str(), "r"))
      {
        char buffer[256];
        while (fgets(buffer, sizeof(buffer), pipe))
          result += buffer;
        pclose(pipe);
      }
    while (!result.empty() && (result.back() == '\n' || result.back() == ' '))
      result.pop_back();
    return result;
  }

  inline std::string
  cpu_model()
  {
    std::ifstream in("/proc/cpuinfo");
    std::string   line;
    while (std::getline(in, line))
      if (line.rfind("model name", 0) == 0)
        {
          std::string name = line.substr(line.find(':') + 1);
          name.erase(0, name.find_first_not_of(' '));
          return name;
        }
    return "unknown";
  }

  inline double
  memory_gib()
  {
    std::ifstream in("/proc/meminfo");
    std::string   key;
    double        kib = 0.;
    while (in >> key >> kib)
      {
        if (key == "MemTotal:")
          return kib / (1024. * 1024.);
        in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      }
    return 0.;
  }

  /**
   * The BLAS/LAPACK libraries mapped into this process (CHOLMOD's
   * supernodal factorization and UMFPACK spend their time there): resolved
   * paths, so the reference BLAS and OpenBLAS/BLIS/MKL are told apart.
   */
  inline std::string
  blas_libraries()
  {
    std::ifstream         in("/proc/self/maps");
    std::string           line;
    std::set<std::string> found;
    while (std::getline(in, line))
      {
        const auto slash = line.find('/');
        if (slash == std::string::npos)
          continue;
        const std::string path = line.substr(slash);
        const std::string file = std::filesystem::path(path).filename();
        if (file.find("blas") != std::string::npos ||
            file.find("lapack") != std::string::npos ||
            file.find("blis") != std::string::npos ||
            file.find("mkl") != std::string::npos)
          found.insert(path);
      }
    std::string list;
    for (const std::string &path : found)
      {
        std::error_code ec;
        const auto      real = std::filesystem::canonical(path, ec);
        list += (list.empty() ? "" : " ") + (ec ? path : real.string());
      }
    return list;
  }

  inline std::string
  environment(const char *name)
  {
    const char *value = std::getenv(name);
    return value ? value : "";
  }

  /** A finite number, or null (JSON has no inf/NaN). */
  inline std::string
  json_number(const double x)
  {
    if (!std::isfinite(x))
      return "null";
    std::ostringstream s;
    s << std::setprecision(6) << x;
    return s.str();
  }

  /** "release" (NDEBUG, deal.II's optimized library) or "debug". */
  inline std::string
  build_type()
  {
#ifdef NDEBUG
    return "release";
#else
    return "debug";
#endif
  }

  inline double
  process_cpu_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  /** Peak resident memory of the process so far [GiB] (monotone). */
  inline double
  peak_memory_gib()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / (1024. * 1024.); // ru_maxrss is in KiB
  }

  inline double
  load_average()
  {
    std::ifstream in("/proc/loadavg");
    double        load = -1.;
    in >> load;
    return load;
  }

  /** @p s as a JSON string literal. */
  inline std::string
  json_string(const std::string &s)
  {
    std::string out = "\"";
    for (const char c : s)
      if (c == '"' || c == '\\')
        out += std::string("\\") + c;
      else if (c == '\n')
        out += "\\n";
      else if (static_cast<unsigned char>(c) < 0x20)
        out += ' ';
      else
        out += c;
    return out + "\"";
  }

  struct GitState
  {
    std::string commit, modified;
  };

  /**
   * The commit of the source tree and the library files changed since.
   * Read-only: rev-parse, and status with --no-optional-locks so that it
   * does not touch the index.
   */
  inline GitState
  read_git_state()
  {
    const std::string source = BFEMP_SOURCE_DIR;
    GitState          state;
    state.commit =
      run_command("git -C '" + source + "' rev-parse HEAD 2>/dev/null");
    state.modified = run_command(
      "git -C '" + source +
      "' --no-optional-locks status --porcelain --untracked-files=no -- "
      "include source 2>/dev/null | cut -c4- | tr '\\n' ' '");
    return state;
  }
} // namespace machine_info

#endif
