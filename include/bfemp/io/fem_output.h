#ifndef bfemp_io_fem_output_h
#define bfemp_io_fem_output_h

#include <bfemp/fem/fem_body.h>
#include <bfemp/io/pvd_series.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * The FEM snapshots of a run: fem_body_B_NNNNN.vtu per body (the deformed
   * mesh, one triangle or tetrahedron per element) and fem_body_B.pvd.
   * Point data: displacement (x - X), velocity, prescribed (1 on prescribed
   * nodes); cell data, constant per element: cauchy_stress, von_mises, J.
   * Elements are written as separate cells, so element fields show as
   * constants per element in ParaView, as linear simplices compute them.
   */
  template <int dim>
  class FemOutput
  {
  public:
    FemOutput(const std::string                                &folder,
              const std::vector<std::unique_ptr<FemBody<dim>>> &bodies);

    void
    write(const double time, const unsigned int snapshot);

    /** Continues the series of a checkpointed run (PvdSeries::resume()). */
    void
    resume(const unsigned int next_snapshot);

  private:
    void
    write_body(const unsigned int b,
               const double       time,
               const unsigned int snapshot);

    std::string                                       folder;
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies;
    std::vector<PvdSeries>                            series;
  };
} // namespace bfemp

#endif
