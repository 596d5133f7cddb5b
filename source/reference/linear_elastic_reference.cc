#include <bfemp/base/input_error.h>
#include <bfemp/reference/linear_elastic_reference.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <cmath>
#include <map>

namespace bfemp
{
  namespace
  {
    // Problems up to this size are solved directly: the factorization of a
    // 2D quadratic mesh of 10^5 unknowns takes seconds, while AMG with only
    // the translations as near-null space converges slowly on slender bent
    // bodies.
    constexpr types::global_dof_index max_direct_dofs = 300000;
  } // namespace



  template <int dim>
  LinearElasticReference<dim>::LinearElasticReference(
    const BodyParameters<dim> &body,
    const GridBoundaries<dim> &boundaries,
    const Lattice<dim>        &lattice,
    const Tensor<1, dim>      &gravity,
    const double               time,
    const double               cell_size,
    const unsigned int         degree,
    const std::string         &where)
    : body(body)
    , gravity(gravity)
    , time(time)
    , fe(FE_Q<dim>(degree), dim)
    , dof_handler(triangulation)
  {
    if (degree < 1 || degree > 4)
      throw InputError("the FE reference's degree is " +
                       std::to_string(degree) + "; allowed: 1 to 4");
    if (!body.initial_displacement.is_constant() ||
        body.initial_displacement.value(Point<dim>()).norm() > 0.)
      throw InputError(where + ", entry 'initial displacement': the FE "
                               "reference starts from the rest state; "
                               "allowed: none");
    // the linearization at F = I of each material: the exact law of linear
    // elastic materials, the small-strain limit of the others
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    for (const MaterialParameters *material : body.all_materials())
      {
        tangents.push_back(
          create_material<dim>(material->model, material->moduli())
            ->first_piola_kirchhoff_derivative(identity));
        densities.push_back(material->density);
      }
    make_mesh(cell_size, where);
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    make_constraints(boundaries, lattice, where);
  }



  template <int dim>
  void
  LinearElasticReference<dim>::make_mesh(const double       cell_size,
                                         const std::string &where)
  {
    const auto &primitives        = body.primitives;
    using Type                    = typename ShapePrimitive<dim>::Type;
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    if (primitives.size() != 1 || primitives[0].type != Type::box ||
        primitives[0].subtract ||
        (primitives[0].rotation - identity).norm() > 0.)
      throw InputError(where +
                       ": the FE reference meshes a box; allowed: one "
                       "'primitive 0' of type box, not rotated or subtracted "
                       "(regions of other materials may have any shape)");
    if (!(cell_size > 0.))
      throw InputError("the FE reference's cell size is " +
                       std::to_string(cell_size) + "; allowed: > 0");
    const Point<dim>         &lower = primitives[0].lower_corner;
    const Point<dim>         &upper = primitives[0].upper_corner;
    std::vector<unsigned int> repetitions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double cells = (upper[d] - lower[d]) / cell_size;
        repetitions[d]     = static_cast<unsigned int>(std::lround(cells));
        if (repetitions[d] == 0 || std::abs(cells - repetitions[d]) > 1e-6)
          throw InputError(
            where + ", 'primitive 0': the box's side " + std::to_string(d) +
            " (" + std::to_string(upper[d] - lower[d]) +
            " m) is not a multiple of the FE reference's cell size " +
            std::to_string(cell_size) + " m");
      }
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              repetitions,
                                              lower,
                                              upper,
                                              /*colorize=*/true);
  }



  template <int dim>
  void
  LinearElasticReference<dim>::make_constraints(
    const GridBoundaries<dim> &boundaries,
    const Lattice<dim>        &lattice,
    const std::string         &where)
  {
    // The walls act on points as on grid nodes (GridBoundaries), here on
    // the FE support points; each DoF keeps the row of the condition's
    // projector that belongs to its own displacement component.
    std::vector<types::global_dof_index> dofs;
    std::vector<unsigned int>            components;
    std::vector<Point<dim>>              points;
    for (unsigned int c = 0; c < dim; ++c)
      {
        std::map<types::global_dof_index, Point<dim>> support_points;
        DoFTools::map_dofs_to_support_points(mapping,
                                             dof_handler,
                                             support_points,
                                             fe.component_mask(
                                               FEValuesExtractors::Scalar(c)));
        for (const auto &[dof, point] : support_points)
          {
            dofs.push_back(dof);
            components.push_back(c);
            points.push_back(point);
          }
      }
    const std::vector<Tensor<1, dim>> at_rest(points.size());
    constraints.reinit(locally_relevant_dofs);
    for (const auto &constraint :
         boundaries.implicit_constraints(lattice, points, at_rest, time))
      {
        if (constraint.obstacle_velocity.norm() > 0.)
          throw InputError("subsection 'boundaries': the FE reference of " +
                           where +
                           " is static; allowed: walls and level sets at "
                           "rest");
        const unsigned int    c    = components[constraint.node];
        const Tensor<2, dim> &free = constraint.free_projector;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != c && std::abs(free[c][d]) > 1e-12)
            throw InputError(
              "subsection 'boundaries': a level set holds the FE reference "
              "of " +
              where +
              " along an oblique normal; allowed: walls and level sets "
              "whose normals are along the axes where they touch the body");
        const types::global_dof_index dof = dofs[constraint.node];
        if (std::abs(free[c][c]) < 1e-12 && !constraints.is_constrained(dof))
          constraints.add_line(dof);
      }
    constraints.close();
    n_constrained = constraints.n_constraints();
  }



  template <int dim>
  void
  LinearElasticReference<dim>::assemble()
  {
    // Trilinos' own pattern, filled directly: a DynamicSparsityPattern
    // next to the matrix would double the memory of a 3D quadratic mesh
    // (about 190 entries per row).
    TrilinosWrappers::SparsityPattern pattern(locally_owned_dofs,
                                              locally_owned_dofs,
                                              locally_relevant_dofs,
                                              MPI_COMM_WORLD);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    pattern.compress();
    matrix.reinit(pattern);
    rhs.reinit(locally_owned_dofs, MPI_COMM_WORLD);

    const QGauss<dim>                    quadrature(fe.degree + 1);
    const QGauss<dim - 1>                face_quadrature(fe.degree + 1);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_values |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> indices(n);
    std::vector<unsigned int>            component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    // C : (e_c (x) g) for each shape function: the column of the stiffness
    // that the function's gradient e_c (x) g produces
    std::vector<Tensor<2, dim>> stress_of(n);

    // the surface loads at time T: one face of the box each (boundary id
    // 2 direction + upper, as colorized)
    std::map<types::boundary_id, Tensor<1, dim>> face_traction;
    for (const SurfaceLoad<dim> &load : body.surface_loads)
      face_traction[2 * load.direction + (load.upper ? 1 : 0)] +=
        load.traction(time);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_matrix = 0.;
          cell_rhs    = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const unsigned int m =
                body.material_index_at(fe_values.quadrature_point(q));
              const Tensor<4, dim> &C   = tangents[m];
              const double          JxW = fe_values.JxW(q);
              for (unsigned int j = 0; j < n; ++j)
                {
                  const Tensor<1, dim> g =
                    fe_values.shape_grad_component(j, q, component[j]);
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      {
                        double sum = 0.;
                        for (unsigned int l = 0; l < dim; ++l)
                          sum += C[a][b][component[j]][l] * g[l];
                        stress_of[j][a][b] = sum;
                      }
                }
              // grad v_i : C : grad v_j = g_i . (C : grad v_j)[c_i]
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Tensor<1, dim> g =
                    fe_values.shape_grad_component(i, q, component[i]);
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) += g * stress_of[j][component[i]] * JxW;
                  cell_rhs(i) +=
                    densities[m] * gravity[component[i]] *
                    fe_values.shape_value_component(i, q, component[i]) * JxW;
                }
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto load =
                  face_traction.find(cell->face(f)->boundary_id());
                if (load == face_traction.end())
                  continue;
                fe_face_values.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  for (unsigned int i = 0; i < n; ++i)
                    cell_rhs(i) +=
                      load->second[component[i]] *
                      fe_face_values.shape_value_component(i, q, component[i]) *
                      fe_face_values.JxW(q);
              }
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_rhs,
                                                 indices,
                                                 matrix,
                                                 rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }



  template <int dim>
  typename LinearElasticReference<dim>::Statistics
  LinearElasticReference<dim>::solve(const Solver solver)
  {
    Statistics statistics;
    statistics.n_cells       = triangulation.n_global_active_cells();
    statistics.n_dofs        = dof_handler.n_dofs();
    statistics.n_constrained = n_constrained;

    Timer timer;
    assemble();
    statistics.assembly_seconds = timer.wall_time();

    timer.restart();
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, MPI_COMM_WORLD);
    if (solver == Solver::direct || (solver == Solver::automatic &&
                                     dof_handler.n_dofs() <= max_direct_dofs))
      {
        SolverControl                  control(1, 0., false, false);
        TrilinosWrappers::SolverDirect direct(control);
        direct.solve(matrix, owned, rhs);
        statistics.solver = "sparse direct (Amesos KLU)";
      }
    else
      {
        std::vector<std::vector<bool>> constant_modes;
        DoFTools::extract_constant_modes(dof_handler,
                                         ComponentMask(dim, true),
                                         constant_modes);
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = true;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        data.constant_modes        = constant_modes;
        TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(matrix, data);
        SolverControl control(20000, 1e-10 * rhs.l2_norm(), false, false);
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(matrix, owned, rhs, amg);
        statistics.iterations = control.last_step();
        statistics.solver     = "CG with ML AMG";
      }
    constraints.distribute(owned);
    statistics.solve_seconds = timer.wall_time();
    solution.reinit(locally_owned_dofs, locally_relevant_dofs, MPI_COMM_WORLD);
    solution                    = owned;
    statistics.max_displacement = owned.linfty_norm();
    return statistics;
  }



  template <int dim>
  void
  LinearElasticReference<dim>::locate(const std::vector<Point<dim>> &X)
  {
    if (X == located_points)
      return;
    evaluation.reinit(X, triangulation, mapping);
    if (!evaluation.all_points_found())
      throw InputError("the FE reference: a particle's rest position lies "
                       "outside the body's box");
    located_points = X;
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  LinearElasticReference<dim>::displacements(const std::vector<Point<dim>> &X)
  {
    locate(X);
    // a point on a face shared by cells gets their average; the field is
    // continuous, so they agree
    return VectorTools::point_values<dim>(evaluation, dof_handler, solution);
  }



  template <int dim>
  std::vector<Tensor<2, dim>>
  LinearElasticReference<dim>::displacement_gradients(
    const std::vector<Point<dim>> &X)
  {
    locate(X);
    // the gradient jumps across faces where the material does; a point on
    // such a face gets the average of the cells' gradients
    return VectorTools::point_gradients<dim>(evaluation, dof_handler, solution);
  }



  template class LinearElasticReference<2>;
  template class LinearElasticReference<3>;
} // namespace bfemp
