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

PlacementColumns::PlacementColumns(const Statement& select)
    : x(select.Column("x")),
      y(select.Column("y")),
      z(select.Column("z")),
      positions_json(select.Column("positions_json")) {}

std::optional<Placement> ReadPlacement(const Statement& row, const PlacementColumns& c) {
  if (const auto positions = row.OptionalText(c.positions_json)) {
    Placement placement;
    for (const auto& q : json::parse(*positions))
      placement.push_back({q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>()});
    return placement;
  }
  const auto x = row.OptionalDouble(c.x);
  const auto y = row.OptionalDouble(c.y);
  const auto z = row.OptionalDouble(c.z);
  if (x && y && z)
    return Placement{{*x, *y, *z}};
  return std::nullopt;
}

ParamColumns::ParamColumns(const Statement& select)
    : kind(select.Column("kind")),
      scenario(select.Column("scenario")),
      train_seed(select.Column("train_seed")),
      fidelity(select.Column("fidelity")),
      train_episodes(select.Column("train_episodes")),
      positioner(select.Column("positioner")),
      rng_run(select.Column("rng_run")),
      duration_s(select.Column("duration_s")),
      warmup_s(select.Column("warmup_s")),
      overrides_json(select.Column("overrides_json")),
      policy_sha256(select.Column("policy_sha256")),
      placement(select) {}

JobParams ReadParams(const Statement& row, const ParamColumns& c,
                     std::optional<Placement>& placement, const std::string& file) {
  JobParams p;
  try {
    p.kind = ParseJobKind(row.Text(c.kind));
    p.scenario = row.Text(c.scenario);
    if (const auto seed = row.OptionalInt(c.train_seed)) {
      p.train_seed = static_cast<std::uint64_t>(*seed);
    }
    p.fidelity = row.OptionalText(c.fidelity).value_or("");
    if (const auto episodes = row.OptionalInt(c.train_episodes)) {
      p.train_episodes = static_cast<int>(*episodes);
    }
    p.positioner = row.OptionalText(c.positioner).value_or("");
    if (const auto run = row.OptionalInt(c.rng_run))
      p.rng_run = static_cast<std::uint64_t>(*run);
    p.duration_s = row.OptionalDouble(c.duration_s);
    p.warmup_s = row.OptionalDouble(c.warmup_s);
    for (const auto& pair : json::parse(row.Text(c.overrides_json))) {
      p.overrides.push_back({pair.at(0).get<std::string>(), pair.at(1).get<std::string>()});
    }
    placement = ReadPlacement(row, c.placement);
    p.policy_sha256 = row.OptionalText(c.policy_sha256).value_or("");
  } catch (const std::exception& e) {
    throw StoreError(file, std::string("malformed job row: ") + e.what());
  }
  return p;
}

RunningJobColumns::RunningJobColumns(const Statement& select)
    : id(select.Column("id")),
      campaign_id(select.Column("campaign_id")),
      worker_id(select.Column("worker_id")),
      slot(select.Column("slot")),
      attempt(select.Column("attempt")),
      started_at(select.Column("started_at")),
      timeout_s(select.Column("timeout_s")) {}

RunningJob ReadRunningJob(const Statement& row, const RunningJobColumns& c) {
  return {row.Text(c.id),
          row.Text(c.campaign_id),
          row.Text(c.worker_id),
          static_cast<int>(row.Int(c.slot)),
          static_cast<int>(row.Int(c.attempt)),
          row.Double(c.started_at),
          row.Double(c.timeout_s)};
}

}  // namespace rlpos
