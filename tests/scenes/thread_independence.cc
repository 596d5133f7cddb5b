// The particle loops run over stripes of cells, with scatters split into two
// colours (ParticleSystem). That design promises results that do not depend
// on the number of threads, bit for bit. Here the default scene runs for 0.1 s
// on 1 and then on 2 threads, and every particle's position, velocity, F and
// affine matrix is compared exactly. Which threads ran is measured, not
// assumed: a TBB scheduler observer records the worker threads that joined
// the parallel loops during each run (none with one thread, at least one
// with two).

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <deal.II/base/multithread_info.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <tbb/task_scheduler_observer.h>
#include <thread>
#include <vector>

#include "tests.h"

using namespace dealii;

namespace
{
  /** The TBB worker threads that enter the scheduler while it lives. */
  class WorkerThreads : public tbb::task_scheduler_observer
  {
  public:
    WorkerThreads()
    {
      observe(true);
    }

    ~WorkerThreads()
    {
      observe(false);
    }

    void
    on_scheduler_entry(const bool is_worker) override
    {
      if (!is_worker)
        return;
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    }

    std::size_t
    count()
    {
      std::lock_guard<std::mutex> lock(mutex);
      return ids.size();
    }

  private:
    std::mutex                mutex;
    std::set<std::thread::id> ids;
  };

  /** Every particle's location and properties, by particle id, and the
   *  number of worker threads that took part. */
  std::map<types::particle_index, std::vector<double>>
  run_default_scene(const unsigned int threads, std::size_t &workers)
  {
    MultithreadInfo::set_thread_limit(threads);
    WorkerThreads             observer;
    bfemp::SceneParameters<2> parameters;
    parameters.read("thread_independence.prm");
    std::ostringstream   console;
    bfemp::Simulation<2> simulation(parameters,
                                    "thread_independence.prm",
                                    console);
    simulation.run();
    workers = observer.count();

    std::map<types::particle_index, std::vector<double>> state;
    for (const auto &particle : simulation.particles().handler())
      {
        std::vector<double> &values = state[particle.get_id()];
        for (unsigned int d = 0; d < 2; ++d)
          values.push_back(particle.get_location()[d]);
        for (const double p : particle.get_properties())
          values.push_back(p);
      }
    return state;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  std::filesystem::remove_all("results");
  {
    std::ofstream prm("thread_independence.prm");
    prm << "include " << BFEMP_SOURCE_DIR << "/prm/default.prm\n"
        << "subsection run\n"
           "  set end time = 0.1\n"
           "  set quiet    = true\n"
           "end\n"
           "subsection output\n"
           "  set directory       = results\n"
           "  set write particles = false\n"
           "  set write grid      = false\n"
           "end\n";
  }

  std::size_t workers_1 = 0, workers_2 = 0;
  const auto  one_thread  = run_default_scene(1, workers_1);
  const auto  two_threads = run_default_scene(2, workers_2);
  deallog << "worker threads that joined the loops: " << workers_1
          << " with a limit of 1, " << (workers_2 > 0 ? "at least 1" : "0")
          << " with a limit of 2" << std::endl;
  deallog << "particles: " << one_thread.size() << std::endl;
  bfemp_tests::check(workers_1 == 0, "the first run ran on one thread");
  bfemp_tests::check(workers_2 >= 1,
                     "the second run's loops ran on two threads");
  bfemp_tests::check(one_thread.size() == two_threads.size() &&
                       one_thread.size() > 1000,
                     "both runs have the same particles");

  std::size_t differing = 0;
  for (const auto &[id, values] : one_thread)
    if (two_threads.at(id) != values)
      ++differing;
  deallog << "particles whose state differs in any bit: " << differing
          << std::endl;
  bfemp_tests::check(differing == 0,
                     "1 and 2 threads give bitwise identical particles");
}
