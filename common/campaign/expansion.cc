#include "common/campaign/expansion.h"

#include <algorithm>
#include <map>

#include "common/campaign/campaign_id.h"
#include "common/campaign/job_content.h"
#include "common/config/config_error.h"
#include "common/hash/sha256.h"
#include "common/job/job_settings.h"
#include "common/job/offsets.h"
#include "common/provenance/provenance.h"
#include "common/scenario/names.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

std::vector<ScenarioOverride> Overrides(const CampaignScenario& s) {
  std::vector<ScenarioOverride> out;
  for (const auto& text : s.overrides)
    out.push_back(ParseOverride(text));
  return out;
}

// The settings every job of a scenario shares: the campaign's eval settings (a packet-level env
// and the oracle's re-scoring simulate with them too) and the scenario entry's overrides.
JobParams ScenarioParams(const CampaignSpec& spec, const CampaignScenario& s, JobKind kind) {
  JobParams p;
  p.kind = kind;
  p.scenario = s.scenario.name;
  p.duration_s = spec.eval.duration;
  p.warmup_s = spec.eval.warmup;
  p.overrides = Overrides(s);
  return p;
}

// A train job's: the campaign's train settings; after the scenario's "set", the algorithm's
// overrides ("": the scenario's own agent.algorithm).
JobParams TrainParams(const CampaignSpec& spec, const CampaignScenario& s,
                      const std::string& algorithm, std::uint64_t seed) {
  JobParams p = ScenarioParams(spec, s, JobKind::kTrain);
  p.train_seed = seed;
  p.fidelity = spec.train.fidelity;
  p.train_episodes = spec.train.episodes;
  if (!algorithm.empty()) {
    for (const auto& text : AlgorithmOverrides(algorithm))
      p.overrides.push_back(ParseOverride(text));
  }
  return p;
}

JobParams EvalParams(const CampaignSpec& spec, const CampaignScenario& s, std::uint64_t run) {
  JobParams p = ScenarioParams(spec, s, JobKind::kEval);
  p.rng_run = run;
  return p;
}

// A track job's: the track section's duration and fidelity, the run, the positioner.
JobParams TrackParams(const CampaignSpec& spec, const CampaignScenario& s,
                      const std::string& positioner, std::uint64_t run) {
  JobParams p = ScenarioParams(spec, s, JobKind::kTrack);
  p.duration_s = spec.track.duration;
  p.fidelity = spec.track.fidelity;
  p.positioner = positioner;
  p.rng_run = run;
  return p;
}

// "" trains with the scenario's own agent.algorithm, under the plain labels.
std::vector<std::string> TrainAlgorithms(const CampaignSpec& spec) {
  std::vector<std::string> algorithms = spec.train.algorithms;
  if (algorithms.empty())
    algorithms.push_back("");
  return algorithms;
}

// Where the campaign fixes the setting of a JobParams field of a job of `kind`.
std::string CampaignFieldOf(const std::string& field, JobKind kind) {
  if (kind == JobKind::kTrack && field == "duration_s")
    return "/track/duration";
  if (kind == JobKind::kTrack && field == "fidelity")
    return "/track/fidelity";
  static const std::map<std::string, std::string> fields{
      {"train_seed", "/train/seeds"},        {"fidelity", "/train/fidelity"},
      {"train_episodes", "/train/episodes"}, {"rng_run", "/rng_runs"},
      {"duration_s", "/eval/duration"},      {"warmup_s", "/eval/warmup"}};
  const auto it = fields.find(field);
  return it == fields.end() ? field : it->second;
}

// One eval label and where its position comes from.
struct EvalSource {
  std::string label;
  std::string depends_on_key;
  std::optional<std::uint64_t> train_seed;
  PositionRule rule;
};

// Offsets (the paper's positions 1-5 around the RL position) are defined around one UAV: a
// scenario of several gets none.
bool UsesOffsets(const CampaignSpec& spec, const CampaignScenario& s) {
  return spec.Uses("offsets") && s.scenario.uavs.size() == 1;
}

bool NeedsTraining(const CampaignSpec& spec, const CampaignScenario& s) {
  return spec.Uses("rl") || UsesOffsets(spec, s);
}

// Position jobs of a scenario, one per selected positioner that gives a position and one per
// named policy.
std::size_t PositionJobs(const CampaignSpec& spec) {
  std::size_t producers =
      static_cast<std::size_t>(std::count_if(spec.policies.begin(), spec.policies.end(),
                                             [](const CampaignPolicy& p) { return p.placed; }));
  for (std::string_view positioner : kPlacingPositioners)
    producers += spec.Uses(std::string(positioner)) ? 1 : 0;
  return producers;
}

}  // namespace

void CheckJobSettings(const CampaignSpec& spec) {
  for (std::size_t i = 0; i < spec.scenarios.size(); ++i) {
    const CampaignScenario& s = spec.scenarios[i];
    if (s.overrides.empty())
      continue;
    // Every setting the campaign fixes for a job of this scenario, and where it fixes it.
    std::vector<ScenarioOverride> fixed;
    std::vector<std::string> where;
    const auto add = [&](const JobParams& p) {
      for (const auto& setting : JobSettings(p)) {
        fixed.push_back(setting.setting);
        where.push_back(CampaignFieldOf(setting.field, p.kind));
      }
      for (std::size_t k = s.overrides.size(); k < p.overrides.size(); ++k) {
        fixed.push_back(p.overrides[k]);
        where.push_back("/train/algorithms");
      }
    };
    if (NeedsTraining(spec, s)) {
      for (const std::string& algorithm : TrainAlgorithms(spec)) {
        for (const std::uint64_t seed : spec.train.seeds)
          add(TrainParams(spec, s, algorithm, seed));
      }
    }
    // Position jobs' settings are every eval's too.
    if (NeedsTraining(spec, s) || PositionJobs(spec) > 0) {
      for (const std::uint64_t run : spec.rng_runs)
        add(EvalParams(spec, s, run));
    }
    for (const std::string& positioner : spec.track.positioners) {
      for (const std::uint64_t run : spec.rng_runs)
        add(TrackParams(spec, s, positioner, run));
    }
    for (const CampaignPolicy& policy : spec.policies) {
      if (!policy.tracked)
        continue;
      for (const std::uint64_t run : spec.rng_runs) {
        JobParams p = TrackParams(spec, s, "rl", run);
        p.policy_sha256 = policy.bundle.sha256;
        add(p);
      }
    }
    if (const auto c = FindContradiction(Overrides(s), fixed)) {
      const std::size_t k = c->override_index;
      throw ConfigError("/scenarios/" + std::to_string(i) + "/set/" + std::to_string(k),
                        "\"" + s.overrides[k] + "\" contradicts " + where[c->setting_index] + " (" +
                            ToString(fixed[c->setting_index]) + "); keep one of them");
    }
  }
}

std::string EvalLabel(int k, const std::string& algorithm, std::size_t seed_index,
                      std::uint64_t seed) {
  std::string label = k == 0 ? "rl" : "offset" + std::to_string(k);
  if (!algorithm.empty())
    label += "@" + algorithm;
  if (seed_index > 0)
    label += "@seed" + std::to_string(seed);
  return label;
}

CampaignPlan PlanCampaign(CampaignSpec spec) {
  CampaignPlan out;
  // Text, not a JSON tree: a spec lists every RngRun, and 100k of them as a tree are megabytes.
  out.spec_json = ToJsonText(spec);
  out.id = CampaignIdOfSpecText(out.spec_json);
  out.name = spec.name;
  out.max_attempts = 1 + spec.retries;
  out.job_timeout_s = spec.job_timeout_s;
  out.parsed = std::move(spec);
  return out;
}

std::size_t CampaignPlan::JobCount() const {
  const CampaignSpec& spec = parsed;
  const std::size_t producers = PositionJobs(spec);
  const std::size_t seeds =
      spec.train.seeds.size() * std::max<std::size_t>(1, spec.train.algorithms.size());
  std::size_t count = 0;
  for (const auto& s : spec.scenarios) {
    const std::size_t trains = NeedsTraining(spec, s) ? seeds : 0;
    const std::size_t labels = producers + trains * ((spec.Uses("rl") ? 1 : 0) +
                                                     (UsesOffsets(spec, s) ? kOffsetCount : 0));
    count += producers + trains + labels * spec.rng_runs.size();
    const auto tracked =
        static_cast<std::size_t>(std::count_if(spec.policies.begin(), spec.policies.end(),
                                               [](const CampaignPolicy& p) { return p.tracked; }));
    count += (spec.track.positioners.size() + tracked) * spec.rng_runs.size();
  }
  return count;
}

namespace {

// One scenario's jobs in ForEachJob's order, each handed to `add` (which gives it its id and
// content): its position jobs and train jobs, the evals of the positions they give, its track
// runs.
class ScenarioJobMaker {
 public:
  ScenarioJobMaker(const CampaignSpec& spec, const CampaignScenario& s,
                   const std::string& campaign_id, const std::function<void(Job)>& add)
      : spec_(spec), s_(s), name_(s.scenario.name), campaign_id_(campaign_id), add_(add) {}

  void MakeAll() {
    MakePositionJobs();
    if (NeedsTraining(spec_, s_))
      MakeTrainJobs();
    MakeEvalJobs();
    MakeTrackJobs();
  }

 private:
  // A position job, whose placement the label's evals take.
  void AddPosition(const std::string& label, JobParams params) {
    Job job;
    job.key = "position/" + name_ + "/" + label;
    job.label = label;
    job.params = std::move(params);
    sources_.push_back({label, job.key, std::nullopt, {}});
    add_(std::move(job));
  }

  void MakePositionJobs() {
    for (std::string_view placing : kPlacingPositioners) {
      const std::string positioner(placing);
      if (!spec_.Uses(positioner))
        continue;
      JobParams params = ScenarioParams(spec_, s_, JobKind::kPosition);
      params.positioner = positioner;
      AddPosition(positioner, std::move(params));
    }
    // A named policy places the UAVs as a position job: `position --positioner rl --policy`.
    for (const CampaignPolicy& policy : spec_.policies) {
      if (!policy.placed)
        continue;
      JobParams params = ScenarioParams(spec_, s_, JobKind::kPosition);
      params.positioner = "rl";
      params.policy_sha256 = policy.bundle.sha256;
      AddPosition(PolicyLabel(policy.name), std::move(params));
    }
  }

  void MakeTrainJobs() {
    const OffsetGeometry geometry = OffsetGeometryOf(s_.scenario);
    for (const std::string& algorithm : TrainAlgorithms(spec_)) {
      for (std::size_t i = 0; i < spec_.train.seeds.size(); ++i)
        MakeTrainJob(algorithm, i, geometry);
    }
  }

  // The train job of the seed at `seed_index`, whose policy the rl and offset evals take.
  void MakeTrainJob(const std::string& algorithm, std::size_t seed_index,
                    const OffsetGeometry& geometry) {
    const std::uint64_t seed = spec_.train.seeds[seed_index];
    Job job;
    job.key = "train/" + name_ + "/" + (algorithm.empty() ? "" : algorithm + "/") + "seed" +
              std::to_string(seed);
    job.label = EvalLabel(0, algorithm, seed_index, seed);
    job.params = TrainParams(spec_, s_, algorithm, seed);
    if (spec_.Uses("rl"))
      sources_.push_back({EvalLabel(0, algorithm, seed_index, seed), job.key, seed, {}});
    if (UsesOffsets(spec_, s_)) {
      for (int k = 1; k <= kOffsetCount; ++k) {
        PositionRule rule;
        rule.offset = k;
        rule.geometry = geometry;
        sources_.push_back({EvalLabel(k, algorithm, seed_index, seed), job.key, seed, rule});
      }
    }
    add_(std::move(job));
  }

  void MakeEvalJobs() {
    for (const std::uint64_t run : spec_.rng_runs) {
      for (const auto& source : sources_) {
        Job job;
        job.key = "eval/" + name_ + "/" + source.label + "/run" + std::to_string(run);
        job.label = source.label;
        job.depends_on = JobId(campaign_id_, source.depends_on_key);
        job.position_rule = source.rule;
        job.params = EvalParams(spec_, s_, run);
        job.params.train_seed = source.train_seed;
        add_(std::move(job));
      }
    }
  }

  // Track runs depend on no job: each decides its own placements as the UEs walk.
  void AddTrack(const std::string& label, JobParams params, std::uint64_t run) {
    Job job;
    job.key = "track/" + name_ + "/" + label + "/run" + std::to_string(run);
    job.label = label;
    job.params = std::move(params);
    add_(std::move(job));
  }

  void MakeTrackJobs() {
    for (const std::string& positioner : spec_.track.positioners) {
      for (const std::uint64_t run : spec_.rng_runs)
        AddTrack(positioner, TrackParams(spec_, s_, positioner, run), run);
    }
    for (const CampaignPolicy& policy : spec_.policies) {
      if (!policy.tracked)
        continue;
      for (const std::uint64_t run : spec_.rng_runs) {
        JobParams params = TrackParams(spec_, s_, "rl", run);
        params.policy_sha256 = policy.bundle.sha256;
        AddTrack(PolicyLabel(policy.name), std::move(params), run);
      }
    }
  }

  const CampaignSpec& spec_;
  const CampaignScenario& s_;
  const std::string& name_;
  const std::string& campaign_id_;
  const std::function<void(Job)>& add_;
  std::vector<EvalSource> sources_;  // the eval labels of the jobs made so far
};

}  // namespace

void CampaignPlan::ForEachJob(const std::function<void(Job&&)>& emit) const {
  const std::string build = ThisBuild().rlpos_version;
  for (const auto& s : parsed.scenarios) {
    const std::string scenario_sha256 = Sha256Hex(s.document.dump());
    const std::function<void(Job)> add = [&](Job job) {
      job.id = JobId(id, job.key);
      job.content_base = JobContentBase(job.params, scenario_sha256, build);
      emit(std::move(job));
    };
    ScenarioJobMaker(parsed, s, id, add).MakeAll();
  }
}

ExpandedCampaign ExpandCampaign(const CampaignSpec& spec) {
  ExpandedCampaign out;
  static_cast<CampaignPlan&>(out) = PlanCampaign(spec);
  out.jobs.reserve(out.JobCount());
  out.ForEachJob([&](Job&& job) { out.jobs.push_back(std::move(job)); });
  return out;
}

}  // namespace rlpos
