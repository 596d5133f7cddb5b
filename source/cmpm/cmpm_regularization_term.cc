#include <bfemp/cmpm/cmpm_regularization_term.h>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace bfemp
{
  template <int dim>
  CmpmRegularizationTerm<dim>::CmpmRegularizationTerm(
    ParticleSystem<dim>           &particles,
    const CmpmDiscretization<dim> &cmpm,
    const DofSpace<dim>           &dofs,
    const double                   weight)
    : particles(particles)
    , cmpm(cmpm)
    , dofs(dofs)
    , weight(weight)
  {}



  template <int dim>
  typename CmpmRegularizationTerm<dim>::Element
  CmpmRegularizationTerm<dim>::build_element(
    const std::array<int, dim> &index) const
  {
    const CoarseGrid<dim> &grid = cmpm.coarse_grid();
    Element                element;
    element.index = grid.element_index(index);

    // the element's unknowns, their masses and positions (in units of H
    // from the element's corner node, for a well-scaled fit)
    std::vector<Point<dim>> positions;
    std::vector<double>     masses;
    double                  mean = 0.;
    for (unsigned int I = 0; I < grid.n_local_nodes(); ++I)
      {
        const std::size_t  lattice_node = grid.global_node(index, I);
        const unsigned int node         = dofs.grid_node(lattice_node);
        if (node == DofSpace<dim>::invalid)
          continue;
        element.nodes.push_back(node);
        masses.push_back(node_mass[node]);
        mean += node_mass[node];
        Point<dim> X;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = grid.local_node_offset(I)[d] /
                 static_cast<double>(grid.parameters().nodes_per_span);
        positions.push_back(X);
      }
    const unsigned int n = element.nodes.size();
    mean /= std::max(n, 1u);
    element.kappa.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        element.kappa[k] = weight * std::max(0., mean - masses[k]);
        element.relative_weight =
          std::max(element.relative_weight, element.kappa[k] / (weight * mean));
      }

    // P_e = A (A^T W A)^-1 A^T W, the m_I-weighted fit by the affine basis
    // A = [1, X]; nodes on one line (plane in 3D) cannot fix it: no share
    FullMatrix<double> A(n, dim + 1), WA(n, dim + 1), normal(dim + 1, dim + 1);
    for (unsigned int k = 0; k < n; ++k)
      {
        A(k, 0) = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          A(k, d + 1) = positions[k][d];
        for (unsigned int c = 0; c <= dim; ++c)
          WA(k, c) = masses[k] / mean * A(k, c);
      }
    A.Tmmult(normal, WA);
    if (element.relative_weight == 0. ||
        std::abs(normal.determinant()) < 1e-12 * std::pow(n, dim + 1))
      {
        element.nodes.clear();
        return element;
      }
    normal.gauss_jordan();
    FullMatrix<double> fit(n, dim + 1);
    A.mmult(fit, normal);
    element.complement.reinit(n, n);
    fit.mTmult(element.complement, WA);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        element.complement(k, l) =
          (k == l ? 1. : 0.) - element.complement(k, l);
    return element;
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::reinit(const std::vector<double> &node_mass)
  {
    this->node_mass = node_mass;
    elements.clear();
    std::mutex mutex;
    // the elements holding particles, each built by the thread of its cell
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      if (cell_particles.begin() == cell_particles.end())
        return;
      Element element = build_element(
        cmpm.coarse_grid().element_of(cell_particles.begin()->get_location()));
      if (element.nodes.empty())
        return;
      std::lock_guard<std::mutex> lock(mutex);
      elements.push_back(std::move(element));
    });
    std::sort(elements.begin(),
              elements.end(),
              [](const Element &a, const Element &b) {
                return a.index < b.index;
              });
  }



  template <int dim>
  std::string
  CmpmRegularizationTerm<dim>::name() const
  {
    return "cMPM regularization";
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    for (const Element &element : elements)
      for (const unsigned int node : element.nodes)
        sparsity.add_row_entries(node, element.nodes);
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  CmpmRegularizationTerm<dim>::deviation(const Element        &element,
                                         const Vector<double> &u) const
  {
    const unsigned int          n = element.nodes.size();
    std::vector<Tensor<1, dim>> w(n), result(n);
    for (unsigned int k = 0; k < n; ++k)
      w[k] = DofSpace<dim>::get(u, element.nodes[k]);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        result[k] += element.complement(k, l) * w[l];
    return result;
  }



  template <int dim>
  double
  CmpmRegularizationTerm<dim>::value(const Vector<double> &u) const
  {
    double energy = 0.;
    for (const Element &element : elements)
      {
        const std::vector<Tensor<1, dim>> d = deviation(element, u);
        for (unsigned int k = 0; k < d.size(); ++k)
          energy += 0.5 * element.kappa[k] * d[k].norm_square();
      }
    return energy;
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::add_gradient(const Vector<double> &u,
                                            Vector<double> &gradient) const
  {
    // d/dw_l of 1/2 sum_k kappa_k |d_k|^2, d = (1 - P) w:
    // sum_k (1 - P)_kl kappa_k d_k
    for (const Element &element : elements)
      {
        const std::vector<Tensor<1, dim>> d = deviation(element, u);
        const unsigned int                n = element.nodes.size();
        for (unsigned int l = 0; l < n; ++l)
          {
            Tensor<1, dim> g;
            for (unsigned int k = 0; k < n; ++k)
              g += element.complement(k, l) * element.kappa[k] * d[k];
            for (unsigned int c = 0; c < dim; ++c)
              gradient[dim * element.nodes[l] + c] += g[c];
          }
      }
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::add_hessian(const Vector<double> &,
                                           SparseMatrix<double> &hessian,
                                           const HessianKind) const
  {
    // (1 - P)^T K (1 - P) per component: positive semi-definite as it is
    for (const Element &element : elements)
      {
        const unsigned int n = element.nodes.size();
        FullMatrix<double> KC(n, n), block(n, n);
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int l = 0; l < n; ++l)
            KC(k, l) = element.kappa[k] * element.complement(k, l);
        element.complement.Tmmult(block, KC);
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int l = 0; l < n; ++l)
            for (unsigned int c = 0; c < dim; ++c)
              hessian.add(dim * element.nodes[k] + c,
                          dim * element.nodes[l] + c,
                          block(k, l));
      }
  }



  template <int dim>
  unsigned int
  CmpmRegularizationTerm<dim>::n_elements() const
  {
    return elements.size();
  }



  template <int dim>
  double
  CmpmRegularizationTerm<dim>::largest_relative_weight() const
  {
    double largest = 0.;
    for (const Element &element : elements)
      largest = std::max(largest, element.relative_weight);
    return largest;
  }



  template class CmpmRegularizationTerm<2>;
  template class CmpmRegularizationTerm<3>;
} // namespace bfemp
