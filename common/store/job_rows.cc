#include "common/store/job_rows.h"

#include <nlohmann/json.hpp>

#include "common/scenario/placement_json.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"

namespace rlpos {

using nlohmann::json;

std::optional<std::string> PositionsJson(const Placement& placement) {
  if (placement.size() < 2)
    return std::nullopt;
  return PlacementJson(placement).dump();
}

std::optional<Placement> ReadPlacement(const Statement& row, int first) {
  if (const auto positions = row.OptionalText(first + 3)) {
    Placement placement;
    for (const auto& q : json::parse(*positions))
      placement.push_back({q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>()});
    return placement;
  }
  const auto x = row.OptionalDouble(first);
  const auto y = row.OptionalDouble(first + 1);
  const auto z = row.OptionalDouble(first + 2);
  if (x && y && z)
    return Placement{{*x, *y, *z}};
  return std::nullopt;
}

JobParams ReadParams(const Statement& row, int first, std::optional<Placement>& placement,
                     const std::string& file) {
  JobParams p;
  try {
    p.kind = ParseJobKind(row.Text(first));
    p.scenario = row.Text(first + 1);
    if (const auto seed = row.OptionalInt(first + 2)) {
      p.train_seed = static_cast<std::uint64_t>(*seed);
    }
    p.fidelity = row.OptionalText(first + 3).value_or("");
    if (const auto episodes = row.OptionalInt(first + 4)) {
      p.train_episodes = static_cast<int>(*episodes);
    }
    p.positioner = row.OptionalText(first + 5).value_or("");
    if (const auto run = row.OptionalInt(first + 6))
      p.rng_run = static_cast<std::uint64_t>(*run);
    p.duration_s = row.OptionalDouble(first + 7);
    p.warmup_s = row.OptionalDouble(first + 8);
    for (const auto& pair : json::parse(row.Text(first + 9))) {
      p.overrides.push_back({pair.at(0).get<std::string>(), pair.at(1).get<std::string>()});
    }
    placement = ReadPlacement(row, first + 10);
    p.policy_sha256 = row.OptionalText(first + 14).value_or("");
  } catch (const std::exception& e) {
    throw StoreError(file, std::string("malformed job row: ") + e.what());
  }
  return p;
}

RunningJob ReadRunningJob(const Statement& row) {
  return {row.Text(0),
          row.Text(1),
          row.Text(2),
          static_cast<int>(row.Int(3)),
          static_cast<int>(row.Int(4)),
          row.Double(5),
          row.Double(6)};
}

}  // namespace rlpos
