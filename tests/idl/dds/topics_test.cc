// Every message type through a Writer and a Reader of one loopback participant (topics.h), and
// the IDL's bounds: a field at its bound is written, one over it refused. The QoS contract is in
// topics_qos_test.cc.
#include "idl/dds/topics.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/idl/dds/dds_test_support.h"
#include "tests/idl/dds/topics_test_messages.h"

namespace rlpos::testing {
namespace {

msg::JobAssignment PositionAssignment() {
  msg::JobAssignment a =
      WithFreshParams(Assignment("c0ffee/position/C/centroid", 2), JobKind::kPosition, "C");
  a.worker_id = "w-\xc3\xa9";
  a.order.params.positioner = "centroid";
  a.order.params.duration_s = 0.25;
  a.order.params.overrides = {{"/ues/0/demand", "1e-3"}};
  a.order.scenario_document = "{}";
  return a;
}

msg::JobAssignment TrainAssignment() {
  msg::JobAssignment a = WithFreshParams(Assignment("job-t", 1), JobKind::kTrain, "C");
  a.order.params.train_seed = 9;
  a.order.params.fidelity = "packet";
  a.order.params.train_episodes = 25;
  return a;
}

TEST_F(TopicsTest, WorkerStatusRoundTrip) {
  Reader<msg::WorkerStatus> reader(participant_);
  Writer<msg::WorkerStatus> writer(participant_);
  const msg::WorkerStatus busy = Status("w1", 3), idle = Status("w2", 0);
  writer.Write(busy);
  writer.Write(idle);
  const auto got = AwaitData(reader, 2);
  ASSERT_EQ(got.size(), 2u);
  ExpectSame(got[0], busy);
  ExpectSame(got[1], idle);
  EXPECT_EQ(got[0].jobs.size(), 3u);
  EXPECT_TRUE(got[1].jobs.empty());
}

TEST_F(TopicsTest, JobAssignmentRoundTrip) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  const msg::JobAssignment sent = Assignment("c0ffee/eval/B/rl/run1", 3, 1023);
  writer.Write(sent);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  ExpectSame(got[0], sent);
}

TEST_F(TopicsTest, AnEvalOfThreeUavsCarriesEachPositionInOrder) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  msg::JobAssignment a = Assignment("c0ffee/eval/urban3/rl/run2", 1);
  a.order.placement = Placement{{10, 20, 30}, {40.25, 50, 60}, {70, 80, 90.5}};
  writer.Write(a);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  ExpectSame(got[0], a);
  ASSERT_EQ(got[0].order.placement->size(), 3u);
  EXPECT_EQ((*got[0].order.placement)[1].x, 40.25);
}

TEST_F(TopicsTest, JobEventRoundTripEveryState) {
  Reader<msg::JobEvent> reader(participant_);
  Writer<msg::JobEvent> writer(participant_);
  const std::vector<msg::JobState> states{msg::JobState::kStarted, msg::JobState::kProgress,
                                          msg::JobState::kSucceeded, msg::JobState::kFailed};
  std::vector<msg::JobEvent> sent;
  for (std::size_t i = 0; i < states.size(); ++i) {
    msg::JobEvent e;
    e.job_id = "job" + std::to_string(i);
    e.attempt = static_cast<int>(i) + 2;
    e.worker_id = "w" + std::to_string(i);
    e.slot = static_cast<int>(i) * 341;  // up to 1023
    e.state = states[i];
    e.result_json = i == 2 ? R"({"position":[1.5,2,3]})" : "";
    e.message = i == 3 ? "line one\nline \"two\" [exit code 1]" : "episode 3/10";
    e.provenance = {"host-" + std::to_string(i),
                    "v0.1-" + std::to_string(i) + "-gabc",
                    "3.37",
                    "1.13.0",
                    "0.10.2",
                    std::string(64, 'a' + static_cast<char>(i))};
    writer.Write(e);
    sent.push_back(e);
  }
  const auto got = AwaitData(reader, sent.size());
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(got[i].job_id, sent[i].job_id);
    EXPECT_EQ(got[i].attempt, sent[i].attempt);
    EXPECT_EQ(got[i].worker_id, sent[i].worker_id);
    EXPECT_EQ(got[i].slot, sent[i].slot);
    EXPECT_EQ(got[i].state, sent[i].state);
    EXPECT_EQ(got[i].result_json, sent[i].result_json);
    EXPECT_EQ(got[i].message, sent[i].message);
    const Provenance &a = got[i].provenance, &b = sent[i].provenance;
    EXPECT_EQ(std::tie(a.host, a.rlpos_version, a.ns3_version, a.torch_version,
                       a.cyclonedds_version, a.scenario_sha256),
              std::tie(b.host, b.rlpos_version, b.ns3_version, b.torch_version,
                       b.cyclonedds_version, b.scenario_sha256));
  }
}

TEST_F(TopicsTest, JobEventReaderKeepsEveryEventOfAJobInOrder) {
  Reader<msg::JobEvent> reader(participant_);
  Writer<msg::JobEvent> writer(participant_);
  msg::JobEvent e;
  e.job_id = "j";
  for (auto state :
       {msg::JobState::kStarted, msg::JobState::kProgress, msg::JobState::kSucceeded}) {
    e.state = state;
    writer.Write(e);
  }
  const auto got = AwaitData(reader, 3);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].state, msg::JobState::kStarted);
  EXPECT_EQ(got[1].state, msg::JobState::kProgress);
  EXPECT_EQ(got[2].state, msg::JobState::kSucceeded);
}

TEST_F(TopicsTest, CampaignRequestRoundTripEveryKind) {
  Reader<msg::CampaignRequest> reader(participant_);
  Writer<msg::CampaignRequest> writer(participant_);
  const std::vector<msg::RequestKind> kinds{msg::RequestKind::kSubmit, msg::RequestKind::kCancel,
                                            msg::RequestKind::kRetry};
  std::vector<msg::CampaignRequest> sent;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    msg::CampaignRequest r;
    r.request_id = "req-" + std::to_string(i);
    r.kind = kinds[i];
    r.campaign_id = i == 0 ? "" : "c0ffee";
    r.campaign_json = i == 0 ? R"({"id":"c0ffee","jobs":[]})" : "";
    writer.Write(r);
    sent.push_back(r);
  }
  const auto got = AwaitData(reader, sent.size());
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(got[i].request_id, sent[i].request_id);
    EXPECT_EQ(got[i].kind, sent[i].kind);
    EXPECT_EQ(got[i].campaign_id, sent[i].campaign_id);
    EXPECT_EQ(got[i].campaign_json, sent[i].campaign_json);
  }
}

TEST_F(TopicsTest, CampaignReplyRoundTrip) {
  Reader<msg::CampaignReply> reader(participant_);
  Writer<msg::CampaignReply> writer(participant_);
  const msg::CampaignReply ok = CreatedReply("req-1");
  msg::CampaignReply refused;
  refused.request_id = "req-2";
  refused.ok = false;
  refused.jobs = -1;
  refused.message = "results store x.db: no campaign \"nope\"";
  writer.Write(ok);
  writer.Write(refused);
  const auto got = AwaitData(reader, 2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].request_id, "req-1");
  EXPECT_TRUE(got[0].ok);
  EXPECT_EQ(got[0].campaign_id, "c0ffee");
  EXPECT_EQ(got[0].jobs, 44);
  EXPECT_TRUE(got[0].created);
  EXPECT_EQ(got[0].message, "");
  EXPECT_EQ(got[1].request_id, "req-2");
  EXPECT_FALSE(got[1].ok);
  EXPECT_EQ(got[1].campaign_id, "");
  EXPECT_EQ(got[1].jobs, -1);
  EXPECT_FALSE(got[1].created);
  EXPECT_EQ(got[1].message, refused.message);
}

TEST_F(TopicsTest, EveryKindOfAssignmentRoundTrips) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  const std::vector<msg::JobAssignment> sent{TrainAssignment(), PositionAssignment(),
                                             Assignment("c0ffee/eval/B/rl/run7", 1, 1)};
  for (const auto& a : sent)
    writer.Write(a);
  std::vector<Received<msg::JobAssignment>> got;
  ASSERT_TRUE(AwaitSample(
      reader, [&](const auto& r) { return r.data.order.job_id == sent.back().order.job_id; }, 5.0,
      &got));
  ASSERT_EQ(got.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE(i);
    EXPECT_TRUE(got[i].valid);
    EXPECT_EQ(got[i].decode_error, "");
    ExpectSame(got[i].data, sent[i]);
  }
  // Only the fields of its kind travel: a train job has no position, a position job no seed.
  EXPECT_FALSE(got[0].data.order.placement.has_value());
  EXPECT_FALSE(got[1].data.order.params.train_seed.has_value());
  EXPECT_EQ(got[1].data.order.params.fidelity, "");
  EXPECT_FALSE(got[1].data.order.params.rng_run.has_value());
}

TEST_F(TopicsTest, CampaignRequestWithScenariosRoundTrip) {
  Reader<msg::CampaignRequest> reader(participant_);
  Writer<msg::CampaignRequest> writer(participant_);
  msg::CampaignRequest r;
  r.request_id = "req-scenarios";
  r.kind = msg::RequestKind::kSubmit;
  r.campaign_json = R"({"name": "m\u00e9", "scenarios": ["b.json", {"file": "c.json"}]})";
  r.scenarios = {{"scenarios/b.json", R"({"name": "B", "venue": {"width": 100}})"},
                 {"/abs/h\xc3\xb4te/c.json", ""},
                 {"big.json", "{\"pad\": \"" + std::string(262144 - 11, 'x') + "\"}"}};
  ASSERT_EQ(r.scenarios[2].document.size(), 262144u);  // exactly the bound
  writer.Write(r);
  const auto got = AwaitSample(reader, [](const auto& s) { return s.valid; });
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->decode_error, "");
  EXPECT_EQ(got->data.request_id, r.request_id);
  EXPECT_EQ(got->data.kind, msg::RequestKind::kSubmit);
  EXPECT_EQ(got->data.campaign_json, r.campaign_json);
  ASSERT_EQ(got->data.scenarios.size(), r.scenarios.size());
  for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(got->data.scenarios[i].file, r.scenarios[i].file);
    EXPECT_EQ(got->data.scenarios[i].document, r.scenarios[i].document);
  }
}

// Sets a field of `base` to a size (in bytes or elements) and writes it: at `bound` it is
// written, one more throws DdsError.
template <typename M, typename F>
void ExpectBound(Participant& participant, const M& base, const char* field, std::size_t bound,
                 F set) {
  SCOPED_TRACE(field);
  Writer<M> writer(participant);
  M at = base, over = base;
  set(at, bound);
  set(over, bound + 1);
  EXPECT_NO_THROW(writer.Write(at));
  EXPECT_THROW(writer.Write(over), DdsError);
}

TEST_F(TopicsTest, WriteRefusesEveryFieldOverItsIdlBound) {
  const auto text = [](std::size_t n) { return std::string(n, 'a'); };
  const msg::JobAssignment a = Assignment("c0ffee/j", 1);
  ExpectBound(participant_, a, "job_id", 256, [&](auto& m, auto n) { m.order.job_id = text(n); });
  ExpectBound(participant_, a, "worker_id", 128, [&](auto& m, auto n) { m.worker_id = text(n); });
  ExpectBound(participant_, a, "campaign_id", 64,
              [&](auto& m, auto n) { m.order.campaign_id = text(n); });
  ExpectBound(participant_, a, "scenario", 128,
              [&](auto& m, auto n) { m.order.params.scenario = text(n); });
  ExpectBound(participant_, a, "scenario_document", 262144,
              [&](auto& m, auto n) { m.order.scenario_document = text(n); });
  ExpectBound(participant_, a, "overrides", 64, [&](auto& m, auto n) {
    m.order.params.overrides.assign(n, ScenarioOverride{"wifi.mode", "adhoc"});
  });
  ExpectBound(participant_, a, "override path", 128, [&](auto& m, auto n) {
    m.order.params.overrides = {{text(n), "1"}};
  });
  ExpectBound(participant_, a, "override value", 4096, [&](auto& m, auto n) {
    m.order.params.overrides = {{"x", text(n)}};
  });
  ExpectBound(participant_, a, "positions", 8, [&](auto& m, auto n) {
    m.order.placement = Placement(n, Vec3{1, 2, 3});
  });

  const msg::WorkerStatus s = Status("w1", 1);
  ExpectBound(participant_, s, "status worker_id", 128,
              [&](auto& m, auto n) { m.worker_id = text(n); });
  ExpectBound(participant_, s, "host", 128, [&](auto& m, auto n) { m.host = text(n); });
  ExpectBound(participant_, s, "jobs", 1024, [&](auto& m, auto n) { m.jobs.assign(n, "j#1"); });
  ExpectBound(participant_, s, "job key", 300, [&](auto& m, auto n) { m.jobs = {text(n)}; });

  msg::JobEvent e;
  e.job_id = "j";
  ExpectBound(participant_, e, "event job_id", 256, [&](auto& m, auto n) { m.job_id = text(n); });
  ExpectBound(participant_, e, "event worker_id", 128,
              [&](auto& m, auto n) { m.worker_id = text(n); });
  ExpectBound(participant_, e, "result_json", 262144,
              [&](auto& m, auto n) { m.result_json = text(n); });
  ExpectBound(participant_, e, "message", 1024, [&](auto& m, auto n) { m.message = text(n); });

  msg::CampaignRequest r;
  r.request_id = "req";
  ExpectBound(participant_, r, "request_id", 256, [&](auto& m, auto n) { m.request_id = text(n); });
  ExpectBound(participant_, r, "request campaign_id", 64,
              [&](auto& m, auto n) { m.campaign_id = text(n); });
  ExpectBound(participant_, r, "campaign_json", 65536,
              [&](auto& m, auto n) { m.campaign_json = text(n); });
  ExpectBound(participant_, r, "scenarios", 32, [&](auto& m, auto n) {
    m.scenarios.assign(n, SubmittedScenario{"b.json", "{}"});
  });
  ExpectBound(participant_, r, "scenario file", 512, [&](auto& m, auto n) {
    m.scenarios = {{text(n), "{}"}};
  });
  ExpectBound(participant_, r, "scenario document", 262144, [&](auto& m, auto n) {
    m.scenarios = {{"b.json", text(n)}};
  });

  msg::CampaignReply reply;
  reply.request_id = "req";
  ExpectBound(participant_, reply, "reply request_id", 256,
              [&](auto& m, auto n) { m.request_id = text(n); });
  ExpectBound(participant_, reply, "reply campaign_id", 64,
              [&](auto& m, auto n) { m.campaign_id = text(n); });
}

TEST_F(TopicsTest, WriteRefusesANulInsideAString) {
  Writer<msg::JobAssignment> writer(participant_);
  msg::JobAssignment a = Assignment("c0ffee/j", 1);
  a.order.job_id = std::string("c0ffee/j") + '\0' + "/x";
  EXPECT_THROW(writer.Write(a), DdsError);
  a = Assignment("c0ffee/j", 1);
  a.order.params.overrides = {{"name", std::string("B") + '\0' + "C"}};
  EXPECT_THROW(writer.Write(a), DdsError);
}

TEST_F(TopicsTest, ALongReplyMessageIsCutToItsBound) {
  Reader<msg::CampaignReply> reader(participant_);
  Writer<msg::CampaignReply> writer(participant_);
  msg::CampaignReply reply;
  reply.request_id = "req-long";
  reply.message = std::string(1024, 'm') + "and the rest";
  writer.Write(reply);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].message, std::string(1024, 'm'));
}

}  // namespace
}  // namespace rlpos::testing
