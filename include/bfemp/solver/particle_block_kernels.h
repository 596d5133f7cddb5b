#ifndef bfemp_solver_particle_block_kernels_h
#define bfemp_solver_particle_block_kernels_h

namespace bfemp
{
  /**
   * The inner loops of the MPM elasticity Hessian (eq. 25), where implicit
   * 3D MPM assembly spends most of its time. Both run over
   * particle_block_width stencil nodes at once in vector registers, so
   * they take a particle's node data by component, each component a row
   * of L values (L a multiple of particle_block_width, zero-padded past
   * the stencil's nodes):
   * - gradients G: g^_l[d] = (F_p^n)^T grad w_lp at G[d L + l];
   * - first contractions C: A_k[a][b][d] at C[((a dim + b) dim + d) L + k].
   *
   * On x86-64 they are compiled twice, for x86-64-v3 (AVX2 and fused
   * multiply-adds) and for the baseline, and the processor picks the
   * version when the library is loaded: results may differ in the last
   * bits between machines (as BLAS's do), never between runs or thread
   * counts on one machine.
   */
  constexpr unsigned int particle_block_width = 4;

  /**
   * A_k[a][b][d] = w sum_j A[a][j][b][d] g^_k[j] for all stencil nodes k
   * of one particle: the first contraction of the blocks of row node k
   * (@p tangent: dP/dF, dim^4 values in deal.II's Tensor<4, dim> order;
   * @p weight: s V_p^0).
   */
  template <int dim>
  void
  first_contractions(const double *tangent,
                     double        weight,
                     const double *gradients,
                     unsigned int  L,
                     double       *contractions);

  /**
   * One block row k of the Hessian summed over a group of particles that
   * share a stencil:
   *
   *   row[(a dim + b) L + l] = sum_p sum_d A_k,p[a][b][d] g^_l,p[d]
   *
   * for the columns l in [@p l_begin, @p L) (l_begin a multiple of
   * particle_block_width); @p contractions[p] points at particle p's
   * C + k, @p gradients[p] at its G. Entries of @p row before l_begin are
   * left alone.
   */
  template <int dim>
  void
  sum_block_row(const double *const *contractions,
                const double *const *gradients,
                unsigned int         n_particles,
                unsigned int         L,
                unsigned int         l_begin,
                double              *row);
} // namespace bfemp

#endif
