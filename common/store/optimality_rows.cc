#include "common/store/optimality_rows.h"

#include "common/store/sqlite_db.h"

namespace rlpos {
namespace {

// Per scenario: its oracle's reward and its number of UAVs (the oracle evals' uav_metrics rows).
constexpr const char* kOracle =
    "SELECT v.scenario, AVG(v.reward) AS reward, "
    "MAX((SELECT COUNT(*) FROM uav_metrics u WHERE u.job_id = v.job_id)) AS uavs "
    "FROM v_eval_runs v WHERE v.campaign_id = ?1 AND v.positioner = 'oracle' "
    "AND v.reward IS NOT NULL GROUP BY v.scenario";

// Every placement's evals against the oracle's: each eval depends on the job that found its
// placement. rl evals ("rl", "rl@...") depend on a train job, whose result names the algorithm it
// trained; a named policy's ("rl+<name>") and the other positioners' (baseline, centroid, the
// oracle itself) on a position job: their "algorithm" is their label, so that no summary counts
// them with a trained algorithm. The offsets around rl's position are no placement of their own.
// The placement's seconds are its job's, or the job's whose result the cache gave it.
const std::string kSelect =
    std::string(
        "SELECT r.scenario, o.uavs, CASE WHEN t.kind = 'train' THEN "
        "COALESCE(json_extract(t.result_json, '$.algorithm'), '') ELSE r.positioner END, "
        "CASE WHEN t.kind = 'train' THEN COALESCE(t.train_seed, 0) ELSE 0 END, r.positioner, "
        "COUNT(*), AVG(r.reward), o.reward, t.kind = 'train', "
        "MAX(COALESCE(s.finished_at - s.started_at, t.finished_at - t.started_at)) "
        "FROM v_eval_runs r "
        "JOIN jobs e ON e.id = r.job_id "
        "JOIN jobs t ON t.id = e.depends_on "
        "LEFT JOIN jobs s ON s.id = t.cached_from "
        "JOIN (") +
    kOracle +
    ") o ON o.scenario = r.scenario "
    // Scenarios in campaign order (their first job), found once, as the metric readers do.
    "JOIN (SELECT scenario AS order_scenario, MIN(seq) AS order_seq FROM jobs "
    "WHERE campaign_id = ?1 GROUP BY scenario) f ON f.order_scenario = r.scenario "
    "WHERE r.campaign_id = ?1 AND r.reward IS NOT NULL AND (t.kind = 'position' OR "
    "(t.kind = 'train' AND (r.positioner = 'rl' OR substr(r.positioner, 1, 3) = 'rl@'))) "
    "GROUP BY r.scenario, r.positioner "
    // The trained rl of a scenario first, then the placements of position jobs.
    "ORDER BY f.order_seq, MAX(t.kind = 'position'), MIN(t.seq)";

}  // namespace

std::optional<double> OptimalityRow::Ratio() const {
  if (!(oracle_reward > 0))
    return std::nullopt;
  return rl_reward / oracle_reward;
}

bool OptimalityRow::IsRl() const {
  return label == "rl" || label.rfind("rl@", 0) == 0 || label.rfind("rl+", 0) == 0;
}

bool OptimalityRow::IsOracle() const {
  return !trained && label == "oracle";
}

std::vector<OptimalityRow> ReadOptimalityRows(Database& db, const std::string& campaign_id) {
  Statement select = db.Prepare(kSelect);
  select.Bind(campaign_id);
  std::vector<OptimalityRow> out;
  while (select.Step()) {
    OptimalityRow row;
    row.scenario = select.Text(0);
    row.uavs = static_cast<int>(select.Int(1));
    row.algorithm = select.Text(2);
    row.train_seed = static_cast<std::uint64_t>(select.Int(3));
    row.label = select.Text(4);
    row.runs = static_cast<int>(select.Int(5));
    row.rl_reward = select.Double(6);
    row.oracle_reward = select.Double(7);
    row.trained = select.Int(8) != 0;
    row.placement_s = select.OptionalDouble(9);
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
