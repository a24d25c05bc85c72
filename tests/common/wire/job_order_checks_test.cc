// What a worker refuses in an order's placement (wire/job_order.h): one position per UAV, each
// inside the venue and outside every building, and none for a job that is not an eval.
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

}  // namespace
}  // namespace rlpos
