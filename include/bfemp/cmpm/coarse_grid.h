#ifndef bfemp_cmpm_coarse_grid_h
#define bfemp_cmpm_coarse_grid_h

#include <bfemp/cmpm/cmpm_parameters.h>
#include <bfemp/grid/lattice.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The geometry of cMPM (seed 002, Sections 3.3 and 5): the coarse mesh
   * D^H of elements of span H, the coarse nodes (a lattice of spacing
   * L = H, H/2 or H/3) and, inside every coarse element, the fine B-spline
   * patch.
   *
   * Fine patch. A uniform quadratic B-spline patch with n functions per
   * direction and no repeated knots (Remark 2) covers n - 2 knot spans of
   * size s = H / (n - 2), exactly the element. Fine node k (= the centre of
   * the support of B_k) sits at (k - 1/2) s in element coordinates, so the
   * outer two rows per side, k in {0, 1, n - 2, n - 1}, are the rows that the
   * neighbouring element's patch has too (Appendix A, eq. A.4): the boundary
   * fine nodes. The others, (n - 4)^dim of them, are the interior fine nodes
   * (the seed's "n_b = (n - 4)^2" counts these; see doc/cmpm.md).
   *
   * Coarse nodes. Lattice multi-indices j with position origin + (j - 1) L,
   * so that the ring of nodes outside the grid, which the quadratic B-spline
   * of the outermost elements needs, has non-negative indices. Element c
   * (multi-index) has its lower corner at lattice index l c + 1 (l = H / L);
   * its connectivity (Lemma 1) is the set of nodes at offsets o in
   * [-1, l + 1]^dim from that corner that its coarse-boundary map uses:
   * all of them for the B-spline element (r = 16 / 25 in 2D, 64 / 125 in
   * 3D), those on the element's own face lines/planes (some o_d in {0, l})
   * for the boundary B-spline element (12 / 16, 56 / 98), the 2^dim corners
   * for the multilinear one.
   *
   * Fine node numbering: k = k_0 + n k_1 (+ n^2 k_2); coarse local nodes in
   * the same direction-0-fastest order of their offsets.
   */
  template <int dim>
  class CoarseGrid
  {
  public:
    /** The 3^dim fine B-spline functions that are nonzero in a knot span. */
    static constexpr unsigned int n_stencil = dim == 2 ? 9 : 27;

    /**
     * The fine patch functions B_k(x) of eq. 7 (with h = s) and their
     * gradients grad B_k [1/m] that are nonzero at x (element coordinates),
     * the patch of eqs. 12-14. x in [0, H]^dim; on the element's upper
     * faces the last knot span is used, so both sides of a face can be
     * evaluated on it.
     */
    struct FineStencil
    {
      unsigned int   node[n_stencil];
      double         value[n_stencil];
      Tensor<1, dim> gradient[n_stencil];
    };

    /**
     * @p origin and @p n_elements describe the coarse mesh (the grid's lower
     * corner and its cells), @p element_size is H (`grid/cell size`).
     */
    CoarseGrid(const Point<dim>                    &origin,
               const double                         element_size,
               const std::array<unsigned int, dim> &n_elements,
               const CmpmParameters                &parameters);

    /** H [m]. */
    double
    element_size() const;

    /** s = H / (n - 2) [m]. */
    double
    knot_span() const;

    /** n. */
    unsigned int
    n_fine_1d() const;

    /** n^dim. */
    unsigned int
    n_fine() const;

    const CmpmParameters &
    parameters() const;

    /** Number of coarse elements per direction. */
    const std::array<unsigned int, dim> &
    n_elements() const;

    std::size_t
    n_elements_total() const;

    /** Element multi-index containing x (not range checked). */
    std::array<int, dim>
    element_of(const Point<dim> &x) const;

    /** Flat element index, direction 0 fastest. */
    std::size_t
    element_index(const std::array<int, dim> &element) const;

    std::array<int, dim>
    element_multi_index(std::size_t index) const;

    /** Lower corner of an element [m]. */
    Point<dim>
    element_origin(const std::array<int, dim> &element) const;

    /** The coarse node lattice (spacing L, shifted by one node). */
    const Lattice<dim> &
    node_lattice() const;

    /** r, the size of every element's connectivity. */
    unsigned int
    n_local_nodes() const;

    /** Offset o of local coarse node I from the element's corner node. */
    const std::array<int, dim> &
    local_node_offset(const unsigned int I) const;

    /** Flat lattice index of local coarse node I of @p element. */
    std::size_t
    global_node(const std::array<int, dim> &element,
                const unsigned int          I) const;

    /**
     * The unknowns of every element: its r local coarse nodes, then, with
     * `cmpm/interior modes` = body load, one node of its own (the
     * amplitudes of its interior modes, dim components like a coarse
     * node's). r or r + 1.
     */
    unsigned int
    n_element_unknowns() const;

    /** Whether the elements have interior modes (n_element_unknowns() > r). */
    bool
    has_interior_modes() const;

    /**
     * The index of unknown I of @p element among all unknown nodes: the
     * lattice index of local coarse node I for I < r, else
     * node_lattice().n_nodes + the element's flat index. GridState and the
     * DofSpace are sized by n_unknown_nodes().
     */
    std::size_t
    unknown_node(const std::array<int, dim> &element,
                 const unsigned int          I) const;

    /** node_lattice().n_nodes, plus one per element with interior modes. */
    std::size_t
    n_unknown_nodes() const;

    /**
     * Where an unknown node sits for the grid's walls and level sets: a
     * lattice node's position, or the centre of the element that owns an
     * interior-mode node (a wall whose layers cover the element holds its
     * interior as it holds its coarse nodes).
     */
    Point<dim>
    unknown_position(const std::size_t node) const;

    /** Fills @p stencil with the fine functions nonzero at @p x. */
    void
    fine_stencil(const Point<dim> &x, FineStencil &stencil) const;

    /** Fine node multi-index of fine node k. */
    std::array<unsigned int, dim>
    fine_multi_index(unsigned int k) const;

    /** Position of fine node k in element coordinates [m]. */
    Point<dim>
    fine_node_position(const unsigned int k) const;

    /** Whether fine node k is shared with a neighbouring element's patch. */
    bool
    is_boundary_fine_node(const unsigned int k) const;

    /** Index of fine node k among the interior fine nodes, or -1. */
    int
    interior_index(const unsigned int k) const;

    /** Fine node of interior index i. */
    unsigned int
    interior_fine_node(const unsigned int i) const;

    unsigned int
    n_interior_fine() const;

  private:
    Point<dim>                        origin;
    double                            H;
    double                            inverse_H;
    std::array<unsigned int, dim>     n_elements_per_direction;
    CmpmParameters                    prm;
    unsigned int                      l;
    double                            s;
    Lattice<dim>                      nodes;
    std::vector<std::array<int, dim>> local_offsets;
    std::vector<int>                  interior_of_fine;
    std::vector<unsigned int>         fine_of_interior;
  };
} // namespace bfemp

#endif
