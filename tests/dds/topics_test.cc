// Every message type through a Writer and a Reader of one loopback participant, and the QoS
// contract of topics.h: disposal, transient-local history, writers that go without disposing.
#include "dds/topics.h"

#include <gtest/gtest.h>

#include "dds/wait_set.h"
#include "dds_test_support.h"

namespace rlpos {
namespace {

using testing::AwaitData;
using testing::AwaitSample;
using testing::WaitFor;

class TopicsTest : public ::testing::Test {
 protected:
  TopicsTest() : participant_(testing::TestOptions()) {}

  Participant participant_;
};

msg::WorkerStatus Status(const std::string& id, int busy) {
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

msg::JobAssignment Assignment(const std::string& job_id, int attempt) {
  msg::JobAssignment a;
  a.worker_id = "w1";
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
  o.position = Vec3{50, 35.5, 10};
  o.scenario_document = "{\"name\": \"B\", \"pad\": \"" + std::string(100000, 'x') + "\"}";
  return a;
}

msg::JobAssignment TrainAssignment() {
  msg::JobAssignment a = Assignment("job-t", 1);
  a.order.params = JobParams{};
  a.order.params.kind = JobKind::kTrain;
  a.order.params.scenario = "C";
  a.order.params.train_seed = 9;
  a.order.params.fidelity = "packet";
  a.order.params.train_episodes = 25;
  a.order.position.reset();
  return a;
}

void ExpectSame(const msg::WorkerStatus& a, const msg::WorkerStatus& b) {
  EXPECT_EQ(a.worker_id, b.worker_id);
  EXPECT_EQ(a.host, b.host);
  EXPECT_EQ(a.pid, b.pid);
  EXPECT_EQ(a.slots, b.slots);
  EXPECT_EQ(a.busy, b.busy);
  EXPECT_EQ(a.jobs, b.jobs);
}

void ExpectSame(const msg::JobAssignment& a, const msg::JobAssignment& b) {
  EXPECT_EQ(a.worker_id, b.worker_id);
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
  ASSERT_EQ(x.position.has_value(), y.position.has_value());
  if (x.position) {
    EXPECT_EQ(x.position->x, y.position->x);
    EXPECT_EQ(x.position->y, y.position->y);
    EXPECT_EQ(x.position->z, y.position->z);
  }
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
  const msg::JobAssignment sent = Assignment("c0ffee/eval/B/rl/run1", 3);
  writer.Write(sent);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  ExpectSame(got[0], sent);
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
    e.state = states[i];
    e.result_json = i == 2 ? R"({"position":[1.5,2,3]})" : "";
    e.message = i == 3 ? "line one\nline \"two\" [exit code 1]" : "episode 3/10";
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
    EXPECT_EQ(got[i].state, sent[i].state);
    EXPECT_EQ(got[i].result_json, sent[i].result_json);
    EXPECT_EQ(got[i].message, sent[i].message);
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
  msg::CampaignReply ok;
  ok.request_id = "req-1";
  ok.ok = true;
  ok.campaign_id = "c0ffee";
  ok.jobs = 44;
  ok.created = true;
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

TEST_F(TopicsTest, DisposeArrivesAsAnInvalidSampleWithTheKey) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  writer.Write(Assignment("job-a", 1));
  writer.Write(Assignment("job-b", 1));
  ASSERT_EQ(AwaitData(reader, 2).size(), 2u);

  msg::JobAssignment key;
  key.order.job_id = "job-a";
  writer.Dispose(key);
  const auto disposed = AwaitSample(reader, [](const auto& r) { return !r.valid; });
  ASSERT_TRUE(disposed.has_value());
  EXPECT_EQ(disposed->state, InstanceState::kDisposed);
  EXPECT_EQ(disposed->data.order.job_id, "job-a");
  EXPECT_TRUE(disposed->data.order.scenario_document.empty());  // only the key travels
  EXPECT_TRUE(reader.Take().empty());                           // job-b is untouched
}

TEST_F(TopicsTest, LateReaderGetsTheLastWorkerStatusPerWorker) {
  Writer<msg::WorkerStatus> writer(participant_);
  writer.Write(Status("w1", 1));
  writer.Write(Status("w1", 2));  // keep last 1: replaces the first
  writer.Write(Status("w2", 0));
  Reader<msg::WorkerStatus> reader(participant_);
  auto got = AwaitData(reader, 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (auto& r : reader.Take())
    got.push_back(r.data);
  ASSERT_EQ(got.size(), 2u);
  const auto& w1 = got[0].worker_id == "w1" ? got[0] : got[1];
  const auto& w2 = got[0].worker_id == "w1" ? got[1] : got[0];
  ExpectSame(w1, Status("w1", 2));
  ExpectSame(w2, Status("w2", 0));
}

TEST_F(TopicsTest, LateReaderGetsTheLastAssignment) {
  Writer<msg::JobAssignment> assignments(participant_);
  assignments.Write(Assignment("job-a", 1));
  assignments.Write(Assignment("job-a", 2));
  Reader<msg::JobAssignment> assignment_reader(participant_);
  const auto a = AwaitData(assignment_reader, 1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].order.attempt, 2);
}

TEST_F(TopicsTest, TrainAssignmentRoundTrip) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  writer.Write(TrainAssignment());
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  ExpectSame(got[0], TrainAssignment());
}

TEST_F(TopicsTest, AFieldOverItsBoundIsNotWritten) {
  Writer<msg::JobAssignment> writer(participant_);
  msg::JobAssignment a = Assignment("job-a", 1);
  a.order.job_id = std::string(300, 'j');
  EXPECT_THROW(writer.Write(a), DdsError);
  a = Assignment("job-a", 1);
  a.order.scenario_document = std::string(300000, ' ');
  EXPECT_THROW(writer.Write(a), DdsError);
}

TEST_F(TopicsTest, ReplyIsNotKeptForLateReaders) {
  Writer<msg::CampaignReply> replies(participant_);
  msg::CampaignReply reply;
  reply.request_id = "req-9";
  reply.ok = true;
  replies.Write(reply);
  replies.Unregister(reply);
  Reader<msg::CampaignReply> reader(participant_);
  ASSERT_TRUE(WaitFor([&] { return replies.MatchedReaders() == 1; }));
  // A reply written once the reader is matched arrives; the earlier one was never kept.
  reply.request_id = "req-10";
  replies.Write(reply);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].request_id, "req-10");
}

TEST_F(TopicsTest, CampaignRequestsAreVolatile) {
  Writer<msg::CampaignRequest> writer(participant_);
  msg::CampaignRequest early;
  early.request_id = "early";
  writer.Write(early);
  Reader<msg::CampaignRequest> reader(participant_);
  ASSERT_TRUE(WaitFor([&] { return writer.MatchedReaders() == 1; }));
  msg::CampaignRequest late;
  late.request_id = "late";
  writer.Write(late);
  const auto got = AwaitData(reader, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].request_id, "late");
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(reader.Take().empty());
}

TEST_F(TopicsTest, DeletedAssignmentWriterDoesNotDispose) {
  Reader<msg::JobAssignment> reader(participant_);
  {
    Writer<msg::JobAssignment> writer(participant_);
    writer.Write(Assignment("job-a", 1));
    const auto alive = AwaitSample(reader, [](const auto& r) { return r.valid; });
    ASSERT_TRUE(alive.has_value());
    EXPECT_EQ(alive->state, InstanceState::kAlive);
  }
  // A coordinator that stops: its workers must not read this as "stop the job".
  const auto gone = AwaitSample(reader, [](const auto& r) { return !r.valid; });
  ASSERT_TRUE(gone.has_value());
  EXPECT_EQ(gone->state, InstanceState::kNoWriters);
  EXPECT_EQ(gone->data.order.job_id, "job-a");
}

TEST_F(TopicsTest, DeletedWorkerStatusWriterDoesNotDispose) {
  Reader<msg::WorkerStatus> reader(participant_);
  {
    Writer<msg::WorkerStatus> writer(participant_);
    writer.Write(Status("w1", 1));
    ASSERT_EQ(AwaitData(reader, 1).size(), 1u);
  }
  const auto gone = AwaitSample(reader, [](const auto& r) { return !r.valid; });
  ASSERT_TRUE(gone.has_value());
  EXPECT_EQ(gone->state, InstanceState::kNoWriters);
  EXPECT_EQ(gone->data.worker_id, "w1");
}

TEST_F(TopicsTest, MatchedCounts) {
  Writer<msg::JobEvent> writer(participant_);
  EXPECT_EQ(writer.MatchedReaders(), 0);
  {
    Reader<msg::JobEvent> reader(participant_);
    EXPECT_TRUE(WaitFor([&] { return writer.MatchedReaders() == 1; }));
    EXPECT_TRUE(WaitFor([&] { return reader.MatchedWriters() == 1; }));
    Reader<msg::JobEvent> second(participant_);
    EXPECT_TRUE(WaitFor([&] { return writer.MatchedReaders() == 2; }));
  }
  EXPECT_TRUE(WaitFor([&] { return writer.MatchedReaders() == 0; }));
}

TEST_F(TopicsTest, WaitSetWakesOnData) {
  Reader<msg::JobEvent> reader(participant_);
  Writer<msg::JobEvent> writer(participant_);
  WaitSet waits(participant_);
  waits.Attach(reader.handle());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(waits.Wait(0.1));
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(90));
  msg::JobEvent e;
  e.job_id = "j";
  writer.Write(e);
  EXPECT_TRUE(waits.Wait(5.0));
  EXPECT_EQ(reader.Take().size(), 1u);
  EXPECT_FALSE(waits.Wait(0.05));  // taken: nothing left to wake for
}

}  // namespace
}  // namespace rlpos
