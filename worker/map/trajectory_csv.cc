#include "worker/map/trajectory_csv.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "common/config/config_error.h"
#include "common/csv/csv_table.h"

namespace rlpos::map {
namespace {

struct Row {
  int episode = 0;
  std::size_t uav = 0;
  Vec3 position;
};

double Number(const std::string& cell, bool& ok) {
  std::size_t used = 0;
  try {
    const double v = std::stod(cell, &used);
    ok = ok && used == cell.size() && std::isfinite(v);
    return v;
  } catch (const std::exception&) {
    ok = false;
    return 0;
  }
}

// The columns a trajectory needs.
struct Columns {
  std::size_t episode, uav, x, y, z;
};

Row ParseRow(const CsvRow& csv, const Columns& column, std::size_t n_uavs,
             const std::string& where) {
  const auto& cells = csv.cells;
  bool ok = true;
  Row row;
  const double episode = Number(cells[column.episode], ok);
  const double uav = Number(cells[column.uav], ok);
  row.position = {Number(cells[column.x], ok), Number(cells[column.y], ok),
                  Number(cells[column.z], ok)};
  if (!ok)
    throw std::runtime_error(where + ": a cell that is not a number");
  if (uav < 0 || uav >= static_cast<double>(n_uavs) || uav != std::floor(uav))
    throw std::runtime_error(where + ": UAV " + cells[column.uav] + " is not one of the " +
                             std::to_string(n_uavs) + " of the scenario");
  row.episode = static_cast<int>(episode);
  row.uav = static_cast<std::size_t>(uav);
  return row;
}

std::vector<Row> ReadRows(const std::string& file, std::size_t n_uavs) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error(file + ": cannot open file");
  CsvTable table;
  Columns column{};
  try {
    table = ReadCsvTable(in);
    column = {table.Column("episode"), table.Column("uav"), table.Column("x"), table.Column("y"),
              table.Column("z")};
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
  std::vector<Row> rows;
  for (const CsvRow& csv : table.rows)
    rows.push_back(ParseRow(csv, column, n_uavs, file + ": line " + std::to_string(csv.line)));
  if (rows.empty())
    throw std::runtime_error(file + ": no steps");
  return rows;
}

}  // namespace

Flight ReadTrajectoryCsv(const std::string& file, const Scenario& scenario,
                         const std::string& what) {
  std::vector<Row> rows;
  try {
    rows = ReadRows(file, scenario.uavs.size());
  } catch (const std::runtime_error& e) {
    throw ConfigError(what, e.what());
  }
  Flight flight;
  flight.episode = rows.back().episode;
  const Placement start = scenario.InitialPlacement();
  for (std::size_t u = 0; u < start.size(); ++u)
    flight.paths.push_back({static_cast<int>(u), {start[u]}});
  for (const Row& row : rows) {
    if (row.episode == flight.episode)
      flight.paths[row.uav].points.push_back(row.position);
  }
  return flight;
}

}  // namespace rlpos::map
