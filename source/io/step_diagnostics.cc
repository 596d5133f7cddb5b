#include <bfemp/io/step_diagnostics.h>

#include <deal.II/base/tensor.h>

#include <cmath>

namespace bfemp
{
  template <int dim>
  StepDiagnostics<dim> &
  StepDiagnostics<dim>::operator+=(const StepDiagnostics &other)
  {
    mass += other.mass;
    kinetic_energy += other.kinetic_energy;
    elastic_energy += other.elastic_energy;
    gravitational_energy += other.gravitational_energy;
    affine_kinetic_energy += other.affine_kinetic_energy;
    linear_momentum += other.linear_momentum;
    first_moment += other.first_moment;
    angular_momentum += other.angular_momentum;
    min_J     = std::min(min_J, other.min_J);
    max_speed = std::max(max_speed, other.max_speed);
    finite    = finite && other.finite;
    particles_in_level_sets += other.particles_in_level_sets;
    return *this;
  }



  template <int dim>
  double
  StepDiagnostics<dim>::total_energy() const
  {
    return kinetic_energy + elastic_energy + gravitational_energy;
  }



  template <int dim>
  Point<dim>
  StepDiagnostics<dim>::center_of_mass() const
  {
    return mass > 0. ? Point<dim>(first_moment / mass) : Point<dim>();
  }



  template <int dim>
  Tensor<1, dim>
  StepDiagnostics<dim>::center_of_mass_velocity() const
  {
    return mass > 0. ? linear_momentum / mass : Tensor<1, dim>();
  }



  namespace
  {
    /** x cross m v plus the affine part m eps_abc B_cb, B = C D. */
    template <int dim>
    Tensor<1, 3>
    particle_angular_momentum(const double          m,
                              const Point<dim>     &x,
                              const Tensor<1, dim> &v,
                              const Tensor<2, dim> &B)
    {
      Tensor<1, 3> L;
      if constexpr (dim == 2)
        L[2] = m * (x[0] * v[1] - x[1] * v[0] + B[1][0] - B[0][1]);
      else
        {
          const Tensor<1, 3> xv = cross_product_3d(Tensor<1, 3>(x), v);
          for (unsigned int a = 0; a < 3; ++a)
            {
              const unsigned int b = (a + 1) % 3, c = (a + 2) % 3;
              L[a] = m * (xv[a] + B[c][b] - B[b][c]);
            }
        }
      return L;
    }
  } // namespace



  template <int dim>
  StepDiagnostics<dim>
  StepDiagnostics<dim>::measure(
    const ParticleSystem<dim>                         &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const ParticleGridTransfer<dim>                   &transfer,
    const Tensor<1, dim>                              &gravity,
    const unsigned int                                 body)
  {
    using Layout = ParticleLayout<dim>;
    const bool apic =
      transfer.parameters().scheme == TransferParameters::Scheme::apic;
    return particles.template sum<StepDiagnostics<dim>>(
      [&](const auto &particle) {
        const auto p = particle.get_properties();
        if (body != numbers::invalid_unsigned_int &&
            static_cast<unsigned int>(p[Layout::body_id]) != body)
          return StepDiagnostics<dim>();
        const Point<dim>     x = particle.get_location();
        const double         m = p[Layout::mass];
        const Tensor<1, dim> v = Layout::get_vector(p, Layout::velocity);
        const Tensor<2, dim> F =
          Layout::get_tensor(p, Layout::deformation_gradient);
        const Tensor<2, dim> B =
          Layout::get_tensor(p, Layout::affine_velocity) *
          transfer.apic_inertia(x);
        const auto &material =
          *materials[static_cast<unsigned int>(p[Layout::material_id])];

        StepDiagnostics<dim> d;
        d.mass           = m;
        d.kinetic_energy = 0.5 * m * v.norm_square();
        if (apic)
          d.affine_kinetic_energy =
            0.5 * m *
            scalar_product(Layout::get_tensor(p, Layout::affine_velocity), B);
        d.elastic_energy = p[Layout::rest_volume] * material.energy_density(F);
        d.gravitational_energy = -m * (gravity * x);
        d.linear_momentum      = m * v;
        d.first_moment         = m * x;
        d.angular_momentum     = particle_angular_momentum(m, x, v, B);
        d.min_J                = determinant(F);
        d.max_speed            = v.norm();
        d.finite = std::isfinite(d.kinetic_energy) && std::isfinite(d.min_J) &&
                   std::isfinite(x.norm_square()) &&
                   std::isfinite(F.norm_square());
        return d;
      });
  }



  namespace
  {
    struct MaximumSpeed
    {
      double value = 0.;

      MaximumSpeed &
      operator+=(const MaximumSpeed &other)
      {
        value = std::max(value, other.value);
        return *this;
      }
    };
  } // namespace



  template <int dim>
  double
  StepDiagnostics<dim>::measure_max_speed(const ParticleSystem<dim> &particles)
  {
    using Layout = ParticleLayout<dim>;
    return particles
      .template sum<MaximumSpeed>([](const auto &particle) {
        return MaximumSpeed{
          Layout::get_vector(particle.get_properties(), Layout::velocity)
            .norm()};
      })
      .value;
  }



  template <int dim>
  StepDiagnostics<dim>
  StepDiagnostics<dim>::measure(
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
    const Tensor<1, dim>                             &gravity)
  {
    StepDiagnostics d;
    for (const auto &body : bodies)
      d += measure(*body, gravity);
    return d;
  }



  template <int dim>
  StepDiagnostics<dim>
  StepDiagnostics<dim>::measure(const FemBody<dim>   &body,
                                const Tensor<1, dim> &gravity)
  {
    StepDiagnostics d;
    {
      for (unsigned int a = 0; a < body.n_nodes(); ++a)
        {
          const double          m = body.masses()[a];
          const Point<dim>     &x = body.positions()[a];
          const Tensor<1, dim> &v = body.velocities()[a];
          d.mass += m;
          d.first_moment += m * x;
          d.kinetic_energy += 0.5 * m * v.norm_square();
          d.gravitational_energy -= m * (gravity * x);
          d.linear_momentum += m * v;
          d.angular_momentum +=
            particle_angular_momentum<dim>(m, x, v, Tensor<2, dim>());
          d.max_speed = std::max(d.max_speed, v.norm());
          d.finite    = d.finite && std::isfinite(x.norm_square()) &&
                     std::isfinite(v.norm_square());
        }
      for (unsigned int e = 0; e < body.elements().size(); ++e)
        {
          typename SimplexElement<dim>::NodePositions x;
          for (unsigned int a = 0; a <= dim; ++a)
            x[a] = body.positions()[body.element_nodes()[e][a]];
          const auto  &element = body.elements()[e];
          const double J       = determinant(element.deformation_gradient(x));
          d.min_J              = std::min(d.min_J, J);
          if (J > 0.)
            d.elastic_energy += element.energy(x, body.material());
        }
    }
    return d;
  }



  template <int dim>
  double
  StepDiagnostics<dim>::measure_max_speed(
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies)
  {
    double max_speed = 0.;
    for (const auto &body : bodies)
      for (const Tensor<1, dim> &v : body->velocities())
        max_speed = std::max(max_speed, v.norm());
    return max_speed;
  }



  template struct StepDiagnostics<2>;
  template struct StepDiagnostics<3>;
} // namespace bfemp
