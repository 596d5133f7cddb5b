#ifndef bfemp_particles_particle_system_h
#define bfemp_particles_particle_system_h

#include <bfemp/grid/background_grid.h>
#include <bfemp/particles/particle_layout.h>

#include <deal.II/base/parallel.h>
#include <deal.II/particles/particle_handler.h>

#include <vector>

namespace bfemp
{
  /**
   * The MPM particles, stored in a deal.II Particles::ParticleHandler on the
   * background grid with the property layout of ParticleLayout, and the
   * thread-parallel loops over them.
   *
   * Particle loops run over stripes of grid cells (stripe_width cells wide in
   * direction 0). A particle's kernel stencil reaches at most one node below
   * and two above its cell, so stripes two apart never write the same node:
   * scatters (P2G) run all even stripes in parallel, then all odd ones. No
   * locks, no per-thread copies of the grid, and sums are formed in a fixed
   * order, so results do not depend on the number of threads.
   */
  template <int dim>
  class ParticleSystem
  {
  public:
    using Layout   = ParticleLayout<dim>;
    using Accessor = Particles::ParticleAccessor<dim>;

    static constexpr unsigned int stripe_width = 3;

    explicit ParticleSystem(const BackgroundGrid<dim> &grid);

    /**
     * Every particle's id, location and properties, in the order of the
     * particle loops (what a checkpoint saves).
     */
    struct Records
    {
      std::vector<types::particle_index> ids;
      std::vector<Point<dim>>            locations;
      /** n_properties values per particle, particle after particle. */
      std::vector<double> properties;
    };

    /** Adds one particle at x with all its properties. */
    void
    insert(const Point<dim> &x, const ArrayView<const double> &properties);

    /** Call after the last insert(): sets up counts and stripes. */
    void
    finish_insertion();

    types::particle_index
    n_particles() const;

    Particles::ParticleHandler<dim> &
    handler();

    const Particles::ParticleHandler<dim> &
    handler() const;

    /** All particles' data in loop order. */
    Records
    gather_in_loop_order() const;

    /**
     * Replaces all particles by @p records, inserted in their order and
     * with their ids; loops then visit them in that order, so a state saved
     * by gather_in_loop_order() continues bit for bit. Throws
     * SimulationError if a particle's kernel stencil is outside the grid.
     */
    void
    replace_all(const Records &records);

    /**
     * After the particles moved: puts each in the cell that now contains it
     * and updates its reference location. Throws SimulationError naming the
     * particle if its kernel stencil left the grid.
     */
    void
    update_cells();

    /** f(particle) for all particles; race-free for scatters to the grid. */
    template <typename Function>
    void
    for_each_scattering(const Function &f);

    /**
     * f(particles) for the particles of each non-empty cell (a range of
     * particle accessors); race-free for scatters to the grid, like
     * for_each_scattering(). For work that is cheaper per cell than per
     * particle, e.g. adding the particles' Hessian blocks to a sparse matrix
     * once per cell.
     */
    template <typename Function>
    void
    for_each_cell_scattering(const Function &f);

    /** f(particles of a cell) for all non-empty cells, each cell on its
     *  own (no scatters to shared nodes). */
    template <typename Function>
    void
    for_each_cell(const Function &f);

    /** f(particle) for all particles, each particle on its own. */
    template <typename Function>
    void
    for_each(const Function &f);

    /**
     * Sum over all particles of f(particle), formed stripe by stripe in a
     * fixed order (deterministic for any thread count).
     */
    template <typename Result, typename Function>
    Result
    sum(const Function &f) const;

    /**
     * Sum over the non-empty cells of f(particles of the cell), formed
     * stripe by stripe in a fixed order like sum(): for sums whose
     * particles share work per cell (cMPM's per-element fine field).
     */
    template <typename Result, typename Function>
    Result
    sum_over_cells(const Function &f) const;

  private:
    /** f(particle) for the particles of every step-th stripe from first. */
    template <typename Function>
    void
    for_stripes(const unsigned int first,
                const unsigned int step,
                const Function    &f);

    /** f(particles of a cell) for the cells of every step-th stripe. */
    template <typename Function>
    void
    for_cells_of_stripes(const unsigned int first,
                         const unsigned int step,
                         const Function    &f);

    /** Sum over the stripes of add_cell(partial, particles of a cell),
     *  formed stripe by stripe in a fixed order. */
    template <typename Result, typename AddCell>
    Result
    sum_by_stripes(const AddCell &add_cell) const;

    void
    rebuild_stripes();

    /** Lists the non-empty cells of stripe @p s again. */
    void
    rebuild_stripe(const unsigned int s);

    /** Clears the handler and inserts @p records in their order. */
    void
    insert_records(const Records &records);

    /** Re-inserts all particles so their data is in loop order in memory. */
    void
    store_in_loop_order();

    const BackgroundGrid<dim>      &grid;
    Particles::ParticleHandler<dim> particle_handler;
    types::particle_index           next_id = 0;
    /** Cell changes since the data was last put in loop order. */
    std::size_t moved_since_ordering = 0;
    /** Particles never appear or vanish after finish_insertion(). */
    types::particle_index n_particles_total = 0;
    std::vector<std::vector<typename BackgroundGrid<dim>::cell_iterator>>
      stripes;
  };

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_cells_of_stripes(const unsigned int first,
                                            const unsigned int step,
                                            const Function    &f)
  {
    const unsigned int n = (stripes.size() + step - 1 - first) / step;
    parallel::apply_to_subranges(
      0u,
      n,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int s = begin; s < end; ++s)
          for (const auto &cell : stripes[first + s * step])
            f(particle_handler.particles_in_cell(cell));
      },
      1);
  }

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_stripes(const unsigned int first,
                                   const unsigned int step,
                                   const Function    &f)
  {
    for_cells_of_stripes(first, step, [&](auto cell_particles) {
      for (auto &particle : cell_particles)
        f(particle);
    });
  }

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_each_cell_scattering(const Function &f)
  {
    for_cells_of_stripes(0, 2, f);
    for_cells_of_stripes(1, 2, f);
  }

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_each_scattering(const Function &f)
  {
    for_stripes(0, 2, f);
    for_stripes(1, 2, f);
  }

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_each_cell(const Function &f)
  {
    for_cells_of_stripes(0, 1, f);
  }

  template <int dim>
  template <typename Function>
  void
  ParticleSystem<dim>::for_each(const Function &f)
  {
    for_stripes(0, 1, f);
  }

  template <int dim>
  template <typename Result, typename AddCell>
  Result
  ParticleSystem<dim>::sum_by_stripes(const AddCell &add_cell) const
  {
    // one partial sum per stripe, added up in stripe order: the result does
    // not depend on how the stripes are spread over threads
    std::vector<Result> partial(stripes.size(), Result());
    auto               &handler =
      const_cast<Particles::ParticleHandler<dim> &>(particle_handler);
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(stripes.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int s = begin; s < end; ++s)
          for (const auto &cell : stripes[s])
            add_cell(partial[s], handler.particles_in_cell(cell));
      },
      1);
    Result result = Result();
    for (const Result &p : partial)
      result += p;
    return result;
  }

  template <int dim>
  template <typename Result, typename Function>
  Result
  ParticleSystem<dim>::sum(const Function &f) const
  {
    return sum_by_stripes<Result>(
      [&](Result &partial, const auto &cell_particles) {
        for (const auto &particle : cell_particles)
          partial += f(particle);
      });
  }

  template <int dim>
  template <typename Result, typename Function>
  Result
  ParticleSystem<dim>::sum_over_cells(const Function &f) const
  {
    return sum_by_stripes<Result>(
      [&](Result &partial, const auto &cell_particles) {
        partial += f(cell_particles);
      });
  }
} // namespace bfemp

#endif
