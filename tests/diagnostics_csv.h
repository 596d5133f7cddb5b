#ifndef bfemp_tests_diagnostics_csv_h
#define bfemp_tests_diagnostics_csv_h

// Reading a run's diagnostics.csv in the tests.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests.h"

namespace bfemp_tests
{
  /** The columns @p names of a diagnostics.csv (or another CSV file with a
   *  header row), in that order, as numbers; a missing column fails the
   *  test. */
  inline std::vector<std::vector<double>>
  read_columns(const std::string &file, const std::vector<std::string> &names)
  {
    std::ifstream in(file);
    std::string   line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
      std::stringstream row(line);
      for (std::string entry; std::getline(row, entry, ',');)
        header.push_back(entry);
    }
    std::vector<unsigned int> index;
    for (const std::string &name : names)
      {
        unsigned int i = 0;
        while (i < header.size() && header[i] != name)
          ++i;
        if (i == header.size())
          bfemp_tests::check(false, "diagnostics.csv has column " + name);
        index.push_back(i);
      }
    std::vector<std::vector<double>> columns(names.size());
    while (std::getline(in, line))
      {
        // only the asked columns are numbers: others may hold labels
        std::vector<std::string> entries;
        std::stringstream        row(line);
        for (std::string entry; std::getline(row, entry, ',');)
          entries.push_back(entry);
        for (unsigned int c = 0; c < names.size(); ++c)
          columns[c].push_back(std::stod(entries.at(index[c])));
      }
    return columns;
  }
} // namespace bfemp_tests

#endif
