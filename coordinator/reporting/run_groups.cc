#include "coordinator/reporting/run_groups.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>

#include "common/campaign/campaign_spec.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

// Plain labels in report order.
const std::vector<std::string>& CanonicalLabels() {
  static const std::vector<std::string> labels = [] {
    std::vector<std::string> out;
    for (const auto& positioner : AllPositioners()) {
      if (positioner == "offsets") {
        for (int k = 1; k <= 5; ++k)
          out.push_back("offset" + std::to_string(k));
      } else {
        out.push_back(positioner);
      }
    }
    return out;
  }();
  return labels;
}

// (rank of the plain label, rank of its algorithm: 0 for none, seed: 0 for the first, the
// label) for sorting "<plain>[@<algorithm>][@seed<N>]".
std::tuple<std::size_t, std::size_t, std::uint64_t, std::string> SortKey(const std::string& label) {
  const auto at = label.find('@');
  const std::string plain = label.substr(0, at);
  const auto& canonical = CanonicalLabels();
  const auto it = std::find(canonical.begin(), canonical.end(), plain);
  const std::size_t rank = static_cast<std::size_t>(it - canonical.begin());  // end: unknown
  std::size_t algorithm_rank = 0;
  std::uint64_t seed = 0;
  std::string rest = at == std::string::npos ? "" : label.substr(at + 1);
  const auto& algorithms = AllAlgorithms();
  for (std::size_t a = 0; a < algorithms.size() && !rest.empty(); ++a) {
    const std::string& name = algorithms[a];
    if (rest.compare(0, name.size(), name) == 0 &&
        (rest.size() == name.size() || rest[name.size()] == '@')) {
      algorithm_rank = a + 1;
      rest = rest.size() == name.size() ? "" : rest.substr(name.size() + 1);
    }
  }
  if (!rest.empty()) {
    const std::string digits = rest.rfind("seed", 0) == 0 ? rest.substr(4) : "";
    const bool numeric =
        !digits.empty() && digits.size() < 19 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(c) != 0; });
    seed = numeric ? std::stoull(digits) + 1 : std::numeric_limits<std::uint64_t>::max();
    if (!numeric)  // an unknown suffix: after every known one
      algorithm_rank = std::numeric_limits<std::size_t>::max();
  }
  return {rank, algorithm_rank, seed, label};
}

}  // namespace

bool ReportLabelLess(const std::string& a, const std::string& b) {
  return SortKey(a) < SortKey(b);
}

std::vector<RunGroup> GroupRuns(const std::vector<MetricRow>& rows) {
  std::vector<std::string> scenarios;
  std::map<std::string, std::map<std::string, std::vector<const MetricRow*>>> by_scenario;
  for (const auto& row : rows) {
    auto found = by_scenario.find(row.scenario);
    if (found == by_scenario.end()) {
      scenarios.push_back(row.scenario);
      found =
          by_scenario.emplace(row.scenario, std::map<std::string, std::vector<const MetricRow*>>{})
              .first;
    }
    found->second[row.label].push_back(&row);
  }
  std::vector<RunGroup> out;
  for (const auto& scenario : scenarios) {
    auto& labels = by_scenario[scenario];
    std::vector<std::string> order;
    for (const auto& entry : labels)
      order.push_back(entry.first);
    std::sort(order.begin(), order.end(), ReportLabelLess);
    for (const auto& label : order)
      out.push_back({scenario, label, std::move(labels[label])});
  }
  return out;
}

}  // namespace rlpos
