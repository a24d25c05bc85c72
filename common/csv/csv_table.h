#pragma once
// The CSV files rlpos-sim writes and others read back (learning_curve.csv, trajectory.csv): a
// header of column names, then rows of plain cells (no cell holds a comma, none is quoted).
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace rlpos {

// One line's cells, split at every comma.
std::vector<std::string> SplitCsvLine(const std::string& line);

struct CsvRow {
  int line = 0;                    // in the file; the header is line 1
  std::vector<std::string> cells;  // as many as the header has
};

struct CsvTable {
  std::vector<std::string> header;
  std::vector<CsvRow> rows;

  // The index of column `name`, or npos.
  std::size_t Find(const std::string& name) const;
  // The index of column `name`; throws std::runtime_error "line 1: no column "name"".
  std::size_t Column(const std::string& name) const;
};

// The header and every row of `in`. Throws std::runtime_error: "empty file" without a header,
// "line N: K cells, not H" for a row of another width than the header's.
CsvTable ReadCsvTable(std::istream& in);

}  // namespace rlpos
