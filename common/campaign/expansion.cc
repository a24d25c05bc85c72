#include "campaign/expansion.h"

#include "campaign/campaign_id.h"
#include "campaign/job_argv.h"

namespace rlpos {
namespace {

void AppendOverrides(std::vector<std::string>& argv, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) {
    argv.push_back("--set");
    argv.push_back(o);
  }
}

std::vector<std::string> TrainArgv(const CampaignSpec& spec, const CampaignScenario& s,
                                   std::uint64_t seed) {
  std::vector<std::string> argv{kSimBinary, "train",        "--scenario", s.path,
                                "--seed",   std::to_string(seed), "--fidelity", spec.train.fidelity,
                                "--out",    kOutDirPlaceholder,   "--json"};
  if (spec.train.episodes) {
    AppendOverrides(argv, {"agent.train_episodes=" + std::to_string(*spec.train.episodes)});
  }
  // The scenario as the campaign validated it (a packet-level env simulates with these too).
  AppendOverrides(argv, EvalOverrides(spec.eval));
  AppendOverrides(argv, s.overrides);
  return argv;
}

std::vector<std::string> PositionArgv(const CampaignSpec& spec, const CampaignScenario& s,
                                      const std::string& positioner) {
  std::vector<std::string> argv{kSimBinary,     "position", "--scenario", s.path,
                                "--positioner", positioner, "--json"};
  // The oracle re-scores its best positions at packet level with the eval settings.
  AppendOverrides(argv, EvalOverrides(spec.eval));
  AppendOverrides(argv, s.overrides);
  return argv;
}

std::vector<std::string> EvalArgv(const CampaignSpec& spec, const CampaignScenario& s,
                                  std::uint64_t run) {
  std::vector<std::string> argv{kSimBinary, "eval",  "--scenario", s.path, "--position",
                                kPositionPlaceholder, "--run", std::to_string(run)};
  if (spec.eval.duration) {
    argv.push_back("--duration");
    argv.push_back(FormatNumber(*spec.eval.duration));
  }
  argv.push_back("--json");
  argv.push_back("--no-progress");
  // Campaign settings first, the scenario's own overrides last: on the rlpos-sim command line a
  // later --set wins, and the scenario entry is the more specific of the two.
  if (spec.eval.warmup) {
    AppendOverrides(argv, {"simulation.warmup=" + FormatNumber(*spec.eval.warmup)});
  }
  AppendOverrides(argv, s.overrides);
  return argv;
}

// One eval label and where its position comes from.
struct EvalSource {
  std::string label;
  std::string depends_on_key;
  std::optional<std::uint64_t> train_seed;
  PositionRule rule;
};

}  // namespace

std::string EvalLabel(int k, std::size_t seed_index, std::uint64_t seed) {
  std::string label = k == 0 ? "rl" : "offset" + std::to_string(k);
  if (seed_index > 0) label += "@seed" + std::to_string(seed);
  return label;
}

ExpandedCampaign ExpandCampaign(const CampaignSpec& spec) {
  ExpandedCampaign out;
  out.id = CampaignId(spec);
  out.name = spec.name;
  out.spec = ToJson(spec);
  out.max_attempts = 1 + spec.retries;
  out.job_timeout_s = spec.job_timeout_s;

  const auto add = [&out](Job job) {
    job.id = JobId(out.id, job.key);
    out.jobs.push_back(std::move(job));
  };

  for (const auto& s : spec.scenarios) {
    const std::string& name = s.scenario.name;
    std::vector<EvalSource> sources;

    for (const char* positioner : {"baseline", "centroid", "oracle"}) {
      if (!spec.Uses(positioner)) continue;
      Job job;
      job.kind = JobKind::kPosition;
      job.key = "position/" + name + "/" + positioner;
      job.scenario = name;
      job.label = positioner;
      job.argv = PositionArgv(spec, s, positioner);
      sources.push_back({positioner, job.key, std::nullopt, {}});
      add(std::move(job));
    }

    if (spec.NeedsTraining()) {
      const OffsetGeometry geometry = OffsetGeometryOf(s.scenario);
      for (std::size_t i = 0; i < spec.train.seeds.size(); ++i) {
        const std::uint64_t seed = spec.train.seeds[i];
        Job job;
        job.kind = JobKind::kTrain;
        job.key = "train/" + name + "/seed" + std::to_string(seed);
        job.scenario = name;
        job.label = EvalLabel(0, i, seed);
        job.train_seed = seed;
        job.argv = TrainArgv(spec, s, seed);
        if (spec.Uses("rl")) sources.push_back({EvalLabel(0, i, seed), job.key, seed, {}});
        if (spec.Uses("offsets")) {
          for (int k = 1; k <= kOffsetCount; ++k) {
            PositionRule rule;
            rule.offset = k;
            rule.geometry = geometry;
            sources.push_back({EvalLabel(k, i, seed), job.key, seed, rule});
          }
        }
        add(std::move(job));
      }
    }

    for (const std::uint64_t run : spec.rng_runs) {
      for (const auto& source : sources) {
        Job job;
        job.kind = JobKind::kEval;
        job.key = "eval/" + name + "/" + source.label + "/run" + std::to_string(run);
        job.scenario = name;
        job.label = source.label;
        job.rng_run = run;
        job.train_seed = source.train_seed;
        job.depends_on = JobId(out.id, source.depends_on_key);
        job.position = source.rule;
        job.argv = EvalArgv(spec, s, run);
        add(std::move(job));
      }
    }
  }
  return out;
}

}  // namespace rlpos
