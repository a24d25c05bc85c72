#pragma once
// The store's read side: campaigns, jobs, metrics, workers and artifacts as `status`,
// `results`, `report` and the coordinator read them. Reads only (a read-only StoreDb will do).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/store/metric_rows.h"
#include "common/store/optimality_rows.h"
#include "common/store/store_records.h"
#include "common/store/track_rows.h"

namespace rlpos {

class Database;
class StoreDb;

class ResultsReader {
 public:
  explicit ResultsReader(StoreDb& store);

  const std::string& file() const;
  // The distinct builds (DescribeBuild) of a campaign's succeeded jobs that recorded one: more
  // than one means its results come from mixed versions.
  std::vector<std::string> CampaignBuilds(const std::string& campaign_id);

  // Throws StoreError for an unknown campaign.
  CampaignProgress Progress(const std::string& campaign_id);
  std::vector<CampaignProgress> AllProgress();
  std::optional<JobRecord> GetJob(const std::string& job_id);
  // One row per succeeded eval job, by scenario (campaign order), label, rng_run.
  std::vector<MetricRow> Metrics(const std::string& campaign_id);
  // One row per UAV of each succeeded eval, in the order of Metrics, then by UAV.
  std::vector<UavMetricRow> UavMetrics(const std::string& campaign_id);
  // One row per succeeded track job, by scenario (campaign order), positioner, rng_run.
  std::vector<TrackRunRow> TrackRuns(const std::string& campaign_id);
  // Their intervals (track_rows.h): every run's, or each scenario and positioner's first run's.
  std::vector<TrackIntervalRecord> TrackIntervals(const std::string& campaign_id,
                                                  TrackRunsRead which);
  // Each interval averaged over the runs of its scenario and positioner (track_rows.h).
  std::vector<TrackSeriesRow> TrackSeries(const std::string& campaign_id);
  // rl's reward against the oracle's, per scenario, algorithm and train seed (optimality_rows.h).
  std::vector<OptimalityRow> Optimality(const std::string& campaign_id);

  // What `status` and `run` show while a campaign runs (results_reader_monitoring.cc).
  std::vector<WorkerRecord> ListWorkers();
  // Throw StoreError for an unknown campaign.
  std::vector<RunningJobView> RunningJobs(const std::string& campaign_id);
  CampaignTiming Timing(const std::string& campaign_id);
  std::vector<FailedJob> FailedJobs(const std::string& campaign_id);
  // The campaign's spec with only its top-level `key` ({} when the spec has none), read out by
  // SQLite: a spec lists every RngRun, and a 100k-run list need not be parsed to get at the
  // scenarios. nullopt for an unknown campaign.
  std::optional<nlohmann::json> CampaignSpecPart(const std::string& campaign_id,
                                                 const std::string& key);
  // The artifacts of a campaign (or of one job, given its id), by job then name.
  std::vector<ArtifactRecord> Artifacts(const std::string& campaign_or_job_id);
  // One artifact by its id (ArtifactRecord::id); nullopt when there is none.
  std::optional<ArtifactRecord> Artifact(std::int64_t id);

 private:
  StoreDb& store_;
  Database* db_;
};

}  // namespace rlpos
