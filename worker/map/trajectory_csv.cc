#include "worker/map/trajectory_csv.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/config/config_error.h"

namespace rlpos::map {
namespace {

struct Row {
  int episode = 0;
  std::size_t uav = 0;
  Vec3 position;
};

std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');)
    cells.push_back(cell);
  return cells;
}

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

Row ParseRow(const std::vector<std::string>& cells, std::map<std::string, std::size_t>& column,
             std::size_t n_uavs, const std::string& where) {
  bool ok = true;
  Row row;
  const double episode = Number(cells[column["episode"]], ok);
  const double uav = Number(cells[column["uav"]], ok);
  row.position = {Number(cells[column["x"]], ok), Number(cells[column["y"]], ok),
                  Number(cells[column["z"]], ok)};
  if (!ok)
    throw std::runtime_error(where + ": a cell that is not a number");
  if (uav < 0 || uav >= static_cast<double>(n_uavs) || uav != std::floor(uav))
    throw std::runtime_error(where + ": UAV " + cells[column["uav"]] + " is not one of the " +
                             std::to_string(n_uavs) + " of the scenario");
  row.episode = static_cast<int>(episode);
  row.uav = static_cast<std::size_t>(uav);
  return row;
}

std::vector<Row> ReadRows(const std::string& file, std::size_t n_uavs) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error(file + ": cannot open file");
  std::string line;
  if (!std::getline(in, line))
    throw std::runtime_error(file + ": empty file");
  std::map<std::string, std::size_t> column;
  const auto header = Cells(line);
  for (std::size_t i = 0; i < header.size(); ++i)
    column[header[i]] = i;
  for (const char* needed : {"episode", "uav", "x", "y", "z"}) {
    if (!column.count(needed))
      throw std::runtime_error(file + ": line 1: no column \"" + needed + "\"");
  }
  std::vector<Row> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    const auto cells = Cells(line);
    const std::string where = file + ": line " + std::to_string(number);
    if (cells.size() != header.size())
      throw std::runtime_error(where + ": " + std::to_string(cells.size()) + " cells, not " +
                               std::to_string(header.size()));
    rows.push_back(ParseRow(cells, column, n_uavs, where));
  }
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
