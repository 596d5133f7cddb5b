#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/fem/fem_body.h>

namespace bfemp
{
  template <int dim>
  FemBody<dim>::FemBody(const FemBodyParameters<dim> &parameters,
                        const std::string            &where)
    : rho(parameters.material.density)
    , fem_mesh(
        std::make_unique<FemMesh<dim>>(parameters.mesh,
                                       parameter_tools::nested(where, "mesh")))
    , body_material(create_material<dim>(parameters.material.model,
                                         parameters.material.moduli()))
    , node_masses(fem_mesh->lumped_masses(rho))
    , x(fem_mesh->rest_positions())
    , v(fem_mesh->n_nodes(), parameters.initial_velocity)
    , node_motion(fem_mesh->n_nodes(), numbers::invalid_unsigned_int)
  {
    for (const auto &motion : parameters.motions)
      prescribed_motions.emplace_back(motion);
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
            throw InputError(parameter_tools::nested(where, "mesh") +
                             ": element " +
                             std::to_string(simplex_elements.size()) +
                             " is degenerate or inverted (" + e.what() +
                             "); FEM meshes need elements of positive volume");
          }
      }
    // Each selection drives its nodes; a later one wins for a node in
    // several (a clamp and a pull that share a corner).
    for (unsigned int k = 0; k < prescribed_motions.size(); ++k)
      {
        const PrescribedMotion<dim> &motion = prescribed_motions[k];
        const std::string            name   = where + ", subsection '" +
                                 FemBodyParameters<dim>::motion_subsection(k) +
                                 "'";
        if (!motion.active())
          {
            if (k > 0)
              throw InputError(name +
                               ", entry 'nodes' = none: every prescribed "
                               "motion after the first needs a node "
                               "selection (all, box or boundary id)");
            continue;
          }
        bool any = false;
        for (unsigned int a = 0; a < fem_mesh->n_nodes(); ++a)
          if (motion.selects(fem_mesh->rest_position(a),
                             fem_mesh->node_boundary_ids(a)))
            {
              node_motion[a] = k;
              any            = true;
            }
        if (!any)
          throw InputError(name +
                           ": the node selection ('nodes' and its box or "
                           "boundary id) contains no node of the mesh");
      }
    for (unsigned int a = 0; a < fem_mesh->n_nodes(); ++a)
      if (node_motion[a] != numbers::invalid_unsigned_int)
        {
          prescribed.push_back(a);
          // Prescribed nodes start where the motion puts them at t = 0 with
          // its velocity, so the first step does not jump.
          x[a] = motion(a).position(fem_mesh->rest_position(a), 0.);
          v[a] = motion(a).velocity(fem_mesh->rest_position(a), 0.);
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
  FemBody<dim>::motion(const unsigned int node) const
  {
    Assert(node_motion[node] != numbers::invalid_unsigned_int,
           ExcMessage("motion() of a node that is not prescribed"));
    return prescribed_motions[node_motion[node]];
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
