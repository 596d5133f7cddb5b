#include <bfemp/io/atomic_file.h>
#include <bfemp/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace bfemp
{
  PvdSeries::PvdSeries(const std::string &pvd_path)
    : pvd_path(pvd_path)
  {}



  void
  PvdSeries::add(const double time, const std::string &vtu_file_name)
  {
    times_and_names.emplace_back(time, vtu_file_name);
    write_file_atomically(pvd_path, [&](std::ostream &out) {
      dealii::DataOutBase::write_pvd_record(out, times_and_names);
    });
  }



  void
  PvdSeries::resume(const unsigned int next_snapshot)
  {
    times_and_names.clear();
    std::ifstream in(pvd_path);
    if (!in)
      return;
    const std::regex record(
      "<DataSet timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*_([0-9]+)\\.vtu)\"");
    const std::filesystem::path folder =
      std::filesystem::path(pvd_path).parent_path();
    for (std::string line; std::getline(in, line);)
      {
        std::smatch match;
        if (!std::regex_search(line, match, record))
          continue;
        if (std::stoul(match[3]) < next_snapshot)
          times_and_names.emplace_back(std::stod(match[1]), match[2]);
        else
          std::filesystem::remove(folder / match[2].str());
      }
    write_file_atomically(pvd_path, [&](std::ostream &out) {
      dealii::DataOutBase::write_pvd_record(out, times_and_names);
    });
  }
} // namespace bfemp
