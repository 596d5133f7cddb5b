#include <bfemp/cmpm/coarsened_shape_functions.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>

namespace bfemp
{
  template <int dim>
  CoarsenedShapeFunctions<dim>::CoarsenedShapeFunctions(
    const CoarseGrid<dim> &grid)
    : coarse_grid(grid)
    , psi(grid)
    , condensation(grid, psi)
    , control(grid.n_elements_total())
    , bound(grid.n_elements_total(), 0.)
  {
    boundary_rank.assign(grid.n_fine(), -1);
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      if (grid.interior_index(k) < 0)
        {
          boundary_rank[k] = boundary_fine.size();
          boundary_fine.push_back(k);
        }
    // The fine nodes up to the last interior one: U_ij (node i <= node j)
    // with j interior needs node i below it (condense()).
    unsigned int last_interior = 0;
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      if (grid.interior_index(k) >= 0)
        last_interior = k;
    n_rows_coupled_to_interior =
      grid.n_interior_fine() + (std::lower_bound(boundary_fine.begin(),
                                                 boundary_fine.end(),
                                                 last_interior) -
                                boundary_fine.begin());
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      {
        double row_sum = 0.;
        for (const auto &[I, weight] : psi.row(k))
          {
            AssertIndexRange(I, grid.n_local_nodes());
            row_sum += std::abs(weight);
          }
        boundary_bound = std::max(boundary_bound, row_sum);
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::build(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points)
  {
    condensation.compute(points, control[element]);
    update_bound(element);
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::update_bound(const std::size_t element)
  {
    // Fine node k moves by sum_I p_kI Q_I: component a by at most
    // sum_I sum_c |(p_kI)_ac| |Q|_inf.
    const unsigned int r       = coarse_grid.n_local_nodes();
    const auto        &p       = control[element];
    double             largest = boundary_bound;
    for (std::size_t i = 0; i * r < p.size(); ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          double row_sum = 0.;
          for (unsigned int I = 0; I < r; ++I)
            for (unsigned int c = 0; c < dim; ++c)
              row_sum += std::abs(p[i * r + I][a][c]);
          largest = std::max(largest, row_sum);
        }
    bound[element] = largest;
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::reinit(
    const std::vector<std::size_t>                            &elements,
    const std::vector<std::vector<LocalQuadraturePoint<dim>>> &points)
  {
    AssertDimension(elements.size(), points.size());
    clear();
    // one element per task: the per-element work is a dense solve of
    // dim (n - 4)^dim unknowns, large against the scheduling cost
    parallel::apply_to_subranges(
      std::size_t(0),
      elements.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t e = begin; e < end; ++e)
          build(elements[e], points[e]);
      },
      1);
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::clear()
  {
    for (auto &element_control : control)
      element_control.clear();
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::rebuild(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points)
  {
    build(element, points);
  }



  template <int dim>
  LocalSolveStatistics
  CoarsenedShapeFunctions<dim>::rebuild_at_equilibrium(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points,
    const std::vector<Tensor<1, dim>>            &coarse_displacement)
  {
    const LocalSolveStatistics statistics =
      condensation.compute_at_equilibrium(points,
                                          coarse_displacement,
                                          control[element]);
    update_bound(element);
    return statistics;
  }



  template <int dim>
  bool
  CoarsenedShapeFunctions<dim>::is_active(const std::size_t element) const
  {
    return !control[element].empty();
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::evaluate(
    const std::array<int, dim>         &element,
    const Point<dim>                   &x,
    std::vector<CoarseShapeValue<dim>> &values) const
  {
    const std::size_t index = coarse_grid.element_index(element);
    AssertThrow(is_active(index),
                ExcMessage("cMPM: a coarse element without shape functions "
                           "was evaluated (it held no particle when they "
                           "were built)"));
    const unsigned int r = coarse_grid.n_local_nodes();
    values.assign(r, CoarseShapeValue<dim>());
    for (unsigned int I = 0; I < r; ++I)
      values[I].node = coarse_grid.global_node(element, I);

    typename CoarseGrid<dim>::FineStencil stencil;
    coarse_grid.fine_stencil(Point<dim>(x -
                                        coarse_grid.element_origin(element)),
                             stencil);
    const std::vector<Tensor<2, dim>> &p = control[index];

    // eq. 15: Phi_I = sum_k B_k p_kI; p_kI = psi_kI identity on the boundary
    // rows (eq. 31), the condensed blocks on the interior rows
    for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
      {
        const double          B      = stencil.value[q];
        const Tensor<1, dim> &grad_B = stencil.gradient[q];
        const int             i = coarse_grid.interior_index(stencil.node[q]);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(stencil.node[q]))
            for (unsigned int a = 0; a < dim; ++a)
              {
                values[I].value[a][a] += B * weight;
                values[I].gradient[a][a] += weight * grad_B;
              }
        else
          for (unsigned int I = 0; I < r; ++I)
            {
              const Tensor<2, dim> &p_kI = p[i * r + I];
              values[I].value += B * p_kI;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int c = 0; c < dim; ++c)
                  values[I].gradient[a][c] += p_kI[a][c] * grad_B;
            }
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::values(
    const std::size_t                            element,
    const typename CoarseGrid<dim>::FineStencil &stencil,
    std::vector<Tensor<2, dim>>                 &phi) const
  {
    Assert(is_active(element), ExcInternalError());
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];
    // eq. 15 as in evaluate(): the boundary rows are psi_kI I, so their
    // part is a scalar per coarse node
    thread_local std::vector<double> boundary;
    boundary.assign(r, 0.);
    phi.assign(r, Tensor<2, dim>());
    for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
      {
        const double B = stencil.value[q];
        const int    i = coarse_grid.interior_index(stencil.node[q]);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(stencil.node[q]))
            boundary[I] += B * weight;
        else
          for (unsigned int I = 0; I < r; ++I)
            phi[I] += B * p[i * r + I];
      }
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int a = 0; a < dim; ++a)
        phi[I][a][a] += boundary[I];
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::evaluate(
    const Point<dim>                   &x,
    std::vector<CoarseShapeValue<dim>> &values) const
  {
    evaluate(coarse_grid.element_of(x), x, values);
  }



  template <int dim>
  double
  CoarsenedShapeFunctions<dim>::averaged_scalar(const Tensor<2, dim> &value)
  {
    return trace(value) / dim;
  }



  template <int dim>
  const CoarseGrid<dim> &
  CoarsenedShapeFunctions<dim>::grid() const
  {
    return coarse_grid;
  }



  template <int dim>
  const CoarseBoundaryMap<dim> &
  CoarsenedShapeFunctions<dim>::coarse_boundary_map() const
  {
    return psi;
  }



  template <int dim>
  double
  CoarsenedShapeFunctions<dim>::interpolation_bound(
    const std::size_t element) const
  {
    Assert(is_active(element), ExcInternalError());
    return bound[element];
  }



  template <int dim>
  const std::vector<Tensor<2, dim>> &
  CoarsenedShapeFunctions<dim>::interior_control(
    const std::size_t element) const
  {
    return control[element];
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::fine_values(
    const std::size_t                  element,
    const std::vector<Tensor<1, dim>> &coarse,
    std::vector<Tensor<1, dim>>       &fine) const
  {
    Assert(is_active(element), ExcInternalError());
    const unsigned int r = coarse_grid.n_local_nodes();
    AssertDimension(coarse.size(), r);
    const std::vector<Tensor<2, dim>> &p = control[element];
    fine.assign(coarse_grid.n_fine(), Tensor<1, dim>());
    for (unsigned int k = 0; k < fine.size(); ++k)
      {
        const int i = coarse_grid.interior_index(k);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(k))
            fine[k] += weight * coarse[I];
        else
          for (unsigned int I = 0; I < r; ++I)
            fine[k] += p[i * r + I] * coarse[I];
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::coarse_forces(
    const std::size_t                  element,
    const std::vector<Tensor<1, dim>> &fine,
    std::vector<Tensor<1, dim>>       &coarse) const
  {
    Assert(is_active(element), ExcInternalError());
    AssertDimension(fine.size(), coarse_grid.n_fine());
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];
    coarse.assign(r, Tensor<1, dim>());
    for (unsigned int k = 0; k < fine.size(); ++k)
      {
        const int i = coarse_grid.interior_index(k);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(k))
            coarse[I] += weight * fine[k];
        else
          for (unsigned int I = 0; I < r; ++I)
            coarse[I] += transpose(p[i * r + I]) * fine[k];
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::condense(
    const std::size_t                  element,
    const std::vector<unsigned int>   &nodes,
    const std::vector<Tensor<2, dim>> &upper,
    const std::vector<char>           &coupled,
    std::vector<Tensor<2, dim>>       &coarse) const
  {
    Assert(is_active(element), ExcInternalError());
    const std::size_t m = nodes.size();
    AssertDimension(upper.size(), m * m);
    AssertDimension(coupled.size(), m * m);
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];
    const unsigned int n_interior        = coarse_grid.n_interior_fine();

    // p has two kinds of rows (eq. 31): psi_kI I on the boundary fine nodes
    // and dense blocks on the interior ones. K_alpha = p^T K p is
    // formed as W + W^T, W = p^T G, G = U p (U: below).
    // The parts of K p and p^T G through the boundary rows of p are sparse
    // sums (K has few nonzero blocks per row, psi few entries per row);
    // those through the interior rows are matrix products by BLAS on
    // scalar matrices: row a of fine node k is row dim k + a, column b of
    // coarse node J is column dim J + b. BLAS is column-major, so a
    // row-major matrix is passed as its transpose. Rows of G: the interior
    // fine nodes first (by interior index), then the boundary ones (by
    // boundary rank); rows of fine nodes not in @p nodes stay zero.
    Assert(std::is_sorted(nodes.begin(), nodes.end()), ExcInternalError());
    const std::size_t                      cols = dim * r;
    thread_local std::vector<unsigned int> row;
    row.resize(m);
    const unsigned int n_rows = coarse_grid.n_fine();
    for (unsigned int i = 0; i < m; ++i)
      {
        const int interior = coarse_grid.interior_index(nodes[i]);
        row[i] =
          interior >= 0 ? interior : n_interior + boundary_rank[nodes[i]];
      }

    // the interior rows of p, dim n_interior x cols
    thread_local std::vector<double> p_interior;
    p_interior.resize(dim * n_interior * cols);
    for (unsigned int i = 0; i < n_interior; ++i)
      for (unsigned int J = 0; J < r; ++J)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            p_interior[(dim * i + a) * cols + dim * J + b] = p[i * r + J][a][b];

    // K's columns of the interior nodes (dim n_rows x dim n_interior), and
    // G += K_kl psi_lJ for the boundary nodes l. One fine node's rows of G
    // at a time, summed in a block-major buffer (coarse node, a, b) that
    // stays in the L1 cache: each psi entry is then one contiguous update
    // of dim x dim values. Only the first n_rows_coupled_to_interior rows of
    // K_interior can hold a block (U_ij needs node i <= node j), so the
    // product with p_interior below runs over those; the rows of G of the
    // fine nodes in @p nodes are written whole, the others are zero.
    const unsigned int n_coupled_rows = n_rows_coupled_to_interior;
    thread_local std::vector<double> K_interior;
    thread_local std::vector<double> G;
    thread_local std::vector<double> G_node;
    K_interior.assign(dim * n_coupled_rows * dim * n_interior, 0.);
    G.resize(dim * n_rows * cols);
    // K = U + U^T with U the upper blocks, the diagonal ones halved, so
    // p^T K p = W + W^T with W = p^T U p: only the upper blocks are read,
    // along their rows (the lower ones, read as transposes, were a strided
    // walk through the m x m blocks, which miss the cache). Fine nodes more
    // than two apart in a direction share no knot span, so node i couples
    // only with the 5^dim nodes around it: they are visited through a
    // position map of the patch in increasing node number (the order of
    // @p nodes, which is sorted), not by testing all m^2 pairs.
    const unsigned int            n_1d = coarse_grid.n_fine_1d();
    thread_local std::vector<int> position;
    position.assign(n_rows, -1);
    for (unsigned int i = 0; i < m; ++i)
      position[nodes[i]] = i;
    for (unsigned int k = 0; k < n_rows; ++k)
      if (position[k] < 0)
        {
          const int          interior = coarse_grid.interior_index(k);
          const unsigned int g_row =
            interior >= 0 ? interior : n_interior + boundary_rank[k];
          std::fill_n(&G[dim * g_row * cols], dim * cols, 0.);
        }
    constexpr unsigned int block = dim * dim;
    for (unsigned int i = 0; i < m; ++i)
      {
        G_node.assign(r * block, 0.);
        const std::array<unsigned int, dim> index =
          coarse_grid.fine_multi_index(nodes[i]);
        unsigned int lower[dim], extent[dim], n_neighbours = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d]  = index[d] >= 2 ? index[d] - 2 : 0;
            extent[d] = std::min(index[d] + 2, n_1d - 1) - lower[d] + 1;
            n_neighbours *= extent[d];
          }
        for (unsigned int t = 0; t < n_neighbours; ++t)
          {
            // t's digits, the first direction fastest: k increases with t
            unsigned int k = 0, stride = 1, rest = t;
            for (unsigned int d = 0; d < dim; ++d)
              {
                k += (lower[d] + rest % extent[d]) * stride;
                rest /= extent[d];
                stride *= n_1d;
              }
            const int j = position[k];
            // not in @p nodes, a lower block, or one that no particle forms
            if (j < static_cast<int>(i) || coupled[i * m + j] == 0)
              continue;
            // U_ij
            const double          factor = j == static_cast<int>(i) ? 0.5 : 1.;
            const Tensor<2, dim> &K_ij   = upper[i * m + j];
            if (row[j] < n_interior)
              {
                Assert(row[i] < n_coupled_rows, ExcInternalError());
                double *K_row = &K_interior[dim * row[i] * dim * n_interior];
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    K_row[a * dim * n_interior + dim * row[j] + b] =
                      factor * K_ij[a][b];
              }
            else
              {
                double K[block];
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    K[a * dim + b] = factor * K_ij[a][b];
                for (const auto &[J, weight] : psi.row(k))
                  {
                    double *G_J = &G_node[J * block];
                    for (unsigned int c = 0; c < block; ++c)
                      G_J[c] += weight * K[c];
                  }
              }
          }
        for (unsigned int a = 0; a < dim; ++a)
          {
            double *G_row = &G[(dim * row[i] + a) * cols];
            for (unsigned int J = 0; J < r; ++J)
              for (unsigned int b = 0; b < dim; ++b)
                G_row[dim * J + b] = G_node[J * block + a * dim + b];
          }
      }

    // G += K_interior p_interior, i.e. G^T += p_interior^T K_interior^T,
    // over G's first n_coupled_rows rows
    const types::blas_int n_cols = cols, n_g_rows = dim * n_coupled_rows,
                          n_inner = dim * n_interior;
    // ('cmpm/fine nodes per direction' >= 5: at least one interior fine
    // node, so BLAS's leading dimensions are >= 1)
    Assert(n_interior > 0, ExcInternalError());
    const double                     one = 1.;
    thread_local std::vector<double> C;
    C.resize(cols * cols);
    gemm("N",
         "N",
         &n_cols,
         &n_g_rows,
         &n_inner,
         &one,
         p_interior.data(),
         &n_cols,
         K_interior.data(),
         &n_inner,
         &one,
         G.data(),
         &n_cols);
    // coarse = p^T G: the interior rows of G (the first dim n_interior),
    // coarse^T = G_interior^T p_interior, ...
    const double zero = 0.;
    gemm("N",
         "T",
         &n_cols,
         &n_cols,
         &n_inner,
         &one,
         G.data(),
         &n_cols,
         p_interior.data(),
         &n_cols,
         &zero,
         C.data(),
         &n_cols);
    // ... and coarse_(I a),. += sum_k psi_kI G_(k a),. over the boundary
    // rows k. psi has a few entries per row (the face B-splines of one
    // fine node), so this is a sparse sum of contiguous rows of G. It runs
    // by psi's rows: each row of G is read once while C stays in the L2
    // cache (by psi's columns, G, larger than L2, was read once per entry
    // of psi, and the step took 1.15 times as long).
    const types::blas_int unit = 1;
    for (unsigned int b = 0; b < boundary_fine.size(); ++b)
      {
        const unsigned int k = boundary_fine[b];
        if (position[k] < 0)
          continue; // a zero row of G
        for (const auto &[I, weight] : psi.row(k))
          for (unsigned int a = 0; a < dim; ++a)
            axpy(&n_cols,
                 &weight,
                 &G[(dim * (n_interior + b) + a) * cols],
                 &unit,
                 &C[(dim * I + a) * cols],
                 &unit);
      }

    // p^T K p = W + W^T, symmetric to the last bit (the upper blocks
    // mirrored), as the assembled Hessian of the other terms is
    coarse.resize(r * r);
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int J = I; J < r; ++J)
        {
          Tensor<2, dim> &block = coarse[I * r + J];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block[a][b] = C[(dim * I + a) * cols + dim * J + b] +
                            C[(dim * J + b) * cols + dim * I + a];
          coarse[J * r + I] = transpose(block);
        }
  }



  template class CoarsenedShapeFunctions<2>;
  template class CoarsenedShapeFunctions<3>;
} // namespace bfemp
