#ifndef bfemp_reference_linear_elastic_reference_h
#define bfemp_reference_linear_elastic_reference_h

#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/grid/lattice.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/body_parameters.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The static linear-elastic solution of one MPM body of a scene by
   * hexahedral finite elements of degree p (FE_Q(p)^dim on a uniform mesh
   * of the body's box): the benchmark of seed 002 Section 8.2 ("hexahedral
   * FEM (polynomial degree p = 2) using fine mesh D^h"), against which cMPM
   * and B-spline MPM on the same scene are measured by eq. (38).
   *
   * The problem is the one the scene poses, linearized at the rest state:
   * find u with u = 0 (or u.n = 0) where the scene's walls hold the grid,
   *   int_Omega grad v : C(X) : grad u dX
   *     = int_Omega rho(X) g . v dX + sum_faces int_face t(T) . v dA,
   * where C(X) = dP/dF(I) of the material the body has at X (its
   * 'material region's, looked up at every quadrature point, as the
   * particles look them up at their positions), g the gravity and t the
   * body's surface loads at the time T. For 'linear elastic' materials this
   * is the exact static equilibrium that a long backward Euler step of the
   * scene approaches as the inertia term M / dt^2 vanishes.
   *
   * Boundary conditions come from the scene's walls at the FE support
   * points: a point inside a sticky wall's layers is fixed, one inside a
   * slip wall's layers keeps only its tangential freedom (separable walls
   * hold nothing in a static problem). Walls that move or level sets with
   * oblique normals are refused.
   *
   * The code loops over locally owned cells and solves with Trilinos, so
   * that a parallel::distributed::Triangulation can replace the serial one.
   */
  template <int dim>
  class LinearElasticReference
  {
  public:
    /** What the solve cost and found. */
    struct Statistics
    {
      unsigned int            n_cells       = 0;
      types::global_dof_index n_dofs        = 0;
      unsigned int            n_constrained = 0;
      std::string             solver;
      unsigned int            iterations       = 0;
      double                  assembly_seconds = 0.;
      double                  solve_seconds    = 0.;
      double                  max_displacement = 0.;
    };

    /**
     * Meshes @p body (which must be one axis-aligned box) with cubes of edge
     * @p cell_size (the box's sides must be multiples of it), and sets up
     * FE_Q(@p degree)^dim, the constraints of @p boundaries on @p lattice and
     * the loads at time @p time. @p where names the body's prm subsection
     * for messages. Throws InputError if the scene is not such a problem.
     */
    LinearElasticReference(const BodyParameters<dim> &body,
                           const GridBoundaries<dim> &boundaries,
                           const Lattice<dim>        &lattice,
                           const Tensor<1, dim>      &gravity,
                           const double               time,
                           const double               cell_size,
                           const unsigned int         degree,
                           const std::string         &where);

    /** How solve() solves the linear system. */
    enum class Solver
    {
      /** direct up to 300,000 unknowns, iterative above */
      automatic,
      /** sparse direct (Amesos KLU) */
      direct,
      /** CG with ML algebraic multigrid (one near-null-space vector per
       *  displacement component) to a relative residual of 1e-10 */
      iterative
    };

    /** Assembles and solves with @p solver. */
    Statistics
    solve(const Solver solver = Solver::automatic);

    /** u(X) at the rest positions @p X (all inside the box). */
    std::vector<Tensor<1, dim>>
    displacements(const std::vector<Point<dim>> &X);

    /** grad u(X) (index [i][j] = du_i / dX_j) at the rest positions @p X. */
    std::vector<Tensor<2, dim>>
    displacement_gradients(const std::vector<Point<dim>> &X);

  private:
    /** The mesh of the body's box, colorized (face 2 d + upper). */
    void
    make_mesh(const double cell_size, const std::string &where);

    /** u = 0 (components) at the support points the walls hold. */
    void
    make_constraints(const GridBoundaries<dim> &boundaries,
                     const Lattice<dim>        &lattice,
                     const std::string         &where);

    /** The stiffness matrix and load vector of the weak form above. */
    void
    assemble();

    /** Points @p X into the mesh for the evaluations (once per set). */
    void
    locate(const std::vector<Point<dim>> &X);

    const BodyParameters<dim> &body;
    Tensor<1, dim>             gravity;
    double                     time;
    /** C = dP/dF(I) and density of each of the body's materials. */
    std::vector<Tensor<4, dim>> tangents;
    std::vector<double>         densities;

    Triangulation<dim>        triangulation;
    FESystem<dim>             fe;
    MappingQ1<dim>            mapping;
    DoFHandler<dim>           dof_handler;
    IndexSet                  locally_owned_dofs;
    IndexSet                  locally_relevant_dofs;
    AffineConstraints<double> constraints;
    unsigned int              n_constrained = 0;

    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs;
    /** The solution with ghost entries, for the point evaluations. */
    TrilinosWrappers::MPI::Vector solution;

    Utilities::MPI::RemotePointEvaluation<dim> evaluation;
    std::vector<Point<dim>>                    located_points;
  };
} // namespace bfemp

#endif
