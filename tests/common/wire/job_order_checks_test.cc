// What a worker refuses in an order (wire/job_order.h): a placement must have one position per
// UAV, each inside the venue and outside every building, and none for a job that is not an eval;
// an override must not contradict a setting the job fixes.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "common/wire/job_order.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

JobOrder Urban3Eval() {
  std::ifstream in(testing::SourcePath("campaigns/scenarios/urban3.json"));
  JobOrder order;
  order.job_id = "c1/eval/urban3/rl/run1";
  order.campaign_id = "c1";
  order.timeout_s = 60;
  order.params.kind = JobKind::kEval;
  order.params.scenario = "urban3";
  order.params.rng_run = 1;
  order.placement = Placement{{45, 45, 40}, {55, 45, 40}, {50, 55, 40}};
  order.scenario_document.assign(std::istreambuf_iterator<char>(in), {});
  return order;
}

std::string ErrorOf(const JobOrder& order) {
  try {
    CheckJobOrder(order, 3600);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(JobOrderPlacement, OnePositionPerUavEachFlyable) {
  JobOrder order = Urban3Eval();
  EXPECT_EQ(ErrorOf(order), "accepted");
  order.placement->pop_back();
  EXPECT_EQ(ErrorOf(order), "positions: 2 given, the scenario has 3 UAVs");
  order.placement = std::nullopt;
  EXPECT_EQ(ErrorOf(order), "positions: an eval job needs one per UAV");
  order = Urban3Eval();
  (*order.placement)[1] = {20, 20, 10};  // inside block00 (x, y 10-40, 22 m high)
  EXPECT_EQ(ErrorOf(order), "positions[1]: 20,20,10 is inside a building");
  (*order.placement)[1] = {20, 20, 30};
  (*order.placement)[2] = {50, 151, 40};
  EXPECT_EQ(ErrorOf(order), "positions[2]: 50,151,40 is outside the venue");
  order = Urban3Eval();
  order.params.kind = JobKind::kTrain;
  order.params.rng_run.reset();
  order.params.train_seed = 1;
  order.params.fidelity = "analytic";
  EXPECT_EQ(ErrorOf(order), "positions: only an eval job has them");
}

// The same order, as a train job with `overrides`.
JobOrder Urban3Train(std::vector<ScenarioOverride> overrides) {
  JobOrder order = Urban3Eval();
  order.job_id = "c1/train/urban3/seed1";
  order.placement.reset();
  order.params.kind = JobKind::kTrain;
  order.params.rng_run.reset();
  order.params.train_seed = 1;
  order.params.fidelity = "analytic";
  order.params.overrides = std::move(overrides);
  return order;
}

TEST(JobOrderSettings, AnOverrideThatContradictsTheJobIsRefused) {
  EXPECT_EQ(ErrorOf(Urban3Train({{"env.fidelity", "analytic"}, {"agent.seed", "1"}})), "accepted");
  EXPECT_EQ(ErrorOf(Urban3Train({{"wifi.mode", "adhoc"}, {"env.fidelity", "packet"}})),
            "overrides[1]: \"env.fidelity=packet\" contradicts the job's fidelity "
            "(/env/fidelity=analytic)");
  JobOrder eval = Urban3Eval();
  eval.params.overrides = {{"/simulation/run", "2"}};
  EXPECT_EQ(ErrorOf(eval),
            "overrides[0]: \"/simulation/run=2\" contradicts the job's rng_run "
            "(/simulation/run=1)");
}

TEST(JobOrderSettings, TheJobsSettingsAreInItsScenario) {
  JobOrder order = Urban3Train({{"agent.train_episodes", "7"}});
  order.params.train_seed = 5;
  order.params.fidelity = "packet";
  const CheckedOrder checked = CheckJobOrder(order, 3600);
  EXPECT_EQ(checked.scenario["agent"]["seed"], 5);
  EXPECT_EQ(checked.scenario["env"]["fidelity"], "packet");
  EXPECT_EQ(checked.scenario["agent"]["train_episodes"], 7);  // the job leaves it open
  EXPECT_EQ(checked.parsed.agent.seed, 5u);
  EXPECT_EQ(checked.parsed.env.fidelity, "packet");
}

}  // namespace
}  // namespace rlpos
