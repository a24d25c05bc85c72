// A job's settings reach its scenario one way, with one precedence: the scenario document, its
// campaign entry's "set", a train job's algorithm overrides, then the settings the campaign fixes
// for the job (train seed, fidelity and episodes, eval duration and warm-up, RngRun). A "set"
// entry that gives one of those another value is refused when the campaign is read.
#include <gtest/gtest.h>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "common/wire/job_order.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;
using testing::SourcePath;

// A campaign over the shipped scenario B whose entry has `set`, with `extra` fields.
json CampaignWithSet(const std::vector<std::string>& set, const json& extra = json::object()) {
  json campaign = {
      {"name", "t"},
      {"scenarios", {{{"file", SourcePath("campaigns/scenarios/b.json")}, {"set", set}}}},
      {"rng_runs", {1, 2}}};
  campaign.update(extra);
  return campaign;
}

// The one-line error ParseCampaign gives, or "" when it accepts the campaign.
std::string Refusal(const json& campaign) {
  try {
    ParseCampaign(campaign, ".");
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

void ExpectRefusal(const json& campaign, const std::string& set_entry,
                   const std::string& campaign_field) {
  const std::string error = Refusal(campaign);
  EXPECT_EQ(error.find(set_entry), 0u) << error;
  EXPECT_NE(error.find(campaign_field), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(JobSettings, ASetThatContradictsTheCampaignsFidelityIsRefused) {
  // train.fidelity defaults to analytic; the train jobs of rl would run it.
  ExpectRefusal(CampaignWithSet({"wifi.mode=adhoc", "env.fidelity=packet"}), "/scenarios/0/set/1",
                "/train/fidelity");
  ExpectRefusal(CampaignWithSet({"/env/fidelity=analytic"}, {{"train", {{"fidelity", "packet"}}}}),
                "/scenarios/0/set/0", "/train/fidelity");
  // A parent object that holds the setting is the same contradiction.
  ExpectRefusal(CampaignWithSet({"env={\"fidelity\": \"packet\"}"}), "/scenarios/0/set/0",
                "/train/fidelity");
}

TEST(JobSettings, EverySettingTheCampaignFixesIsGuarded) {
  ExpectRefusal(CampaignWithSet({"agent.train_episodes=7"}, {{"train", {{"episodes", 8}}}}),
                "/scenarios/0/set/0", "/train/episodes");
  ExpectRefusal(CampaignWithSet({"agent.seed=1"}, {{"train", {{"seeds", {1, 2}}}}}),
                "/scenarios/0/set/0", "/train/seeds");
  ExpectRefusal(CampaignWithSet({"simulation.run=1"}), "/scenarios/0/set/0", "/rng_runs");
  ExpectRefusal(CampaignWithSet({"simulation.duration=4"}, {{"eval", {{"duration", 3}}}}),
                "/scenarios/0/set/0", "/eval/duration");
  ExpectRefusal(CampaignWithSet({"simulation.warmup=0.25"}, {{"eval", {{"warmup", 0.5}}}}),
                "/scenarios/0/set/0", "/eval/warmup");
  ExpectRefusal(CampaignWithSet({"agent.algorithm=dqn"}, {{"train", {{"algorithms", {"ppo"}}}}}),
                "/scenarios/0/set/0", "/train/algorithms");
}

TEST(JobSettings, ASetThatAgreesOrThatTheCampaignLeavesOpenIsAccepted) {
  // The same value as the campaign's: no contradiction.
  EXPECT_EQ(Refusal(CampaignWithSet({"env.fidelity=analytic", "agent.seed=1"})), "");
  // No train job (no rl, no offsets): nothing fixes the fidelity.
  EXPECT_EQ(Refusal(CampaignWithSet({"env.fidelity=packet"}, {{"positioners", {"baseline"}}})), "");
  // The campaign leaves episodes and the eval duration to the scenario: "set" decides.
  EXPECT_EQ(Refusal(CampaignWithSet({"agent.train_episodes=7", "simulation.duration=4"})), "");
  // One RngRun and the same run in "set".
  EXPECT_EQ(Refusal(CampaignWithSet({"simulation.run=2"}, {{"rng_runs", {2, 2}}})), "");
}

// What each job's scenario holds, as the worker makes it from the job.
json TrainDocument(const ExpandedCampaign& campaign, const std::string& key) {
  const Job& job = testing::FindJob(campaign, key);
  return EffectiveScenarioDocument(campaign.parsed.scenarios[0].document, job.params);
}

TEST(JobSettings, EveryJobSettingIsInTheScenarioTheWorkerWrites) {
  const ExpandedCampaign campaign = ExpandCampaign(ParseCampaign(
      CampaignWithSet(
          {"agent.train_episodes=7", "simulation.duration=4"},
          {{"train", {{"seeds", {3}}, {"fidelity", "packet"}}}, {"eval", {{"warmup", 0.75}}}}),
      "."));
  const json train = TrainDocument(campaign, "train/B/seed3");
  // The campaign's settings and the "set" it leaves open, all in the document: no flag of the
  // command line changes them afterwards.
  EXPECT_EQ(train["env"]["fidelity"], "packet");
  EXPECT_EQ(train["agent"]["seed"], 3);
  EXPECT_EQ(train["agent"]["train_episodes"], 7);
  EXPECT_EQ(train["simulation"]["duration"], 4);
  EXPECT_EQ(train["simulation"]["warmup"], 0.75);
  const json eval = TrainDocument(campaign, "eval/B/rl/run2");
  EXPECT_EQ(eval["simulation"]["run"], 2);
  EXPECT_EQ(eval["simulation"]["warmup"], 0.75);
}

}  // namespace
}  // namespace rlpos
