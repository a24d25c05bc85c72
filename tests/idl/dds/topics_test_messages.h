#pragma once
// What the two tests of topics.h share (topics_test.cc: every message type and the IDL's bounds;
// topics_qos_test.cc: the QoS contract): their fixture, a loopback participant per test, and
// the worker statuses and assignments they write.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "idl/dds/topics.h"
#include "tests/idl/dds/dds_test_support.h"

namespace rlpos::testing {

class TopicsTest : public ::testing::Test {
 protected:
  TopicsTest() : participant_(testing::TestOptions()) {}

  Participant participant_;
};

inline msg::WorkerStatus Status(const std::string& id, int busy) {
  msg::WorkerStatus s;
  s.worker_id = id;
  s.host = "h\xc3\xb4te-" + id;  // UTF-8
  s.pid = (std::int64_t{1} << 40) + busy;
  s.slots = 4;
  s.busy = busy;
  for (int i = 0; i < busy; ++i)
    s.jobs.push_back("c0ffee/eval/B/rl/run" + std::to_string(i) + "#2");
  return s;
}

inline msg::JobAssignment Assignment(const std::string& job_id, int attempt, int slot = 0) {
  msg::JobAssignment a;
  a.worker_id = "w1";
  a.slot = slot;
  JobOrder& o = a.order;
  o.job_id = job_id;
  o.attempt = attempt;
  o.campaign_id = "c0ffee";
  o.timeout_s = 12.5;
  o.params.kind = JobKind::kEval;
  o.params.scenario = "B";
  o.params.rng_run = 7;
  o.params.train_seed = 3;
  o.params.duration_s = 5;
  o.params.warmup_s = 0;
  o.params.overrides = {{"wifi.mode", "\"adhoc\""}, {"ues.0.demand", "12.5"}};
  o.placement = Placement{{50, 35.5, 10}};
  o.scenario_document = "{\"name\": \"B\", \"pad\": \"" + std::string(100000, 'x') + "\"}";
  return a;
}

inline void ExpectSame(const msg::WorkerStatus& a, const msg::WorkerStatus& b) {
  EXPECT_EQ(a.worker_id, b.worker_id);
  EXPECT_EQ(a.host, b.host);
  EXPECT_EQ(a.pid, b.pid);
  EXPECT_EQ(a.slots, b.slots);
  EXPECT_EQ(a.busy, b.busy);
  EXPECT_EQ(a.jobs, b.jobs);
}

}  // namespace rlpos::testing
