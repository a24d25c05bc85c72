#include "common/csv/csv_table.h"

#include <sstream>
#include <stdexcept>

namespace rlpos {

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');)
    cells.push_back(cell);
  return cells;
}

std::size_t CsvTable::Find(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name)
      return i;
  }
  return std::string::npos;
}

std::size_t CsvTable::Column(const std::string& name) const {
  const std::size_t i = Find(name);
  if (i == std::string::npos)
    throw std::runtime_error("line 1: no column \"" + name + "\"");
  return i;
}

CsvTable ReadCsvTable(std::istream& in) {
  CsvTable table;
  std::string line;
  if (!std::getline(in, line))
    throw std::runtime_error("empty file");
  table.header = SplitCsvLine(line);
  for (int number = 2; std::getline(in, line); ++number) {
    CsvRow row{number, SplitCsvLine(line)};
    if (row.cells.size() != table.header.size())
      throw std::runtime_error("line " + std::to_string(number) + ": " +
                               std::to_string(row.cells.size()) + " cells, not " +
                               std::to_string(table.header.size()));
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace rlpos
