// An rl positioner that names a policy folder instead of training one: the folder is read,
// checked and packed when the campaign is read; its hash is part of the campaign id and of its
// position job's content; it expands into one position job (positioner rl) per scenario whose
// evals are labelled rl+<name>; and every bad folder is a one-line error naming the JSON path.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/campaign/campaign_id.h"
#include "common/campaign/campaign_request.h"
#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "common/wire/policy_bundle_files.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;
using testing::FindJob;
using testing::SourcePath;
using testing::TempDir;
using testing::WriteFile;

// A folder as `rlpos-sim train` writes it, trained on `scenario_file`.
void WriteTrainedPolicy(const std::string& folder, const std::string& scenario_file,
                        const std::string& weights = "weights") {
  std::filesystem::create_directories(folder);
  WriteFile(folder + "/scenario.json", testing::ReadFile(scenario_file));
  WriteFile(folder + "/result.json", R"({"algorithm": "dqn", "first_episode_run": 1})");
  WriteFile(folder + "/policy.pt", weights);
  WriteFile(folder + "/learning_curve.csv", "episode\n");  // not part of the policy
}

// Campaign file in `dir` over B naming policies/p1 (and more positioners).
std::string WriteCampaign(const TempDir& dir, json positioners) {
  const json campaign = {{"name", "named"},
                         {"scenarios", {SourcePath("campaigns/scenarios/b.json")}},
                         {"rng_runs", {1, 2}},
                         {"positioners", positioners}};
  WriteFile(dir.File("campaign.json"), campaign.dump());
  return dir.File("campaign.json");
}

json NamedP1() {
  return {{"rl", {{"policy", "policies/p1"}}}};
}

TEST(CampaignPolicy, ANamedPolicyIsAPositionJobWithItsOwnLabel) {
  TempDir dir;
  WriteTrainedPolicy(dir.File("policies/p1"), SourcePath("campaigns/scenarios/b.json"));
  const CampaignSpec spec = ReadCampaignFile(WriteCampaign(dir, {"oracle", NamedP1()}));
  EXPECT_EQ(spec.positioners, (std::vector<std::string>{"oracle"}));
  ASSERT_EQ(spec.policies.size(), 1u);
  EXPECT_EQ(spec.policies[0].folder, "policies/p1");
  EXPECT_EQ(spec.policies[0].name, "p1");
  EXPECT_EQ(spec.policies[0].bundle.format, PolicyFormat::kTrained);
  EXPECT_EQ(spec.policies[0].bundle.sha256, ReadPolicyBundle(dir.File("policies/p1")).sha256);
  EXPECT_EQ(ToJson(spec)["policies"][0]["sha256"], spec.policies[0].bundle.sha256);

  const ExpandedCampaign c = ExpandCampaign(spec);
  EXPECT_EQ(c.jobs.size(), c.JobCount());
  EXPECT_EQ(c.jobs.size(), 2u + 2u * 2u);  // oracle and rl+p1: a position job and 2 evals each
  const Job& position = FindJob(c, "position/B/rl+p1");
  EXPECT_EQ(position.label, "rl+p1");
  EXPECT_EQ(position.params.kind, JobKind::kPosition);
  EXPECT_EQ(position.params.positioner, "rl");
  EXPECT_EQ(position.params.policy_sha256, spec.policies[0].bundle.sha256);
  const Job& eval = FindJob(c, "eval/B/rl+p1/run2");
  EXPECT_EQ(eval.label, "rl+p1");
  EXPECT_EQ(eval.depends_on, position.id);
  EXPECT_TRUE(eval.params.policy_sha256.empty());
  for (const Job& job : c.jobs)
    EXPECT_EQ(job.params.kind == JobKind::kTrain, false) << job.key << ": nothing trains";
}

TEST(CampaignPolicy, AnotherPolicyIsAnotherCampaignAndAnotherPlacement) {
  TempDir dir;
  WriteTrainedPolicy(dir.File("policies/p1"), SourcePath("campaigns/scenarios/b.json"));
  const std::string file = WriteCampaign(dir, {"oracle", NamedP1()});
  const ExpandedCampaign before = ExpandCampaign(ReadCampaignFile(file));
  WriteTrainedPolicy(dir.File("policies/p1"), SourcePath("campaigns/scenarios/b.json"),
                     "retrained weights");
  const ExpandedCampaign after = ExpandCampaign(ReadCampaignFile(file));
  EXPECT_NE(after.id, before.id);
  // The policy's placement is never served from another policy's result; the oracle's is.
  EXPECT_NE(FindJob(after, "position/B/rl+p1").content_base,
            FindJob(before, "position/B/rl+p1").content_base);
  EXPECT_EQ(FindJob(after, "position/B/oracle").content_base,
            FindJob(before, "position/B/oracle").content_base);
  // A campaign without policies keeps the id it had before they existed: no "policies" key.
  const CampaignSpec plain = ReadCampaignFile(WriteCampaign(dir, {"oracle"}));
  EXPECT_FALSE(ToJson(plain).contains("policies"));
}

TEST(CampaignPolicy, TheCoordinatorPlansWhatTheClientPacked) {
  TempDir dir;
  WriteTrainedPolicy(dir.File("policies/p1"), SourcePath("campaigns/scenarios/b.json"));
  const json renamed = {{"rl", {{"policy", "policies/p1/"}, {"name", "mine"}}}};
  const CampaignSubmission submission =
      ReadCampaignSubmission(WriteCampaign(dir, {NamedP1(), renamed}));
  ASSERT_EQ(submission.policies.size(), 2u);  // two folder names, one folder
  const CampaignPlan plan = PlanSubmittedCampaign(submission.campaign_json, submission.scenarios,
                                                  submission.policies, SubmitLimits{});
  EXPECT_EQ(plan.id, submission.campaign.id);
  EXPECT_EQ(plan.JobCount(), 2u * (1 + 2));

  std::vector<SubmittedPolicy> tampered = submission.policies;
  tampered[0].files.push_back({"run.sh", "#!/bin/sh"});
  try {
    PlanSubmittedCampaign(submission.campaign_json, submission.scenarios, tampered, {});
    FAIL() << "a bundle with an unknown file was planned";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "policy \"policies/p1\": a policy file that is none of the known names");
  }
  try {
    PlanSubmittedCampaign(submission.campaign_json, submission.scenarios, {}, {});
    FAIL() << "a campaign without its policy was planned";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "campaign: /positioners/0/rl/policy: policy \"policies/p1\" was not sent with the "
              "campaign");
  }
}

// The error ReadCampaignFile gives for a campaign naming `positioner` in `dir`.
std::string ErrorOf(const TempDir& dir, const json& positioner) {
  try {
    ReadCampaignFile(WriteCampaign(dir, {"oracle", positioner}));
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "accepted";
}

TEST(CampaignPolicy, BadFoldersAreOneLineErrorsAtTheirPath) {
  TempDir dir;
  const std::string at = "/positioners/1/rl/policy: ";
  const std::string missing = dir.File("policies/p1");
  EXPECT_EQ(ErrorOf(dir, NamedP1()), at + "policy folder \"" + missing + "\" does not exist");

  std::filesystem::create_directories(missing);
  WriteFile(missing + "/learning_curve.csv", "episode\n");
  EXPECT_NE(ErrorOf(dir, NamedP1()).find(at + "policy folder \"" + missing + "\" holds no policy"),
            std::string::npos);

  WriteFile(missing + "/policy.json", "{\"format\": ");
  WriteFile(missing + "/model.pt", "zip");
  WriteFile(missing + "/scenario.json",
            testing::ReadFile(SourcePath("campaigns/scenarios/b.json")));
  EXPECT_EQ(ErrorOf(dir, NamedP1()), at + "policy folder \"policies/p1\": policy.json is not JSON");
  WriteFile(missing + "/policy.json", "{\"format\": \"onnx\"}");
  EXPECT_EQ(ErrorOf(dir, NamedP1()),
            at + "policy folder \"policies/p1\": policy.json: /format: expected \"torchscript\"");
  std::filesystem::remove_all(missing);

  WriteTrainedPolicy(missing, SourcePath("campaigns/scenarios/b.json"));
  WriteFile(missing + "/policy.pt", std::string(kMaxPolicyBytes, 'w'));
  EXPECT_EQ(ErrorOf(dir, NamedP1()), at + "policy folder \"" + missing +
                                         "\" holds more than 16777216 bytes of policy files");

  WriteTrainedPolicy(missing, SourcePath("campaigns/scenarios/c.json"));
  const std::string error = ErrorOf(dir, NamedP1());
  EXPECT_EQ(
      error.rfind(at + "policy \"policies/p1\" (trained on C) does not fit /scenarios/0 (", 0), 0u)
      << error;

  WriteTrainedPolicy(missing, SourcePath("campaigns/scenarios/b.json"));
  EXPECT_EQ(ErrorOf(dir, NamedP1()), "accepted");
  EXPECT_EQ(ErrorOf(dir, {{"rl", {{"policy", "policies/p1"}, {"nmae", "x"}}}}),
            "/positioners/1/rl/nmae: unknown key \"nmae\"; did you mean \"name\"?");
  EXPECT_EQ(ErrorOf(dir, {{"rl", {{"policy", "policies/p1"}, {"name", "a/b"}}}}),
            "/positioners/1/rl/name: policy name \"a/b\" must be 1-64 of [A-Za-z0-9._@+-]; give "
            "one with \"name\"");
  try {
    ReadCampaignFile(WriteCampaign(dir, {NamedP1(), NamedP1()}));
    FAIL() << "two policies under one name";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(),
              "/positioners/1: policy name \"p1\" is already used; give another "
              "with \"name\"");
  }
}

// A policy for any scenario (rlpos-sim train --generated) fits any campaign scenario that has a
// UAV count it was trained for and restates its env settings, not changes them.
TEST(CampaignPolicy, APolicyForAnyScenarioFitsOtherScenariosWithinItsUavCounts) {
  TempDir dir;
  const std::string folder = dir.File("policies/p1");
  const auto general = [&](const std::string& uavs) {
    WriteTrainedPolicy(folder, SourcePath("campaigns/scenarios/c.json"));
    WriteFile(folder + "/result.json",
              R"({"algorithm": "ppo", "first_episode_run": 1, "general": true,
                  "training": {"uavs": )" + uavs + "}}");
  };
  // Trained "on" C's settings, it places UAVs in B.
  general("[1, 3]");
  EXPECT_EQ(ErrorOf(dir, NamedP1()), "accepted");
  // B has one UAV.
  general("[2, 3]");
  EXPECT_EQ(ErrorOf(dir, NamedP1()),
            "/positioners/1/rl/policy: policy \"policies/p1\" (trained on C) does not fit "
            "/scenarios/0 (" +
                SourcePath("campaigns/scenarios/b.json") +
                "): /uavs: 1 UAVs in the scenario, 2-3 in the policy");
  general("[3, 2]");
  EXPECT_NE(ErrorOf(dir, NamedP1()).find("/training/uavs: expected [min, max] UAV counts"),
            std::string::npos);
  // The same folder without "general" is C's policy: B contradicts it.
  WriteTrainedPolicy(folder, SourcePath("campaigns/scenarios/c.json"));
  EXPECT_NE(ErrorOf(dir, NamedP1()).find("(trained on C) does not fit"), std::string::npos);
}

}  // namespace
}  // namespace rlpos
