// Modified Newton (`solver/modified Newton contraction`, the chord and
// Shamanskii methods, doc/implicit.md): an iteration solves with the last
// factorization as it stands and assembles no Hessian while the Newton
// increments shrink by the contraction per iteration. It targets cMPM,
// whose Hessian assembly (the condensation p^T K p per coarse element)
// dominates a step. Two scenes, each run without and with contraction 0.5
// on the same particles:
//  - the 2D bending beam with L = H/3 and interior modes
//    (prm/cmpm/bending_beam_2d_h3_modes.prm, seed 002 Section 8.1.2; 24
//    steps of 0.025 s; its prm sets 'factorization reuse = 20' and the
//    contraction 0.5, which the run without overrides);
//  - the 2D heterogeneous cMPM block thrown at an FEM block with barrier
//    frictional contact (prm/cmpm/contact_collision_2d.prm, 50 steps), where
//    the barrier's Hessian changes fastest from one iteration to the next.
// Checked for each scene:
//  - both runs reach the end time (contact: no particle inside the FEM
//    block, the smallest distance positive);
//  - the end states agree to the Newton tolerance: every particle (and FEM
//    node) within N eps_d dt of the run without (N steps; each step's answer
//    lies within about one last Newton increment, eps_d dt, of the
//    minimizer);
//  - the modified run assembles at most 0.4 (beam) and 0.5 (contact) times
//    as many Hessians as the run without does Newton iterations (measured:
//    24 of 95, the unknowns being renumbered every step as the beam sags
//    into new coarse elements, so that each step factorizes once; 232 of
//    608 with contact, where the contraction test sets many directions
//    aside while the contact set changes).
// The counts go to the output. About 30 s.

#include <string>

#include "../format.h"
#include "../implicit/implicit_scene.h"

namespace
{
  using namespace implicit_scene;
  using bfemp_tests::format;

  struct Run
  {
    Outcome<2>   outcome;
    unsigned int steps = 0;
    double       dt    = 0.;
    // summed over the steps
    double newton_iterations = 0., modified_iterations = 0.,
           factorizations = 0., particles_inside = 0., min_distance = 1e300;
  };

  /** Runs prm/cmpm/@p scene.prm as @p name with @p entries appended. */
  Run
  run_variant(const std::string &scene,
              const std::string &name,
              const std::string &entries,
              const bool         contact)
  {
    std::ofstream(name + ".prm")
      << "include " << BFEMP_SOURCE_DIR << "/prm/cmpm/" << scene
      << ".prm\nsubsection run\n  set name = " << name
      << "\n  set quiet = true\n  set threads = 1\nend\n"
      << "subsection output\n  set directory = results\n"
         "  set write particles = false\n  set write grid = false\n"
         "  set diagnostics interval = 1\nend\n"
      << entries;
    Run result;
    result.outcome = implicit_scene::run<2>(name + ".prm");
    bfemp_tests::check(result.outcome.error.empty(),
                       name + ": the run reached the end time" +
                         (result.outcome.error.empty()
                            ? ""
                            : ": " + result.outcome.error));
    std::vector<std::string> which = {"step",
                                      "dt",
                                      "newton_iterations",
                                      "modified_newton_iterations",
                                      "factorizations"};
    if (contact)
      which.insert(which.end(), {"particles_in_fem", "min_distance"});
    const auto c = columns(name, which);
    result.steps = static_cast<unsigned int>(c[0].back());
    result.dt    = c[1].back();
    for (unsigned int i = 1; i < c[0].size(); ++i)
      {
        result.newton_iterations += c[2][i];
        result.modified_iterations += c[3][i];
        result.factorizations += c[4][i];
        if (contact)
          {
            result.particles_inside += c[5][i];
            result.min_distance = std::min(result.min_distance, c[6][i]);
          }
      }
    dealii::deallog << name << ": " << result.steps << " steps, "
                    << format("%.0f", result.newton_iterations)
                    << " Newton iterations, "
                    << format("%.0f", result.modified_iterations)
                    << " of them modified (no Hessian assembled), "
                    << format("%.0f", result.factorizations)
                    << " factorizations" << std::endl;
    if (contact)
      bfemp_tests::check(result.particles_inside == 0. &&
                           result.min_distance > 0.,
                         name +
                           ": no particle inside the FEM block, smallest "
                           "distance " +
                           format("%.2e", result.min_distance) + " m > 0");
    return result;
  }

  /** Largest distance between the two runs' particles and FEM nodes,
   *  checked against N eps_d dt. */
  void
  compare_end_states(const Run &a, const Run &b, const std::string &scene)
  {
    constexpr double eps_d = 1e-6; // both scenes' 'solver/Newton tolerance'
    const double distance  = std::max(particle_distance(a.outcome, b.outcome),
                                     fem_node_distance(a.outcome, b.outcome));
    bfemp_tests::check_below(distance,
                             a.steps * eps_d * a.dt,
                             scene + ": end states with and without modified "
                                     "Newton, largest distance in m");
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  const std::string newton =
    "subsection solver\n  set modified Newton contraction = 0\nend\n";
  const std::string modified =
    "subsection solver\n  set modified Newton contraction = 0.5\nend\n";

  const Run beam =
    run_variant("bending_beam_2d_h3_modes", "beam_newton", newton, false);
  const Run beam_modified =
    run_variant("bending_beam_2d_h3_modes", "beam_modified", modified, false);
  compare_end_states(beam, beam_modified, "bending beam");
  const double assemblies =
    beam_modified.newton_iterations - beam_modified.modified_iterations;
  bfemp_tests::check(assemblies <= 0.4 * beam.newton_iterations,
                     "bending beam: Hessians assembled with modified Newton "
                     "at most 0.4 of Newton's iterations: " +
                       format("%.0f", assemblies) + " against " +
                       format("%.0f", beam.newton_iterations));

  const Run collision =
    run_variant("contact_collision_2d", "collision_newton", newton, true);
  const Run collision_modified =
    run_variant("contact_collision_2d", "collision_modified", modified, true);
  compare_end_states(collision, collision_modified, "contact collision");
  const double contact_assemblies = collision_modified.newton_iterations -
                                    collision_modified.modified_iterations;
  bfemp_tests::check(contact_assemblies <= 0.5 * collision.newton_iterations,
                     "contact collision: Hessians assembled with modified "
                     "Newton at most 0.5 of Newton's iterations: " +
                       format("%.0f", contact_assemblies) + " against " +
                       format("%.0f", collision.newton_iterations));
}
