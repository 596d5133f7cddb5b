#ifndef bfemp_fem_fem_body_h
#define bfemp_fem_fem_body_h

#include <bfemp/fem/fem_body_parameters.h>
#include <bfemp/fem/fem_mesh.h>
#include <bfemp/fem/prescribed_motion.h>
#include <bfemp/fem/simplex_element.h>
#include <bfemp/material/material.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * One linear-simplex FEM body (BFEMP Section 3.1): its mesh, material,
   * constant lumped nodal masses, the nodal positions x^n and velocities
   * v^n that the implicit integrator advances, and the nodes whose motion
   * is prescribed. FEM bodies are integrated implicitly only.
   */
  template <int dim>
  class FemBody
  {
  public:
    using Element = typename FemMesh<dim>::Element;

    /**
     * Builds the mesh and the elements; @p where names the prm subsection
     * for messages (a degenerate element is an InputError).
     */
    FemBody(const FemBodyParameters<dim> &parameters, const std::string &where);

    unsigned int
    n_nodes() const;

    const FemMesh<dim> &
    mesh() const;

    /** Node indices of each element, positively oriented. */
    const std::vector<Element> &
    element_nodes() const;

    /** The rest geometry of each element (B_e^-1, V_e, gradN). */
    const std::vector<SimplexElement<dim>> &
    elements() const;

    const Material<dim> &
    material() const;

    double
    density() const;

    /** Lumped nodal masses m_a = sum_e rho V_e / (dim + 1). */
    const std::vector<double> &
    masses() const;

    /** x^n of every node. */
    std::vector<Point<dim>> &
    positions();

    const std::vector<Point<dim>> &
    positions() const;

    /** v^n of every node. */
    std::vector<Tensor<1, dim>> &
    velocities();

    const std::vector<Tensor<1, dim>> &
    velocities() const;

    /** Nodes whose motion is prescribed (Dirichlet DoFs of the solve). */
    const std::vector<unsigned int> &
    prescribed_nodes() const;

    /**
     * Every node prescribed: the body is a kinematic boundary (BFEMP
     * Section 4.4) with no unknowns in the implicit solve.
     */
    bool
    is_kinematic() const;

    /** The motion that drives prescribed node @p node. */
    const PrescribedMotion<dim> &
    motion(const unsigned int node) const;

  private:
    const double                       rho;
    std::unique_ptr<FemMesh<dim>>      fem_mesh;
    std::unique_ptr<Material<dim>>     body_material;
    std::vector<SimplexElement<dim>>   simplex_elements;
    std::vector<double>                node_masses;
    std::vector<Point<dim>>            x;
    std::vector<Tensor<1, dim>>        v;
    std::vector<PrescribedMotion<dim>> prescribed_motions;
    std::vector<unsigned int>          prescribed;
    /** Index into prescribed_motions of every node (invalid: free). */
    std::vector<unsigned int> node_motion;
  };
} // namespace bfemp

#endif
