#pragma once
// What the two tests of topics.h share (topics_test.cc: every message type and the IDL's bounds;
// topics_qos_test.cc: the QoS contract): their fixture, a loopback participant per test, the
// worker statuses, assignments and replies they write and their comparisons; message_codec_test.cc
// builds its assignments and reply from the same ones.
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

// The reply to a submit that created campaign c0ffee of 44 jobs.
inline msg::CampaignReply CreatedReply(const std::string& request_id) {
  msg::CampaignReply r;
  r.request_id = request_id;
  r.ok = true;
  r.campaign_id = "c0ffee";
  r.jobs = 44;
  r.created = true;
  return r;
}

// `a` carrying a fresh `kind` job of `scenario` instead: default parameters and no placement
// (only an eval has one).
inline msg::JobAssignment WithFreshParams(msg::JobAssignment a, JobKind kind,
                                          const std::string& scenario) {
  a.order.params = JobParams{};
  a.order.params.kind = kind;
  a.order.params.scenario = scenario;
  a.order.placement.reset();
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

inline void ExpectSame(const msg::JobAssignment& a, const msg::JobAssignment& b) {
  EXPECT_EQ(a.worker_id, b.worker_id);
  EXPECT_EQ(a.slot, b.slot);
  const JobOrder &x = a.order, &y = b.order;
  EXPECT_EQ(x.job_id, y.job_id);
  EXPECT_EQ(x.attempt, y.attempt);
  EXPECT_EQ(x.campaign_id, y.campaign_id);
  EXPECT_DOUBLE_EQ(x.timeout_s, y.timeout_s);
  EXPECT_EQ(x.scenario_document, y.scenario_document);
  EXPECT_EQ(x.params.kind, y.params.kind);
  EXPECT_EQ(x.params.scenario, y.params.scenario);
  EXPECT_EQ(x.params.rng_run, y.params.rng_run);
  EXPECT_EQ(x.params.train_seed, y.params.train_seed);
  EXPECT_EQ(x.params.fidelity, y.params.fidelity);
  EXPECT_EQ(x.params.train_episodes, y.params.train_episodes);
  EXPECT_EQ(x.params.positioner, y.params.positioner);
  EXPECT_EQ(x.params.duration_s, y.params.duration_s);
  EXPECT_EQ(x.params.warmup_s, y.params.warmup_s);
  EXPECT_EQ(x.params.overrides, y.params.overrides);
  ASSERT_EQ(x.placement.has_value(), y.placement.has_value());
  if (x.placement) {
    ASSERT_EQ(x.placement->size(), y.placement->size());
    for (std::size_t i = 0; i < x.placement->size(); ++i) {
      EXPECT_EQ((*x.placement)[i].x, (*y.placement)[i].x);
      EXPECT_EQ((*x.placement)[i].y, (*y.placement)[i].y);
      EXPECT_EQ((*x.placement)[i].z, (*y.placement)[i].z);
    }
  }
}

}  // namespace rlpos::testing
