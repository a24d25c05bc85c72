#include "common/campaign/expansion.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "common/campaign/campaign_id.h"
#include "common/campaign/campaign_request.h"
#include "common/scenario/number_text.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using testing::FindJob;
using testing::MiniCampaign;
using testing::MiniSpec;
using testing::SourcePath;

TEST(CampaignId, Fnv1aKnownValues) {
  EXPECT_EQ(Fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(Fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(Fnv1a64("foobar"), 0x85944171f73967e8ull);
}

TEST(CampaignId, TwelveHexDigitsStableAcrossParses) {
  const std::string id = CampaignId(MiniSpec());
  EXPECT_EQ(id.size(), 12u);
  EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
  EXPECT_EQ(CampaignId(MiniSpec()), id);
}

TEST(CampaignId, ChangesWithEveryInputThatChangesJobs) {
  const CampaignSpec base = MiniSpec();
  const std::string id = CampaignId(base);
  CampaignSpec more_runs = base;
  more_runs.rng_runs.push_back(3);
  EXPECT_NE(CampaignId(more_runs), id);
  CampaignSpec other_set = base;
  other_set.scenarios[0].overrides.push_back("wifi.mode=adhoc");
  EXPECT_NE(CampaignId(other_set), id);
  CampaignSpec other_scenario = base;  // same file name, other content
  other_scenario.scenarios[0].document["wifi"]["tx_power"] = 17;
  EXPECT_NE(CampaignId(other_scenario), id);
  CampaignSpec other_timeout = base;
  other_timeout.job_timeout_s = 301;
  EXPECT_NE(CampaignId(other_timeout), id);
}

TEST(CampaignId, IgnoresTheCheckoutLocation) {
  CampaignSpec moved = MiniSpec();
  for (auto& s : moved.scenarios)
    s.path = "/elsewhere/" + s.file;
  EXPECT_EQ(CampaignId(moved), CampaignId(MiniSpec()));
}

TEST(Expansion, SameCampaignSameJobs) {
  const ExpandedCampaign a = MiniCampaign();
  const ExpandedCampaign b = MiniCampaign();
  ASSERT_EQ(a.jobs.size(), b.jobs.size());
  for (std::size_t i = 0; i < a.jobs.size(); ++i) {
    EXPECT_EQ(a.jobs[i].id, b.jobs[i].id);
    EXPECT_EQ(a.jobs[i].depends_on, b.jobs[i].depends_on);
    EXPECT_EQ(a.jobs[i].label, b.jobs[i].label);
    EXPECT_EQ(ToJson(a.jobs[i].position_rule), ToJson(b.jobs[i].position_rule));
    EXPECT_TRUE(testing::SameParams(a.jobs[i].params, b.jobs[i].params)) << a.jobs[i].key;
  }
  EXPECT_EQ(a.id, CampaignId(MiniSpec()));
  EXPECT_EQ(a.max_attempts, 2);  // retries 1
  EXPECT_DOUBLE_EQ(a.job_timeout_s, 300.0);
}

TEST(Expansion, KeysIdsAndKinds) {
  const ExpandedCampaign c = MiniCampaign();
  std::map<JobKind, int> kinds;
  std::set<std::string> ids;
  for (const auto& job : c.jobs) {
    ++kinds[job.params.kind];
    EXPECT_EQ(job.id, c.id + "/" + job.key);
    EXPECT_TRUE(ids.insert(job.id).second) << "duplicate " << job.id;
  }
  EXPECT_EQ(kinds[JobKind::kTrain], 2);     // B, C x seed 1
  EXPECT_EQ(kinds[JobKind::kPosition], 6);  // B, C x baseline, centroid, oracle
  EXPECT_EQ(kinds[JobKind::kEval], 2 * 2 * 9);
  const Job& train = FindJob(c, "train/B/seed1");
  EXPECT_EQ(train.params.kind, JobKind::kTrain);
  EXPECT_EQ(train.params.train_seed, 1u);
  EXPECT_TRUE(train.depends_on.empty());
  const Job& eval = FindJob(c, "eval/C/offset5/run2");
  EXPECT_EQ(eval.params.scenario, "C");
  EXPECT_EQ(eval.label, "offset5");
  EXPECT_EQ(eval.params.rng_run, 2u);
  EXPECT_EQ(eval.params.train_seed, 1u);
  EXPECT_EQ(eval.position_rule.offset, 5);
  const std::vector<std::string> labels{"baseline", "centroid", "oracle",  "rl",     "offset1",
                                        "offset2",  "offset3",  "offset4", "offset5"};
  for (const auto& label : labels)
    EXPECT_NO_THROW(FindJob(c, "eval/B/" + label + "/run1"));
}

TEST(Expansion, DagEdges) {
  const ExpandedCampaign c = MiniCampaign();
  EXPECT_EQ(FindJob(c, "eval/B/rl/run1").depends_on, c.id + "/train/B/seed1");
  EXPECT_EQ(FindJob(c, "eval/B/offset3/run2").depends_on, c.id + "/train/B/seed1");
  EXPECT_EQ(FindJob(c, "eval/C/baseline/run1").depends_on, c.id + "/position/C/baseline");
  EXPECT_EQ(FindJob(c, "eval/C/oracle/run2").depends_on, c.id + "/position/C/oracle");
  EXPECT_TRUE(FindJob(c, "position/B/centroid").depends_on.empty());
  // Every dependency is a producer listed before its dependents (the store relies on it).
  std::map<std::string, JobKind> seen;
  for (const auto& job : c.jobs) {
    if (job.params.kind == JobKind::kEval) {
      ASSERT_TRUE(seen.count(job.depends_on)) << job.key;
      EXPECT_NE(seen[job.depends_on], JobKind::kEval);
    } else {
      EXPECT_TRUE(job.depends_on.empty());
    }
    seen[job.id] = job.params.kind;
  }
}

TEST(Expansion, TypedParams) {
  const ExpandedCampaign c = MiniCampaign();
  const JobParams& eval = FindJob(c, "eval/B/baseline/run2").params;
  EXPECT_EQ(eval.kind, JobKind::kEval);
  EXPECT_EQ(eval.scenario, "B");
  EXPECT_EQ(eval.rng_run, 2u);
  EXPECT_EQ(eval.duration_s, 2.0);
  EXPECT_EQ(eval.warmup_s, 0.5);
  EXPECT_TRUE(eval.overrides.empty());
  const JobParams& oracle = FindJob(c, "position/B/oracle").params;
  EXPECT_EQ(oracle.kind, JobKind::kPosition);
  EXPECT_EQ(oracle.positioner, "oracle");
  EXPECT_EQ(oracle.duration_s, 2.0);  // the oracle re-scores with the eval settings
  const JobParams& train = FindJob(c, "train/B/seed1").params;
  EXPECT_EQ(train.kind, JobKind::kTrain);
  EXPECT_EQ(train.train_seed, 1u);
  EXPECT_EQ(train.fidelity, "analytic");
  EXPECT_FALSE(train.train_episodes.has_value());
  EXPECT_EQ(train.warmup_s, 0.5);
}

TEST(Expansion, EachKindCarriesOnlyItsFields) {
  CampaignSpec spec = MiniSpec();
  spec.train.episodes = 25;
  const ExpandedCampaign c = ExpandCampaign(spec);
  for (const auto& job : c.jobs) {
    SCOPED_TRACE(job.key);
    const JobParams& p = job.params;
    EXPECT_EQ(job.key.substr(0, job.key.find('/')), ToString(p.kind));
    EXPECT_EQ(p.scenario, job.key.substr(job.key.find('/') + 1, 1));  // B or C
    // Every kind simulates with the campaign's eval settings.
    EXPECT_EQ(p.duration_s, 2.0);
    EXPECT_EQ(p.warmup_s, 0.5);
    switch (p.kind) {
      case JobKind::kTrain:
        EXPECT_TRUE(p.train_seed.has_value());
        EXPECT_EQ(p.fidelity, "analytic");
        EXPECT_EQ(p.train_episodes, 25);
        EXPECT_EQ(p.positioner, "");
        EXPECT_FALSE(p.rng_run.has_value());
        break;
      case JobKind::kPosition:
        EXPECT_EQ(p.positioner, job.label);
        EXPECT_FALSE(p.train_seed.has_value());
        EXPECT_EQ(p.fidelity, "");
        EXPECT_FALSE(p.train_episodes.has_value());
        EXPECT_FALSE(p.rng_run.has_value());
        break;
      case JobKind::kEval: {
        ASSERT_TRUE(p.rng_run.has_value());
        EXPECT_EQ(job.key,
                  "eval/" + p.scenario + "/" + job.label + "/run" + std::to_string(*p.rng_run));
        // The seed of the policy it evaluates; none for a positioner's position.
        const bool from_training = job.depends_on.find("/train/") != std::string::npos;
        EXPECT_EQ(p.train_seed.has_value(), from_training);
        EXPECT_EQ(p.fidelity, "");
        EXPECT_FALSE(p.train_episodes.has_value());
        EXPECT_EQ(p.positioner, "");
        break;
      }
      case JobKind::kTrack:
        ADD_FAILURE() << "a campaign without a track section made a track job";
        break;
    }
  }
}

TEST(Expansion, CampaignWithoutEvalSettingsLeavesThemToTheScenario) {
  CampaignSpec spec = MiniSpec();
  spec.eval.duration.reset();
  spec.eval.warmup.reset();
  const ExpandedCampaign c = ExpandCampaign(spec);
  for (const auto& job : c.jobs) {
    EXPECT_FALSE(job.params.duration_s.has_value()) << job.key;
    EXPECT_FALSE(job.params.warmup_s.has_value()) << job.key;
  }
}

TEST(Expansion, OverridesAndEpisodesAreTyped) {
  CampaignSpec spec = MiniSpec();
  spec.scenarios[0].overrides = {"simulation.duration=5"};
  spec.train.episodes = 25;
  spec.train.fidelity = "packet";
  const ExpandedCampaign c = ExpandCampaign(spec);
  const JobParams& train = FindJob(c, "train/B/seed1").params;
  EXPECT_EQ(train.fidelity, "packet");
  EXPECT_EQ(train.train_episodes, 25);
  const std::vector<ScenarioOverride> set{{"simulation.duration", "5"}};
  EXPECT_EQ(train.overrides, set);
  EXPECT_EQ(train.duration_s, 2.0);  // the override is applied after it, and wins
  EXPECT_EQ(FindJob(c, "eval/B/rl/run1").params.overrides, set);
  EXPECT_EQ(FindJob(c, "position/B/baseline").params.overrides, set);
  EXPECT_TRUE(FindJob(c, "eval/C/rl/run1").params.overrides.empty());
}

TEST(Expansion, SeveralTrainSeeds) {
  CampaignSpec spec = MiniSpec();
  spec.train.seeds = {7, 2};
  const ExpandedCampaign c = ExpandCampaign(spec);
  // The first listed seed keeps the plain labels; the others are suffixed.
  EXPECT_EQ(FindJob(c, "eval/B/rl/run1").depends_on, c.id + "/train/B/seed7");
  EXPECT_EQ(FindJob(c, "eval/B/offset2/run1").params.train_seed, 7u);
  const Job& later = FindJob(c, "eval/B/rl@seed2/run1");
  EXPECT_EQ(later.label, "rl@seed2");
  EXPECT_EQ(later.depends_on, c.id + "/train/B/seed2");
  EXPECT_EQ(FindJob(c, "eval/B/offset4@seed2/run2").position_rule.offset, 4);
  EXPECT_EQ(FindJob(c, "train/B/seed2").label, "rl@seed2");
  EXPECT_EQ(c.jobs.size(), 2u * (3 + 2 + 2 * (3 + 2 * 6)));
}

TEST(Expansion, PositionerSubsets) {
  CampaignSpec spec = MiniSpec();
  spec.positioners = {"baseline"};
  ExpandedCampaign c = ExpandCampaign(spec);
  EXPECT_EQ(c.jobs.size(), 2u * (1 + 2));  // no training without rl/offsets
  EXPECT_THROW(FindJob(c, "train/B/seed1"), std::out_of_range);

  spec.positioners = {"offsets"};
  c = ExpandCampaign(spec);
  EXPECT_EQ(c.jobs.size(), 2u * (1 + 2 * 5));
  EXPECT_NO_THROW(FindJob(c, "train/C/seed1"));
  EXPECT_THROW(FindJob(c, "eval/C/rl/run1"), std::out_of_range);
}

TEST(Expansion, OffsetRulesCarryTheScenarioGeometry) {
  const ExpandedCampaign c = MiniCampaign();
  const PositionRule& rule = FindJob(c, "eval/B/offset1/run1").position_rule;
  EXPECT_EQ(rule.offset, 1);
  EXPECT_DOUBLE_EQ(rule.distance, 10.0);
  // Scenario B: zone x, y in [0, 100], z in [5, 60]; five buildings.
  EXPECT_DOUBLE_EQ(rule.geometry.bounds.zmin, 5.0);
  EXPECT_DOUBLE_EQ(rule.geometry.bounds.zmax, 60.0);
  EXPECT_DOUBLE_EQ(rule.geometry.bounds.xmax, 100.0);
  EXPECT_EQ(rule.geometry.obstacles.size(), 5u);
  EXPECT_EQ(FindJob(c, "eval/B/rl/run1").position_rule.offset, 0);
}

TEST(NumberText, NumbersReadBackExactly) {
  EXPECT_EQ(FormatNumber(50), "50");
  EXPECT_EQ(FormatNumber(44.5), "44.5");
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(-3.25), "-3.25");
  EXPECT_EQ(std::stod(FormatNumber(1.0 / 3.0)), 1.0 / 3.0);
  EXPECT_EQ(FormatPosition({50, 35.5, 10}), "50,35.5,10");
}

}  // namespace
}  // namespace rlpos

namespace rlpos {
namespace {

// The coordinator's job limit counts a submitted campaign's jobs before expanding it, exactly:
// a campaign of exactly the limit passes, one job more is refused with its count.
TEST(SubmitLimits, CountJobsExactlyBeforeExpanding) {
  std::ifstream in(SourcePath("campaigns/scenarios/b.json"));
  const std::string document((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  const std::vector<SubmittedScenario> files{{"b.json", document}};
  for (const std::string positioners : {R"(["baseline"])", R"(["rl"])", R"(["offsets", "oracle"])",
                                        R"(["baseline", "offsets", "centroid", "oracle", "rl"])"}) {
    for (const std::string seeds : {"[1]", "[1, 2, 3]"}) {
      const std::string campaign = R"({"name": "n", "scenarios": ["b.json"], "rng_runs": [1, 7],
        "positioners": )" + positioners +
                                   R"(, "train": {"seeds": )" + seeds + "}}";
      // The count the limit uses must be the number of jobs the store will make.
      const CampaignPlan plan = PlanSubmittedCampaign(campaign, files, {});
      const std::size_t jobs = ExpandCampaign(plan.parsed).jobs.size();
      EXPECT_EQ(plan.JobCount(), jobs) << positioners << " " << seeds;
      SubmitLimits limits;
      limits.max_jobs = jobs;
      EXPECT_EQ(PlanSubmittedCampaign(campaign, files, limits).JobCount(), jobs);
      limits.max_jobs = jobs - 1;
      try {
        PlanSubmittedCampaign(campaign, files, limits);
        ADD_FAILURE() << positioners << " " << seeds << ": not refused";
      } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "the campaign has " + std::to_string(jobs) +
                                             " jobs, more than the coordinator's limit of " +
                                             std::to_string(jobs - 1))
            << positioners << " " << seeds;
      }
    }
  }
}

TEST(Expansion, EachAlgorithmTrainsItsOwnPoliciesUnderItsOwnLabels) {
  CampaignSpec spec = MiniSpec();
  spec.train.seeds = {7, 2};
  spec.train.algorithms = {"dqn", "sac"};
  const ExpandedCampaign c = ExpandCampaign(spec);
  EXPECT_EQ(c.jobs.size(), c.JobCount());
  const Job& sac = FindJob(c, "train/B/sac/seed7");
  EXPECT_EQ(sac.label, "rl@sac");
  // The algorithm reaches the worker as the scenario's own fields, after the entry's "set".
  const std::vector<ScenarioOverride> selects_sac{{"agent.algorithm", "sac"},
                                                  {"env.action_space", "continuous"}};
  EXPECT_EQ(sac.params.overrides, selects_sac);
  EXPECT_EQ(FindJob(c, "train/B/dqn/seed2").label, "rl@dqn@seed2");
  EXPECT_EQ(FindJob(c, "eval/B/rl@sac/run1").depends_on, c.id + "/train/B/sac/seed7");
  EXPECT_EQ(FindJob(c, "eval/B/offset3@dqn@seed2/run2").depends_on, c.id + "/train/B/dqn/seed2");
  EXPECT_TRUE(FindJob(c, "eval/B/rl@sac/run1").params.overrides.empty());
  // Other algorithms' training is other content: no cache hit across them.
  EXPECT_NE(sac.content_base, FindJob(c, "train/B/dqn/seed7").content_base);
  for (const auto& job : c.jobs)
    EXPECT_EQ(job.key.find("/rl/"), std::string::npos) << job.key;  // no plain label left
  EXPECT_EQ(c.jobs.size(), 2u * (3 + 4 + 2 * (3 + 4 * 6)));  // 2 runs, 2 seeds x 2 algorithms
}

TEST(Expansion, NoAlgorithmsKeyKeepsTheCampaignAsItWas) {
  const CampaignSpec plain = MiniSpec();
  EXPECT_EQ(ToJson(plain)["train"].count("algorithms"), 0u);  // so its id is unchanged
  CampaignSpec with = MiniSpec();
  with.train.algorithms = {"dqn"};
  EXPECT_NE(ExpandCampaign(with).id, ExpandCampaign(plain).id);
}

}  // namespace
}  // namespace rlpos
