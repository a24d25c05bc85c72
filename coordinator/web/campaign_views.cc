#include "coordinator/web/campaign_views.h"

#include <map>

#include "coordinator/reporting/optimality.h"
#include "coordinator/reporting/progress_text.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/uav_summary.h"
#include "coordinator/web/plot_views.h"

namespace rlpos::web {
namespace {

using nlohmann::json;

json OptionalNumber(const std::optional<double>& value) {
  return value ? json(*value) : json(nullptr);
}

std::string Clip(const std::string& text, std::size_t max) {
  return text.size() <= max ? text : text.substr(0, max) + "...";
}

json ProgressJson(const CampaignProgress& p, const CampaignTiming& t, double now) {
  const int done = p.succeeded + p.failed + p.cancelled;
  json out = {{"id", p.campaign_id},
              {"name", p.name},
              {"state", p.state},
              {"total", p.total},
              {"done", done},
              {"settled", IsSettled(p)},
              {"jobs",
               {{"pending", p.pending},
                {"ready", p.ready},
                {"running", p.running},
                {"succeeded", p.succeeded},
                {"failed", p.failed},
                {"cancelled", p.cancelled},
                {"cached", p.cached}}},
              {"created_at", t.created_at},
              {"first_started_at", OptionalNumber(t.first_started_at)},
              {"last_finished_at", OptionalNumber(t.last_finished_at)}};
  out["eta_s"] = IsSettled(p) ? json(nullptr) : OptionalNumber(EstimateRemainingSeconds(p, t, now));
  return out;
}

json WorkersJson(const std::vector<WorkerRecord>& workers) {
  int alive = 0, slots = 0, busy = 0;
  json list = json::array();
  for (const auto& w : workers) {
    if (w.state == "alive") {
      ++alive;
      slots += w.slots;
      busy += w.busy;
    }
    if (list.size() < kMaxListedWorkers) {
      list.push_back({{"id", w.id},
                      {"host", w.host},
                      {"state", w.state},
                      {"slots", w.slots},
                      {"busy", w.busy},
                      {"last_seen", w.last_seen}});
    }
  }
  return {{"alive", alive},
          {"slots", slots},
          {"busy", busy},
          {"total", workers.size()},
          {"list", list}};
}

json RunningJson(const std::vector<RunningJobView>& running) {
  json list = json::array();
  for (const auto& j : running) {
    if (list.size() == kMaxListedJobs)
      break;
    list.push_back({{"key", j.key},
                    {"worker", j.worker_id},
                    {"attempt", j.attempt},
                    {"started_at", j.started_at},
                    {"progress", Clip(j.progress, kMaxErrorText)}});
  }
  return list;
}

json FailedJson(const std::vector<FailedJob>& failed) {
  json list = json::array();
  for (const auto& f : failed) {
    if (list.size() == kMaxListedJobs)
      break;
    list.push_back(
        {{"key", f.key}, {"attempts", f.attempts}, {"error", Clip(f.error, kMaxErrorText)}});
  }
  return list;
}

json ArtifactsJson(const std::vector<ArtifactRecord>& artifacts) {
  json list = json::array();
  for (const auto& a : artifacts) {
    if (list.size() == kMaxListedArtifacts)
      break;
    list.push_back({{"id", a.id},
                    {"job", a.job_key},
                    {"scenario", a.scenario},
                    {"label", a.label},
                    {"name", a.name},
                    {"bytes", a.bytes},
                    {"sha256", a.sha256},
                    {"url", "/api/artifacts/" + std::to_string(a.id)}});
  }
  return list;
}

// The scenarios (campaign order) and positioner labels (report order) that have results.
json AxesJson(const std::vector<PositionerSummary>& summary) {
  json scenarios = json::array(), positioners = json::array();
  for (const auto& s : summary) {
    if (scenarios.empty() || scenarios.back() != s.scenario)
      scenarios.push_back(s.scenario);
    if (std::find(positioners.begin(), positioners.end(), s.positioner) == positioners.end())
      positioners.push_back(s.positioner);
  }
  return {{"scenarios", scenarios}, {"positioners", positioners}};
}

}  // namespace

json CampaignListJson(ResultsReader& store, double now) {
  const auto all = store.AllProgress();
  json list = json::array();
  for (const auto& p : all) {
    if (list.size() == kMaxCampaigns)
      break;
    list.push_back(ProgressJson(p, store.Timing(p.campaign_id), now));
  }
  return {{"campaigns", list},
          {"count", all.size()},
          {"truncated", all.size() > kMaxCampaigns},
          {"now", now}};
}

json CampaignDetailJson(ResultsReader& store, const std::string& campaign_id, double now) {
  const CampaignProgress progress = store.Progress(campaign_id);
  json out = ProgressJson(progress, store.Timing(campaign_id), now);
  out["now"] = now;
  out["workers"] = WorkersJson(store.ListWorkers());
  const auto running = store.RunningJobs(campaign_id);
  out["running"] = RunningJson(running);
  out["running_total"] = running.size();
  const auto failed = store.FailedJobs(campaign_id);
  out["failed"] = FailedJson(failed);
  out["failed_total"] = failed.size();
  const auto summary = SummarizeCampaign(store, campaign_id);
  out["summary"] = SummaryToJson(summary);
  out["per_uav"] = UavSummaryToJson(SummarizeUavs(store.UavMetrics(campaign_id)));
  out["optimality"] = OptimalityJson(store, campaign_id);
  out.update(AxesJson(summary));
  const auto artifacts = store.Artifacts(campaign_id);
  out["artifacts"] = ArtifactsJson(artifacts);
  out["artifacts_total"] = artifacts.size();
  out["builds"] = store.CampaignBuilds(campaign_id);
  return out;
}

json OptimalityJson(ResultsReader& store, const std::string& campaign_id) {
  const std::vector<OptimalityRow> rows = store.Optimality(campaign_id);
  json runs = json::array();
  for (const OptimalityRow& r : rows) {
    if (runs.size() == kMaxListedOptimalityRuns)
      break;
    runs.push_back({{"scenario", r.scenario},
                    {"uavs", r.uavs},
                    {"algorithm", r.algorithm},
                    {"train_seed", r.train_seed},
                    {"label", r.label},
                    {"rl_reward", r.rl_reward},
                    {"oracle_reward", r.oracle_reward},
                    {"ratio", OptionalNumber(r.Ratio())},
                    {"placement_s", OptionalNumber(r.placement_s)}});
  }
  json cdf = json::array();
  for (const OptimalityCurve& curve : OptimalityCdf(rows)) {
    json x = json::array(), p = json::array();
    for (std::size_t i : ThinnedIndices(curve.points.size(), kMaxCurvePoints)) {
      x.push_back(curve.points[i].x);
      p.push_back(curve.points[i].p);
    }
    cdf.push_back({{"algorithm", curve.algorithm}, {"uavs", curve.uavs}, {"x", x}, {"p", p}});
  }
  return {{"summary", OptimalityToJson(SummarizeOptimality(rows))},
          {"runs", runs},
          {"runs_total", rows.size()},
          {"cdf", cdf}};
}

}  // namespace rlpos::web
