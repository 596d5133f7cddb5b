#include <bfemp/cmpm/coarse_grid.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace bfemp
{
  namespace
  {
    /** Whether the connectivity of an element of @p type holds offset o. */
    template <int dim>
    bool
    uses_offset(const CmpmParameters::ElementType type,
                const unsigned int                l,
                const std::array<int, dim>       &o)
    {
      switch (type)
        {
          case CmpmParameters::ElementType::bspline:
            return true;
          case CmpmParameters::ElementType::boundary_bspline:
            // on one of the element's face lines / planes
            for (unsigned int d = 0; d < dim; ++d)
              if (o[d] == 0 || o[d] == static_cast<int>(l))
                return true;
            return false;
          default:
            for (unsigned int d = 0; d < dim; ++d)
              if (o[d] < 0 || o[d] > 1)
                return false;
            return true;
        }
    }
  } // namespace



  template <int dim>
  CoarseGrid<dim>::CoarseGrid(const Point<dim>                    &origin,
                              const double                         element_size,
                              const std::array<unsigned int, dim> &n_elements,
                              const CmpmParameters                &parameters)
    : origin(origin)
    , H(element_size)
    , inverse_H(1. / element_size)
    , n_elements_per_direction(n_elements)
    , prm(parameters)
    , l(parameters.nodes_per_span)
    , s(element_size / (parameters.n_fine - 2.))
  {
    AssertThrow(parameters.n_fine >= 5,
                ExcMessage("cmpm: n >= 5 fine nodes per direction needed"));
    const double                  L = H / l;
    std::array<unsigned int, dim> n_node_cells;
    Point<dim>                    node_origin;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_node_cells[d] = l * n_elements[d] + 2;
        node_origin[d]  = origin[d] - L;
      }
    nodes = Lattice<dim>(node_origin, L, n_node_cells);

    // connectivity offsets in [-1, l + 1]^dim, direction 0 fastest
    const int    width = l + 3;
    unsigned int total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= width;
    for (unsigned int flat = 0; flat < total; ++flat)
      {
        std::array<int, dim> o;
        unsigned int         rest = flat;
        for (unsigned int d = 0; d < dim; ++d)
          {
            o[d] = static_cast<int>(rest % width) - 1;
            rest /= width;
          }
        if (uses_offset<dim>(parameters.element_type, l, o))
          local_offsets.push_back(o);
      }

    interior_of_fine.assign(n_fine(), -1);
    for (unsigned int k = 0; k < n_fine(); ++k)
      if (!is_boundary_fine_node(k))
        {
          interior_of_fine[k] = fine_of_interior.size();
          fine_of_interior.push_back(k);
        }
  }



  template <int dim>
  double
  CoarseGrid<dim>::element_size() const
  {
    return H;
  }



  template <int dim>
  double
  CoarseGrid<dim>::knot_span() const
  {
    return s;
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::n_fine_1d() const
  {
    return prm.n_fine;
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::n_fine() const
  {
    unsigned int total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= prm.n_fine;
    return total;
  }



  template <int dim>
  const CmpmParameters &
  CoarseGrid<dim>::parameters() const
  {
    return prm;
  }



  template <int dim>
  const std::array<unsigned int, dim> &
  CoarseGrid<dim>::n_elements() const
  {
    return n_elements_per_direction;
  }



  template <int dim>
  std::size_t
  CoarseGrid<dim>::n_elements_total() const
  {
    std::size_t total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= n_elements_per_direction[d];
    return total;
  }



  template <int dim>
  std::array<int, dim>
  CoarseGrid<dim>::element_of(const Point<dim> &x) const
  {
    std::array<int, dim> element;
    for (unsigned int d = 0; d < dim; ++d)
      {
        // the arithmetic of Lattice::cell_of, so that a particle's coarse
        // element is its ParticleSystem cell to the last bit
        const double xi        = (x[d] - origin[d]) * inverse_H;
        const int    truncated = static_cast<int>(xi);
        element[d]             = truncated - (xi < truncated);
      }
    return element;
  }



  template <int dim>
  std::size_t
  CoarseGrid<dim>::element_index(const std::array<int, dim> &element) const
  {
    std::size_t index = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Assert(element[d] >= 0 &&
                 element[d] < static_cast<int>(n_elements_per_direction[d]),
               ExcIndexRange(element[d], 0, n_elements_per_direction[d]));
        index += element[d] * stride;
        stride *= n_elements_per_direction[d];
      }
    return index;
  }



  template <int dim>
  std::array<int, dim>
  CoarseGrid<dim>::element_multi_index(std::size_t index) const
  {
    std::array<int, dim> element;
    for (unsigned int d = 0; d < dim; ++d)
      {
        element[d] = index % n_elements_per_direction[d];
        index /= n_elements_per_direction[d];
      }
    return element;
  }



  template <int dim>
  Point<dim>
  CoarseGrid<dim>::element_origin(const std::array<int, dim> &element) const
  {
    Point<dim> corner;
    for (unsigned int d = 0; d < dim; ++d)
      corner[d] = origin[d] + element[d] * H;
    return corner;
  }



  template <int dim>
  const Lattice<dim> &
  CoarseGrid<dim>::node_lattice() const
  {
    return nodes;
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::n_local_nodes() const
  {
    return local_offsets.size();
  }



  template <int dim>
  const std::array<int, dim> &
  CoarseGrid<dim>::local_node_offset(const unsigned int I) const
  {
    AssertIndexRange(I, local_offsets.size());
    return local_offsets[I];
  }



  template <int dim>
  std::size_t
  CoarseGrid<dim>::global_node(const std::array<int, dim> &element,
                               const unsigned int          I) const
  {
    std::array<int, dim> j;
    for (unsigned int d = 0; d < dim; ++d)
      j[d] = l * element[d] + 1 + local_offsets[I][d];
    return nodes.node_index(j);
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::n_element_unknowns() const
  {
    return n_local_nodes() + (has_interior_modes() ? 1 : 0);
  }



  template <int dim>
  bool
  CoarseGrid<dim>::has_interior_modes() const
  {
    return prm.interior_modes != CmpmParameters::InteriorModes::none;
  }



  template <int dim>
  std::size_t
  CoarseGrid<dim>::unknown_node(const std::array<int, dim> &element,
                                const unsigned int          I) const
  {
    AssertIndexRange(I, n_element_unknowns());
    return I < n_local_nodes() ? global_node(element, I)
                               : nodes.n_nodes + element_index(element);
  }



  template <int dim>
  std::size_t
  CoarseGrid<dim>::n_unknown_nodes() const
  {
    return nodes.n_nodes + (has_interior_modes() ? n_elements_total() : 0);
  }



  template <int dim>
  Point<dim>
  CoarseGrid<dim>::unknown_position(const std::size_t node) const
  {
    AssertIndexRange(node, n_unknown_nodes());
    if (node < nodes.n_nodes)
      return nodes.node_position(node);
    Point<dim> centre =
      element_origin(element_multi_index(node - nodes.n_nodes));
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] += 0.5 * H;
    return centre;
  }



  template <int dim>
  void
  CoarseGrid<dim>::fine_stencil(const Point<dim> &x, FineStencil &stencil) const
  {
    // 1D quadratic B-spline (eq. 8) of the nodes base, base + 1, base + 2 in
    // knot span `base`; fine node k sits at (k - 1/2) s.
    double       w[dim][3], dw[dim][3];
    unsigned int base[dim];
    const int    last_span = prm.n_fine - 3;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double xi = x[d] / s;
        const int    span =
          std::clamp(static_cast<int>(std::floor(xi)), 0, last_span);
        base[d]        = span;
        const double t = xi + 0.5 - span; // distance to node `span`
        const double a = 1.5 - t, b = t - 1., c = t - 0.5;
        w[d][0]  = 0.5 * a * a;
        w[d][1]  = 0.75 - b * b;
        w[d][2]  = 0.5 * c * c;
        dw[d][0] = -a / s;
        dw[d][1] = -2. * b / s;
        dw[d][2] = c / s;
      }
    const unsigned int n = prm.n_fine;
    unsigned int       q = 0;
    if constexpr (dim == 2)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int i = 0; i < 3; ++i, ++q)
          {
            stencil.node[q]        = base[0] + i + n * (base[1] + j);
            stencil.value[q]       = w[0][i] * w[1][j];
            stencil.gradient[q][0] = dw[0][i] * w[1][j];
            stencil.gradient[q][1] = w[0][i] * dw[1][j];
          }
    else
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int i = 0; i < 3; ++i, ++q)
            {
              stencil.node[q] =
                base[0] + i + n * (base[1] + j + n * (base[2] + m));
              stencil.value[q]       = w[0][i] * w[1][j] * w[2][m];
              stencil.gradient[q][0] = dw[0][i] * w[1][j] * w[2][m];
              stencil.gradient[q][1] = w[0][i] * dw[1][j] * w[2][m];
              stencil.gradient[q][2] = w[0][i] * w[1][j] * dw[2][m];
            }
  }



  template <int dim>
  std::array<unsigned int, dim>
  CoarseGrid<dim>::fine_multi_index(unsigned int k) const
  {
    std::array<unsigned int, dim> index;
    for (unsigned int d = 0; d < dim; ++d)
      {
        index[d] = k % prm.n_fine;
        k /= prm.n_fine;
      }
    return index;
  }



  template <int dim>
  Point<dim>
  CoarseGrid<dim>::fine_node_position(const unsigned int k) const
  {
    const auto index = fine_multi_index(k);
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = (index[d] - 0.5) * s;
    return x;
  }



  template <int dim>
  bool
  CoarseGrid<dim>::is_boundary_fine_node(const unsigned int k) const
  {
    const auto index = fine_multi_index(k);
    for (unsigned int d = 0; d < dim; ++d)
      if (index[d] < 2 || index[d] + 2 >= prm.n_fine)
        return true;
    return false;
  }



  template <int dim>
  int
  CoarseGrid<dim>::interior_index(const unsigned int k) const
  {
    return interior_of_fine[k];
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::interior_fine_node(const unsigned int i) const
  {
    return fine_of_interior[i];
  }



  template <int dim>
  unsigned int
  CoarseGrid<dim>::n_interior_fine() const
  {
    return fine_of_interior.size();
  }



  template class CoarseGrid<2>;
  template class CoarseGrid<3>;
} // namespace bfemp
