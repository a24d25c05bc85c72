#pragma once
// The eval metrics in the results store (tables metrics and uav_metrics, views v_eval_runs and
// v_eval_uavs), written and read by the columns of EvalMetricTable() (metrics/eval_metrics.h).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/metrics/eval_metrics.h"
#include "common/store/job_result.h"

namespace rlpos {

class Database;

// One succeeded eval (view v_eval_runs): its metrics (null: undefined, or recorded before the
// metric's schema version) and where they were measured.
struct MetricRow : RunMetricFields<std::optional<double>> {
  std::string job_id, scenario, label;
  std::int64_t rng_run = 0;
  double x = 0, y = 0, z = 0;  // the first UAV's position
};

// One UAV's share of one succeeded eval (table uav_metrics, view v_eval_uavs).
struct UavMetricRow : UavMetricFields<std::optional<double>> {
  std::string job_id, scenario, label;
  std::int64_t rng_run = 0;
  int uav = 0;       // index in the scenario's order
  std::string name;  // "uav" for a single-UAV scenario
  double x = 0, y = 0, z = 0;
};

// Which job an eval's metrics belong to.
struct EvalRowKey {
  std::string job_id, campaign_id, scenario, label;
  std::int64_t rng_run = 0;
};

// " v JOIN ... ORDER BY ...": the rows of campaign ?1 of a view named `v` (with campaign_id,
// scenario, positioner and rng_run), scenarios in campaign order (their first job), not by name;
// then positioner and run.
std::string OfCampaignInOrder();

// Inserts the run's row into metrics and one row per UAV into uav_metrics.
void InsertEvalMetrics(Database& db, const EvalRowKey& key, const EvalResult& eval);

// One row per succeeded eval job, by scenario (campaign order), label, rng_run.
std::vector<MetricRow> ReadMetricRows(Database& db, const std::string& campaign_id);
// One row per UAV of each succeeded eval, in the order of ReadMetricRows, then by UAV.
std::vector<UavMetricRow> ReadUavMetricRows(Database& db, const std::string& campaign_id);

}  // namespace rlpos
