#include <bfemp/base/input_error.h>
#include <bfemp/fem/fem_body.h>

namespace bfemp
{
  template <int dim>
  FemBody<dim>::FemBody(const FemBodyParameters<dim> &parameters,
                        const std::string            &where)
    : rho(parameters.material.density)
    , fem_mesh(std::make_unique<FemMesh<dim>>(parameters.mesh, where + "/mesh"))
    , body_material(create_material<dim>(parameters.material.model,
                                         parameters.material.moduli()))
    , node_masses(fem_mesh->lumped_masses(rho))
    , x(fem_mesh->rest_positions())
    , v(fem_mesh->n_nodes(), parameters.initial_velocity)
    , prescribed_motion(parameters.motion)
  {
    for (const auto &nodes : fem_mesh->elements())
      {
        typename SimplexElement<dim>::NodePositions rest;
        for (unsigned int a = 0; a <= dim; ++a)
          rest[a] = fem_mesh->rest_position(nodes[a]);
        try
          {
            simplex_elements.emplace_back(rest);
          }
        catch (const std::exception &e)
          {
            throw InputError(where + "/mesh: element " +
                             std::to_string(simplex_elements.size()) +
                             " is degenerate or inverted (" + e.what() +
                             "); FEM meshes need elements of positive volume");
          }
      }
    if (prescribed_motion.active())
      {
        for (unsigned int a = 0; a < fem_mesh->n_nodes(); ++a)
          if (prescribed_motion.selects(fem_mesh->rest_position(a),
                                        fem_mesh->node_boundary_ids(a)))
            prescribed.push_back(a);
        if (prescribed.empty())
          throw InputError(where +
                           "/prescribed motion: the node selection "
                           "('nodes' and its box or boundary id) contains "
                           "no node of the mesh");
        // Prescribed nodes start where the motion puts them at t = 0 with
        // its velocity, so the first step does not jump.
        for (const unsigned int a : prescribed)
          {
            x[a] = prescribed_motion.position(fem_mesh->rest_position(a), 0.);
            v[a] = prescribed_motion.velocity(fem_mesh->rest_position(a), 0.);
          }
      }
  }



  template <int dim>
  unsigned int
  FemBody<dim>::n_nodes() const
  {
    return fem_mesh->n_nodes();
  }



  template <int dim>
  const FemMesh<dim> &
  FemBody<dim>::mesh() const
  {
    return *fem_mesh;
  }



  template <int dim>
  const std::vector<typename FemBody<dim>::Element> &
  FemBody<dim>::element_nodes() const
  {
    return fem_mesh->elements();
  }



  template <int dim>
  const std::vector<SimplexElement<dim>> &
  FemBody<dim>::elements() const
  {
    return simplex_elements;
  }



  template <int dim>
  const Material<dim> &
  FemBody<dim>::material() const
  {
    return *body_material;
  }



  template <int dim>
  double
  FemBody<dim>::density() const
  {
    return rho;
  }



  template <int dim>
  const std::vector<double> &
  FemBody<dim>::masses() const
  {
    return node_masses;
  }



  template <int dim>
  std::vector<Point<dim>> &
  FemBody<dim>::positions()
  {
    return x;
  }



  template <int dim>
  const std::vector<Point<dim>> &
  FemBody<dim>::positions() const
  {
    return x;
  }



  template <int dim>
  std::vector<Tensor<1, dim>> &
  FemBody<dim>::velocities()
  {
    return v;
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  FemBody<dim>::velocities() const
  {
    return v;
  }



  template <int dim>
  const std::vector<unsigned int> &
  FemBody<dim>::prescribed_nodes() const
  {
    return prescribed;
  }



  template <int dim>
  const PrescribedMotion<dim> &
  FemBody<dim>::motion() const
  {
    return prescribed_motion;
  }



  template class FemBody<2>;
  template <int dim>
  bool
  FemBody<dim>::is_kinematic() const
  {
    return prescribed.size() == n_nodes();
  }



  template class FemBody<3>;
} // namespace bfemp
