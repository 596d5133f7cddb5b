#include <bfemp/cmpm/cmpm_regularization_term.h>
#include <bfemp/solver/node_blocks.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>

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
    std::vector<double> kappa(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        kappa[k] = weight * std::max(0., mean - masses[k]);
        element.relative_weight =
          std::max(element.relative_weight, kappa[k] / (weight * mean));
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
    FullMatrix<double> complement(n, n), kappa_complement(n, n);
    fit.mTmult(complement, WA);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        {
          complement(k, l)       = (k == l ? 1. : 0.) - complement(k, l);
          kappa_complement(k, l) = kappa[k] * complement(k, l);
        }
    // E = 1/2 u^T (1 - P)^T K (1 - P) u per component: the term is quadratic,
    // so its matrix is formed once per step and serves value, gradient and
    // Hessian
    element.stiffness.reinit(n, n);
    complement.Tmmult(element.stiffness, kappa_complement);
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
  CmpmRegularizationTerm<dim>::force(const Element        &element,
                                     const Vector<double> &u) const
  {
    const unsigned int          n = element.nodes.size();
    std::vector<Tensor<1, dim>> result(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        result[k] +=
          element.stiffness(k, l) * DofSpace<dim>::get(u, element.nodes[l]);
    return result;
  }



  template <int dim>
  double
  CmpmRegularizationTerm<dim>::value(const Vector<double> &u) const
  {
    double energy = 0.;
    for (const Element &element : elements)
      {
        const std::vector<Tensor<1, dim>> f = force(element, u);
        for (unsigned int k = 0; k < f.size(); ++k)
          energy += 0.5 * f[k] * DofSpace<dim>::get(u, element.nodes[k]);
      }
    return energy;
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::add_gradient(const Vector<double> &u,
                                            Vector<double> &gradient) const
  {
    for (const Element &element : elements)
      {
        const std::vector<Tensor<1, dim>> f = force(element, u);
        for (unsigned int k = 0; k < f.size(); ++k)
          for (unsigned int c = 0; c < dim; ++c)
            gradient[dim * element.nodes[k] + c] += f[k][c];
      }
  }



  template <int dim>
  void
  CmpmRegularizationTerm<dim>::add_hessian(const Vector<double> &,
                                           SparseMatrix<double> &hessian,
                                           const HessianKind) const
  {
    // the matrix of build_element(), per component: PSD as it is. Its
    // blocks s_kl I go in through add_node_blocks (one walk per row, the
    // nodes in ascending order) instead of one sparsity look-up per entry.
    thread_local std::vector<unsigned int> order;
    thread_local std::vector<unsigned int> sorted;
    for (const Element &element : elements)
      {
        const unsigned int n = element.nodes.size();
        order.resize(n);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(),
                  order.end(),
                  [&](unsigned int k, unsigned int l) {
                    return element.nodes[k] < element.nodes[l];
                  });
        sorted.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          sorted[i] = element.nodes[order[i]];
        add_node_blocks<dim>(
          sorted,
          [&](const unsigned int i, const unsigned int j) {
            Tensor<2, dim> block;
            for (unsigned int c = 0; c < dim; ++c)
              block[c][c] = element.stiffness(order[i], order[j]);
            return block;
          },
          hessian);
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
