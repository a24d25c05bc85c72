#pragma once
// Campaign -> jobs, deterministically: the same campaign gives the same jobs, ids and order.
//
// Per scenario (in campaign order):
//   train/<scenario>/seed<N>            one per train seed, if "rl" or "offsets" is selected
//                                       (offsets only for a single-UAV scenario: they are
//                                       defined around one UAV, so one of several has none)
//   position/<scenario>/<positioner>    baseline, centroid, oracle (those selected)
//   position/<scenario>/rl+<name>       per named policy: its placement (positioner "rl" with
//                                       the policy's sha256)
//   eval/<scenario>/<label>/run<R>      per RngRun, per label, depending on the job giving the
//                                       position: baseline|centroid|oracle and rl+<name> on
//                                       their position job;
//                                       rl and offset1..offset5 on the train job.
//   track/<scenario>/<positioner>/run<R> per track positioner and RngRun (a "track" section):
//                                       a run in which the UEs walk and the UAVs follow; no
//                                       dependency.
// Several train seeds: every seed gets its own rl/offset evals. The first seed's labels are the
// plain "rl", "offset1".."offset5" (the paper's curves); later seeds' carry "@seed<N>"
// ("rl@seed2", "offset3@seed2"), so adding a seed never renames the first seed's results.
// With train.algorithms, each algorithm trains its own seeds (train/<scenario>/<algorithm>/
// seed<N>, with the algorithm's overrides) and its labels carry "@<algorithm>" before any
// seed: "rl@ppo", "offset2@sac", "rl@dqn@seed2".
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/campaign/campaign_spec.h"
#include "common/job/job.h"

namespace rlpos {

// A campaign ready to store: its settings, and its jobs made one at a time from its spec, so
// that a campaign of 100k jobs is never held in memory whole.
struct CampaignPlan {
  std::string id;
  std::string name;
  std::string spec_json;  // ToJson(CampaignSpec).dump(): what the id hashes
  int max_attempts = 3;   // 1 + retries
  double job_timeout_s = 600.0;
  // Jobs may take the result of a succeeded job of the same content (any campaign) instead of
  // running; false: every job runs (`--no-cache`).
  bool use_cache = true;
  CampaignSpec parsed;  // what the jobs are made from

  // How many jobs ForEachJob makes, counted without making them.
  std::size_t JobCount() const;
  // Every job in order: each dependency comes before its dependents.
  void ForEachJob(const std::function<void(Job&&)>& emit) const;
};

CampaignPlan PlanCampaign(CampaignSpec spec);

// A plan with its jobs in memory, for tests that look at them; the daemons and the CLI stream.
struct ExpandedCampaign : CampaignPlan {
  std::vector<Job> jobs;
};

ExpandedCampaign ExpandCampaign(const CampaignSpec& spec);

// Refuses a scenario's "set" entry that gives a setting the campaign fixes for one of the
// scenario's jobs (job/job_settings.h: train seed, fidelity, episodes and algorithm, eval
// duration and warm-up, RngRun) another value. ParseCampaign calls it. Throws ConfigError at
// the entry ("/scenarios/0/set/1"), naming the campaign's field.
void CheckJobSettings(const CampaignSpec& spec);

// The eval label of offset position k (1..5) or of "rl" (k = 0) for the seed at `seed_index`
// of `algorithm` ("": the scenario's own, no suffix).
std::string EvalLabel(int k, const std::string& algorithm, std::size_t seed_index,
                      std::uint64_t seed);

}  // namespace rlpos
