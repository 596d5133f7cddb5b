#include <bfemp/io/atomic_file.h>
#include <bfemp/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

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
} // namespace bfemp
