#ifndef bfemp_scene_scene_parameters_h
#define bfemp_scene_scene_parameters_h

#include <bfemp/base/run_parameters.h>
#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/cmpm/cmpm_parameters.h>
#include <bfemp/contact/contact_parameters.h>
#include <bfemp/fem/fem_body_parameters.h>
#include <bfemp/grid/grid_parameters.h>
#include <bfemp/integrator/time_parameters.h>
#include <bfemp/io/checkpoint_parameters.h>
#include <bfemp/io/output_parameters.h>
#include <bfemp/particles/body_parameters.h>
#include <bfemp/solver/solver_parameters.h>
#include <bfemp/transfer/transfer_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace bfemp
{
  /**
   * Everything a scene prm file says, one struct per subsection. The file is
   * read in passes: the counts that decide which subsections exist ("number
   * of bodies", each body's "number of primitives" and "number of material
   * regions", "number of level sets",
   * "number of FEM bodies")
   * are read leniently until they settle, then the whole file is parsed
   * strictly, so any unknown or malformed entry is reported with its line.
   */
  template <int dim>
  struct SceneParameters
  {
    RunParameters                       run;
    GridParameters<dim>                 grid;
    TimeParameters                      time;
    TransferParameters                  transfer;
    CmpmParameters                      cmpm;
    Tensor<1, dim>                      gravity;
    GridBoundaries<dim>                 boundaries;
    OutputParameters                    output;
    CheckpointParameters                checkpoint;
    std::vector<BodyParameters<dim>>    bodies;
    std::vector<FemBodyParameters<dim>> fem_bodies;
    SolverParameters                    solver;
    ContactParameters                   contact;
    /**
     * The prm file read. A relative mesh file is resolved against the
     * directory of the file (this one or one it includes) that names it.
     */
    std::string file;

    /** Reads and checks @p file; throws InputError naming file and entry. */
    void
    read(const std::string &prm_file);

    /** Declares all entries for the given counts of numbered subsections. */
    static void
    declare_parameters(
      ParameterHandler                                        &prm,
      const std::vector<typename BodyParameters<dim>::Counts> &body_counts,
      const unsigned int                                       n_level_sets,
      const std::vector<unsigned int> &motions_per_fem_body);

    /** Refuses combinations cMPM does not support (cmpm/enabled). */
    void
    check_cmpm() const;

    void
    parse_parameters(ParameterHandler &prm);
  };

  /** The "dimension" entry of a prm file (2 or 3), read before anything. */
  unsigned int
  read_dimension(const std::string &file);

  /** Declares "dimension" (shared by read_dimension and the full reader). */
  void
  declare_dimension(ParameterHandler &prm);

  /**
   * Parses @p file into @p prm; deal.II's parse errors become InputErrors
   * that start with the file name. @p lenient skips undeclared entries.
   */
  void
  parse_prm_file(ParameterHandler  &prm,
                 const std::string &file,
                 const bool         lenient);
} // namespace bfemp

#endif
