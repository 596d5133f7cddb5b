#ifndef bfemp_base_parallel_sum_h
#define bfemp_base_parallel_sum_h

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace bfemp
{
  /**
   * sum_{i < n} f(i), computed by threads in fixed chunks and added up
   * chunk by chunk in order, so the result is the same bit for bit for any
   * number of threads (a tree reduction would not be).
   */
  template <typename Result, typename Function>
  Result
  chunked_sum(const std::size_t n, const Function &f)
  {
    constexpr std::size_t chunk    = 512;
    const std::size_t     n_chunks = (n + chunk - 1) / chunk;
    std::vector<Result>   partial(n_chunks, Result());
    dealii::parallel::apply_to_subranges(
      std::size_t(0),
      n_chunks,
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t c = begin; c < end; ++c)
          for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i)
            partial[c] += f(i);
      },
      1);
    Result result = Result();
    for (const Result &p : partial)
      result += p;
    return result;
  }

  /** A minimum that can be accumulated with += (for chunked_sum). */
  struct Minimum
  {
    double value = std::numeric_limits<double>::infinity();

    Minimum &
    operator+=(const Minimum &other)
    {
      value = std::min(value, other.value);
      return *this;
    }

    Minimum &
    operator+=(const double other)
    {
      value = std::min(value, other);
      return *this;
    }
  };

  /** A maximum that can be accumulated with += (for chunked_sum). */
  struct Maximum
  {
    double value = -std::numeric_limits<double>::infinity();

    Maximum &
    operator+=(const Maximum &other)
    {
      value = std::max(value, other.value);
      return *this;
    }

    Maximum &
    operator+=(const double other)
    {
      value = std::max(value, other);
      return *this;
    }
  };
} // namespace bfemp

#endif
