// rlpos-bench-validation: what checking a message costs, per message kind, on this machine.
// Prints microseconds per message for each check the daemons run on every received sample:
//   rlpos-bench-validation [SOURCE_DIR] [ITERATIONS]
// (SOURCE_DIR holds campaigns/; default ".".) Figures, not assertions: run it side by side.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "common/campaign/campaign_request.h"
#include "common/store/job_result.h"
#include "common/wire/job_order.h"
#include "common/wire/json_text.h"
#include "common/wire/limits.h"
#include "idl/dds/message_checks.h"
#include "tests/support/program_usage.h"

namespace {

std::string ReadText(const std::string& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

double MicrosecondsEach(int n, const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i)
    f();
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
             .count() /
         n;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rlpos;
  constexpr char kUsage[] = "usage: rlpos-bench-validation [SOURCE_DIR] [ITERATIONS]\n";
  if (testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc > 3)
    return testing::UsageError(kUsage);
  const std::string src = argc > 1 ? argv[1] : ".";
  const int n = argc > 2 ? std::atoi(argv[2]) : 2000;
  if (n < 1) {
    std::fprintf(stderr,
                 "rlpos-bench-validation: error: ITERATIONS: expected a positive whole "
                 "number, got \"%s\"\n",
                 argv[2]);
    return 2;
  }
  JobOrder order;
  order.job_id = "0123456789ab/eval/B/rl/run7";
  order.campaign_id = "0123456789ab";
  order.timeout_s = 600;
  order.params.kind = JobKind::kEval;
  order.params.scenario = "B";
  order.params.rng_run = 7;
  order.params.duration_s = 5;
  order.params.warmup_s = 0.5;
  order.placement = Placement{{50, 35, 30}};
  order.scenario_document = ReadText(src + "/campaigns/scenarios/b.json");
  if (order.scenario_document.empty()) {
    std::fprintf(stderr, "rlpos-bench-validation: error: %s/campaigns/scenarios/b.json: missing\n",
                 src.c_str());
    return 2;
  }
  msg::JobEvent event;
  event.job_id = order.job_id;
  event.worker_id = "host-1234";
  event.state = msg::JobState::kSucceeded;
  event.result_json =
      R"({"position": [50, 35, 30], "aggregate_throughput_mbps": 233.9, "mean_delay_ms": 3.5,)"
      R"( "loss_ratio": 0.01, "min_snr_db": 21.5, "n_los": 4, "n_ues": 4, "demands_met": 4,)"
      R"( "run": 7, "scenario": "B"})";
  msg::WorkerStatus status;
  status.worker_id = "host-1234";
  status.host = "host";
  status.slots = 4;
  status.busy = 2;
  status.jobs = {order.job_id + "#1", "0123456789ab/eval/B/rl/run8#1"};
  const std::string campaign = ReadText(src + "/campaigns/mini.json");
  const std::vector<SubmittedScenario> files{
      {"scenarios/b.json", ReadText(src + "/campaigns/scenarios/b.json")},
      {"scenarios/c.json", ReadText(src + "/campaigns/scenarios/c.json")}};

  std::printf("message check                              us/message  (%d iterations)\n", n);
  std::printf("job assignment: CheckJobOrder (b.json)     %10.2f\n",
              MicrosecondsEach(n, [&] { CheckJobOrder(order, 86400); }));
  std::printf("job event: CheckJobEvent                   %10.2f\n",
              MicrosecondsEach(n * 50, [&] { (void)CheckJobEvent(event); }));
  std::printf(
      "job event: result parse + plausibility     %10.2f\n", MicrosecondsEach(n * 10, [&] {
        ParseEvalResult(wire::ParseBoundedJson(event.result_json, wire::kMaxResultJson, "r"));
      }));
  std::printf("worker status: CheckWorkerStatus           %10.2f\n",
              MicrosecondsEach(n * 50, [&] { (void)CheckWorkerStatus(status); }));
  std::printf("submit: PlanSubmittedCampaign + its jobs (mini, 44) %10.2f\n",
              MicrosecondsEach(std::max(1, n / 50), [&] {
                PlanSubmittedCampaign(campaign, files, SubmitLimits{}).ForEachJob([](Job&&) {});
              }));
  return 0;
}
