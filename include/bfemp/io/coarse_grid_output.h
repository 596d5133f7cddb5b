#ifndef bfemp_io_coarse_grid_output_h
#define bfemp_io_coarse_grid_output_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

#include <string>
#include <vector>

namespace bfemp
{
  /**
   * Snapshots of cMPM's active coarse elements (`output/write grid` with
   * `cmpm/enabled`): coarse_grid_NNNNN.vtu, listed in coarse_grid.pvd. Each
   * element the last step used is one VTK patch subdivided into its n - 2
   * fine knot spans per direction, so ParaView shows the coarse elements and
   * their knot-span grid at once. At every patch point it holds the last
   * step's displacement u = sum_I Phi_I Q_I and end velocity
   * v = sum_I Phi_I v_I through the matrix-valued shape functions (seed 002
   * eq. 15), evaluated on the element's own side of its faces, and the
   * element's flat index. The points are the grid's (Eulerian) positions of
   * the step's start: warp by `displacement` in ParaView to see the motion.
   */
  template <int dim>
  class CoarseGridOutput
  {
  public:
    CoarseGridOutput(const std::string             &folder,
                     const CmpmDiscretization<dim> &cmpm);

    /** Writes one snapshot from the coarse nodes' displacement and
     *  velocity in @p state; nothing before the first step. */
    void
    write(const GridState<dim> &state,
          const double          time,
          const unsigned int    snapshot);

    /** Continues the series of a checkpointed run (PvdSeries::resume()). */
    void
    resume(const unsigned int next_snapshot);

    /** The patches write() writes: data rows displacement (dim), velocity
     *  (dim), element. */
    std::vector<DataOutBase::Patch<dim, dim>>
    build_patches(const GridState<dim> &state) const;

  private:
    std::string                    folder;
    const CmpmDiscretization<dim> &cmpm;
    PvdSeries                      series;
  };
} // namespace bfemp

#endif
