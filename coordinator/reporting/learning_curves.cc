#include "coordinator/reporting/learning_curves.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/csv/csv_table.h"
#include "common/store/artifact_files.h"
#include "coordinator/reporting/csv_cells.h"

namespace rlpos {
namespace {

// Points of one learning_curve.csv (rlpos-sim train's columns, found by name).
std::vector<LearningCurvePoint> ReadCurveFile(const std::string& file, const ArtifactRecord& a) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("cannot read");
  const CsvTable table = ReadCsvTable(in);
  const std::size_t episode = table.Column("episode");
  const std::size_t phase = table.Column("phase");
  const std::size_t total_reward = table.Column("total_reward");
  const std::size_t epsilon = table.Column("epsilon");
  const std::size_t mean_loss = table.Find("mean_loss");
  std::vector<LearningCurvePoint> points;
  for (const CsvRow& row : table.rows) {
    LearningCurvePoint p;
    p.scenario = a.scenario;
    p.label = a.label;
    try {
      p.episode = std::stoi(row.cells[episode]);
      p.phase = row.cells[phase];
      p.total_reward = std::stod(row.cells[total_reward]);
      p.epsilon = std::stod(row.cells[epsilon]);
      if (mean_loss != std::string::npos)
        p.mean_loss = std::stod(row.cells[mean_loss]);
    } catch (const std::logic_error&) {
      throw std::runtime_error("line " + std::to_string(row.line) +
                               ": a cell that is not a number");
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
