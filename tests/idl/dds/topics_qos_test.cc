// The QoS contract of topics.h: disposal, transient-local history, writers that go without
// disposing, which participant a sample came from, matched counts and the wait set. "Nothing else
// arrived" is checked with a marker: one writer's samples arrive in the order it wrote them, so
// once a marker written last has arrived, whatever came before it is all that ever will.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "idl/dds/topics.h"
#include "idl/dds/wait_set.h"
#include "tests/idl/dds/dds_test_support.h"
#include "tests/idl/dds/topics_test_messages.h"

namespace rlpos::testing {
namespace {

// A second participant of this process: with neither config nor tag it joins the domain that
// `first` created (its loopback config), as a participant of its own.
DdsOptions SecondParticipantOptions(const Participant& first) {
  DdsOptions same_domain;
  same_domain.domain = first.options().domain;
  same_domain.insecure = true;  // no config of its own: it never leaves first's loopback
  return same_domain;
}

TEST_F(TopicsTest, DisposeArrivesAsAnInvalidSampleWithTheKey) {
  Reader<msg::JobAssignment> reader(participant_);
  Writer<msg::JobAssignment> writer(participant_);
  writer.Write(Assignment("job-a", 1, 0));
  writer.Write(Assignment("job-b", 1, 1));
  ASSERT_EQ(AwaitData(reader, 2).size(), 2u);

  msg::JobAssignment key;
  key.worker_id = "w1";
  key.slot = 0;
  writer.Dispose(key);
  const auto disposed = AwaitSample(reader, [](const auto& r) { return !r.valid; });
  ASSERT_TRUE(disposed.has_value());
  EXPECT_EQ(disposed->state, InstanceState::kDisposed);
  EXPECT_EQ(disposed->data.worker_id, "w1");
  EXPECT_EQ(disposed->data.slot, 0);
  EXPECT_EQ(disposed->data.order.job_id, "");  // only the key travels
  EXPECT_TRUE(disposed->data.order.scenario_document.empty());
  // job-b's slot is untouched: nothing of it came before a marker written after the disposal.
  writer.Write(Assignment("job-marker", 1, 2));
  const auto before =
      TakenBeforeMarker(reader, [](const auto& a) { return a.order.job_id == "job-marker"; });
  ASSERT_TRUE(before.has_value()) << "the marker did not arrive";
  EXPECT_TRUE(before->empty()) << before->size() << " samples, the first of "
                               << before->front().data.order.job_id;
}

TEST_F(TopicsTest, LateReaderGetsTheLastWorkerStatusPerWorker) {
  Writer<msg::WorkerStatus> writer(participant_);
  writer.Write(Status("w1", 1));
  writer.Write(Status("w1", 2));  // keep last 1: replaces the first
  writer.Write(Status("w2", 0));
  Reader<msg::WorkerStatus> reader(participant_);
  ASSERT_TRUE(WaitFor([&] { return writer.MatchedReaders() == 1; }));
  // The history arrives before anything written after the match: the marker closes it.
  writer.Write(Status("w-marker", 0));
  const auto before =
      TakenBeforeMarker(reader, [](const auto& s) { return s.worker_id == "w-marker"; });
  ASSERT_TRUE(before.has_value()) << "the marker did not arrive";
  std::vector<msg::WorkerStatus> got;
  for (const auto& r : *before) {
    EXPECT_TRUE(r.valid);
    got.push_back(r.data);
  }
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

TEST_F(TopicsTest, WriterParticipantTellsWhichParticipantWrote) {
  Participant other(SecondParticipantOptions(participant_));
  Reader<msg::JobEvent> reader(participant_);
  Writer<msg::JobEvent> first(participant_), second(participant_), foreign(other);
  ASSERT_TRUE(WaitFor([&] { return reader.MatchedWriters() == 3; }));
  std::map<std::string, Writer<msg::JobEvent>*> writers{
      {"first", &first}, {"second", &second}, {"foreign", &foreign}};
  for (const auto& [name, writer] : writers) {
    msg::JobEvent e;
    e.job_id = name;
    writer->Write(e);
  }
  std::map<std::string, std::uint64_t> handle;
  ASSERT_TRUE(WaitFor([&] {
    for (const auto& r : reader.Take())
      handle[r.data.job_id] = r.writer;
    return handle.size() == 3;
  }));
  EXPECT_NE(handle["first"], handle["second"]);  // two writers ...
  const std::string mine = reader.WriterParticipant(handle["first"]);
  EXPECT_EQ(mine.size(), 32u) << mine;                          // 16 bytes in hex
  EXPECT_EQ(reader.WriterParticipant(handle["second"]), mine);  // ... of one participant
  const std::string theirs = reader.WriterParticipant(handle["foreign"]);
  EXPECT_EQ(theirs.size(), 32u) << theirs;
  EXPECT_NE(theirs, mine);
  EXPECT_TRUE(reader.HasMatchedWriterOf(mine));
  EXPECT_TRUE(reader.HasMatchedWriterOf(theirs));
  EXPECT_FALSE(reader.HasMatchedWriterOf(std::string(32, '0')));
  EXPECT_EQ(reader.WriterParticipant(0), "");  // no such writer
}

TEST_F(TopicsTest, HasMatchedWriterOfSeesPastManyOtherWriters) {
  Participant other(SecondParticipantOptions(participant_));
  Reader<msg::JobAssignment> reader(participant_);
  std::vector<std::unique_ptr<Writer<msg::JobAssignment>>> crowd;
  for (int i = 0; i < 100; ++i)
    crowd.push_back(std::make_unique<Writer<msg::JobAssignment>>(other));
  Writer<msg::JobAssignment> mine(participant_);
  ASSERT_TRUE(WaitFor([&] { return reader.MatchedWriters() == 101; }));
  mine.Write(Assignment("c0ffee/j", 1));
  const auto got = AwaitSample(reader, [](const auto& r) { return r.valid; });
  ASSERT_TRUE(got.has_value());
  const std::string guid = reader.WriterParticipant(got->writer);
  ASSERT_FALSE(guid.empty());
  // A coordinator stays followed however many other writers a peer adds to the topic.
  EXPECT_TRUE(reader.HasMatchedWriterOf(guid));
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
  // A reply written once the reader is matched arrives; the earlier one was never kept (it
  // would have come first).
  reply.request_id = "req-10";
  replies.Write(reply);
  const auto before =
      TakenBeforeMarker(reader, [](const auto& r) { return r.request_id == "req-10"; });
  ASSERT_TRUE(before.has_value()) << "req-10 did not arrive";
  EXPECT_TRUE(before->empty()) << before->front().data.request_id;
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
  msg::CampaignRequest marker;
  marker.request_id = "marker";
  writer.Write(marker);
  const auto before =
      TakenBeforeMarker(reader, [](const auto& r) { return r.request_id == "marker"; });
  ASSERT_TRUE(before.has_value()) << "the marker did not arrive";
  ASSERT_EQ(before->size(), 1u);
  EXPECT_EQ(before->front().data.request_id, "late");
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
  EXPECT_EQ(gone->data.worker_id, "w1");
  EXPECT_EQ(gone->data.slot, 0);
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
  writer.Write(e);                 // ... until the next sample
  EXPECT_TRUE(waits.Wait(5.0));
  EXPECT_EQ(reader.Take().size(), 1u);
}

}  // namespace
}  // namespace rlpos::testing
