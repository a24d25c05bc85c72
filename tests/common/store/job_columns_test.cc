// The jobs table holds every field common/job/job_fields.h declares: a campaign whose jobs set
// each field of their kind is stored, and each job read back has the same value in every field
// as the job the expansion made. A field declared there but left out of the store's columns
// (common/store/job_rows.h) fails here, as it fails the content hash's and the wire's tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/job/job_fields.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

using nlohmann::json;

// Train jobs with seeds, fidelity and episodes, position jobs of a named policy, evals with
// their RngRun, every kind with a duration, a warm-up and overrides.
ExpandedCampaign EveryField(const testing::TempDir& dir) {
  const std::string folder = dir.File("policies/p1");
  std::filesystem::create_directories(folder);
  // The policy's scenario is B with the campaign's override: it fits.
  json trained_on =
      json::parse(testing::ReadFile(testing::SourcePath("campaigns/scenarios/b.json")));
  trained_on["wifi"]["width"] = 40;
  testing::WriteFile(folder + "/scenario.json", trained_on.dump());
  testing::WriteFile(folder + "/result.json", R"({"algorithm": "dqn"})");
  testing::WriteFile(folder + "/policy.pt", "weights");
  const json document = {
      {"name", "every-field"},
      {"scenarios", {{{"file", "scenarios/b.json"}, {"set", {"wifi.width=40"}}}}},
      {"rng_runs", {3, 4}},
      {"positioners", {"oracle", "rl", {{"rl", {{"policy", "policies/p1"}}}}}},
      {"train", {{"seeds", {7}}, {"fidelity", "analytic"}, {"episodes", 12}}},
      {"eval", {{"duration", 3}, {"warmup", 0.5}}}};
  return ExpandCampaign(ParseCampaign(document,
                                      FileScenarioSource(testing::SourcePath("campaigns")),
                                      FilePolicySource(dir.path())));
}

TEST(StoreJobColumns, EveryDeclaredJobFieldIsStoredAndReadBack) {
  testing::TempDir dir;
  const ExpandedCampaign campaign = EveryField(dir);
  CoordinatorStore store(dir.File("rlpos.db"));
  store.ledger.Submit(campaign);
  std::set<std::string> seen;  // fields some job carried with a value
  for (const Job& job : campaign.jobs) {
    const auto stored = store.reader.GetJob(campaign.id + "/" + job.key);
    ASSERT_TRUE(stored) << job.key;
    std::apply(
        [&](const auto&... field) {
          (
              [&] {
                const json want = FieldJson(job.params.*(field.member));
                EXPECT_EQ(FieldJson(stored->params.*(field.member)), want)
                    << job.key << ": " << field.name;
                if (!want.is_null() && want != json::array())
                  seen.insert(field.name);
              }(),
              ...);
        },
        kJobFields);
  }
  // The campaign above sets each declared field in some job, so none is compared only unset.
  std::apply(
      [&](const auto&... field) {
        ([&] { EXPECT_EQ(seen.count(field.name), 1u) << field.name; }(), ...);
      },
      kJobFields);
}

}  // namespace
}  // namespace rlpos
