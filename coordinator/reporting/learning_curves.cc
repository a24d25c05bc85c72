#include "coordinator/reporting/learning_curves.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/store/artifact_files.h"
#include "coordinator/reporting/csv_cells.h"

namespace rlpos {
namespace {

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');)
    cells.push_back(cell);
  return cells;
}

// Points of one learning_curve.csv (rlpos-sim train's columns, found by name).
std::vector<LearningCurvePoint> ReadCurveFile(const std::string& file, const ArtifactRecord& a) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("cannot read");
  std::string line;
  if (!std::getline(in, line))
    throw std::runtime_error("empty");
  std::map<std::string, std::size_t> column;
  const auto header = SplitCsvLine(line);
  for (std::size_t i = 0; i < header.size(); ++i)
    column[header[i]] = i;
  for (const char* needed : {"episode", "phase", "total_reward", "epsilon"}) {
    if (!column.count(needed))
      throw std::runtime_error(std::string("no column ") + needed);
  }
  std::vector<LearningCurvePoint> points;
  while (std::getline(in, line)) {
    const auto cells = SplitCsvLine(line);
    if (cells.size() != header.size())
      throw std::runtime_error("a row of " + std::to_string(cells.size()) + " cells");
    LearningCurvePoint p;
    p.scenario = a.scenario;
    p.label = a.label;
    try {
      p.episode = std::stoi(cells[column["episode"]]);
      p.phase = cells[column["phase"]];
      p.total_reward = std::stod(cells[column["total_reward"]]);
      p.epsilon = std::stod(cells[column["epsilon"]]);
      if (column.count("mean_loss"))
        p.mean_loss = std::stod(cells[column["mean_loss"]]);
    } catch (const std::logic_error&) {
      throw std::runtime_error("a cell that is not a number in: " + line.substr(0, 80));
    }
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace

std::vector<LearningCurvePoint> ReadLearningCurves(ResultsReader& store,
                                                   const std::string& campaign_id,
                                                   std::vector<std::string>& warnings) {
  const std::filesystem::path root = ArtifactsDirOf(store.file());
  std::vector<LearningCurvePoint> out;
  for (const auto& a : store.Artifacts(campaign_id)) {
    if (a.name != "learning_curve.csv")
      continue;
    const std::string file = (root / a.path).string();
    try {
      const auto points = ReadCurveFile(file, a);
      out.insert(out.end(), points.begin(), points.end());
    } catch (const std::exception& e) {
      warnings.push_back("learning curve " + file + " skipped: " + e.what());
    }
  }
  return out;
}

std::string FormatLearningCurvesCsv(const std::vector<LearningCurvePoint>& points) {
  std::ostringstream out;
  out << "scenario,label,episode,phase,total_reward,mean_loss,epsilon\n";
  for (const auto& p : points) {
    out << CsvText(p.scenario) << ',' << CsvText(p.label) << ',' << p.episode << ',' << p.phase
        << ',' << CsvNumber(p.total_reward) << ',' << CsvNumber(p.mean_loss) << ','
        << CsvNumber(p.epsilon) << '\n';
  }
  return out.str();
}

}  // namespace rlpos
