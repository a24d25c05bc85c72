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
        "COALESCE(json_extract(t.result_json, '$.algorithm'), '') ELSE r.positioner END "
        "AS algorithm, "
        "CASE WHEN t.kind = 'train' THEN COALESCE(t.train_seed, 0) ELSE 0 END AS seed, "
        "r.positioner AS label, COUNT(*) AS runs, AVG(r.reward) AS rl_reward, "
        "o.reward AS oracle_reward, t.kind = 'train' AS trained, "
        "MAX(COALESCE(s.finished_at - s.started_at, t.finished_at - t.started_at)) "
        "AS placement_s "
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
  const ResultColumn scenario = select.Column("scenario"), uavs = select.Column("uavs"),
                     algorithm = select.Column("algorithm"), seed = select.Column("seed"),
                     label = select.Column("label"), runs = select.Column("runs"),
                     rl_reward = select.Column("rl_reward"),
                     oracle_reward = select.Column("oracle_reward"),
                     trained = select.Column("trained"), placement_s = select.Column("placement_s");
  std::vector<OptimalityRow> out;
  while (select.Step()) {
    OptimalityRow row;
    row.scenario = select.Text(scenario);
    row.uavs = static_cast<int>(select.Int(uavs));
    row.algorithm = select.Text(algorithm);
    row.train_seed = static_cast<std::uint64_t>(select.Int(seed));
    row.label = select.Text(label);
    row.runs = static_cast<int>(select.Int(runs));
    row.rl_reward = select.Double(rl_reward);
    row.oracle_reward = select.Double(oracle_reward);
    row.trained = select.Int(trained) != 0;
    row.placement_s = select.OptionalDouble(placement_s);
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
