#include <bfemp/solver/particle_block_kernels.h>

#include <cstring>

// deal.II's flags switch -Wpsabi off; here it would name a vector passed
// between code compiled for different instruction sets (see Nodes).
#pragma GCC diagnostic warning "-Wpsabi"

// Two versions of each kernel on x86-64 with GCC: AVX2 with fused
// multiply-adds where the processor has them, the baseline instruction set
// elsewhere (resolved once when the library is loaded).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#  define BFEMP_SIMD_CLONES \
    __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#  define BFEMP_SIMD_CLONES
#endif

namespace bfemp
{
  namespace
  {
    /** particle_block_width doubles in one vector (two SSE2 registers on
     *  the baseline, one AVX register on x86-64-v3). Vectors are loaded and
     *  stored with memcpy inside the kernels, never passed to a function:
     *  a helper is compiled for the baseline, whose calling convention for
     *  a 32-byte vector differs from the AVX clone's (without inlining, in
     *  Debug builds, the values came back wrong). */
    typedef double Nodes
      __attribute__((vector_size(particle_block_width * sizeof(double))));
  } // namespace

  template <int dim>
  BFEMP_SIMD_CLONES void
  first_contractions(const double      *tangent,
                     const double       weight,
                     const double      *gradients,
                     const unsigned int L,
                     double            *contractions)
  {
    for (unsigned int c = 0; c < L; c += particle_block_width)
      {
        Nodes g[dim];
        for (unsigned int j = 0; j < dim; ++j)
          std::memcpy(&g[j], gradients + j * L + c, sizeof(Nodes));
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int d = 0; d < dim; ++d)
              {
                Nodes sum = {};
                for (unsigned int j = 0; j < dim; ++j)
                  sum += tangent[((a * dim + j) * dim + b) * dim + d] * g[j];
                sum *= weight;
                std::memcpy(contractions + ((a * dim + b) * dim + d) * L + c,
                            &sum,
                            sizeof(Nodes));
              }
      }
  }

  template <int dim>
  BFEMP_SIMD_CLONES void
  sum_block_row(const double *const *contractions,
                const double *const *gradients,
                const unsigned int   n_particles,
                const unsigned int   L,
                const unsigned int   l_begin,
                double              *row)
  {
    for (unsigned int c = l_begin; c < L; c += particle_block_width)
      {
        // dim^2 accumulators stay in registers over all particles of the
        // group: each block entry is written once.
        Nodes sum[dim * dim] = {};
        for (unsigned int p = 0; p < n_particles; ++p)
          {
            const double *A = contractions[p];
            for (unsigned int d = 0; d < dim; ++d)
              {
                Nodes g;
                std::memcpy(&g, gradients[p] + d * L + c, sizeof(Nodes));
                for (unsigned int ab = 0; ab < dim * dim; ++ab)
                  sum[ab] += A[(ab * dim + d) * L] * g;
              }
          }
        for (unsigned int ab = 0; ab < dim * dim; ++ab)
          std::memcpy(row + ab * L + c, &sum[ab], sizeof(Nodes));
      }
  }

  template void
  first_contractions<2>(const double *,
                        double,
                        const double *,
                        unsigned int,
                        double *);
  template void
  first_contractions<3>(const double *,
                        double,
                        const double *,
                        unsigned int,
                        double *);
  template void
  sum_block_row<2>(const double *const *,
                   const double *const *,
                   unsigned int,
                   unsigned int,
                   unsigned int,
                   double *);
  template void
  sum_block_row<3>(const double *const *,
                   const double *const *,
                   unsigned int,
                   unsigned int,
                   unsigned int,
                   double *);
} // namespace bfemp
