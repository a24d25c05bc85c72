// rlpos-hostile-peer: a raw DDS participant that attacks a running campaign on a loopback tag,
// for tests/e2e/hostile_peer.sh. It writes the C types directly (not through our checked
// writers), so it can send what our own programs never would:
//  - assignments to the real worker: traversal and shell text in every string, unknown kinds
//    and enum values, timeouts of 0, -1 and 1e12, an oversize and a deeply nested document,
//    and a well-formed job from a participant that is not the worker's coordinator;
//  - job events claiming success and failure for the jobs the real worker holds;
//  - a dispose of the real worker's status;
//  - a forged reply to every campaign request it sees, at once (so that it races the
//    coordinator's), and a submit that fails validation.
// It also counts what it hears on every topic: an unsecured peer hears a loopback campaign, and
// must hear nothing of a secured one. What another hostile peer writes (its writers carry the
// USER_DATA "rlpos-hostile-peer") is counted apart: two unsecured peers hear each other, the
// positive control that the place where one hears nothing of a campaign carries traffic.
// With --write-only it makes no reader: it attacks and is heard, and hears nothing; what others
// write then never goes to it (secured_campaign.sh's control, on a link that is captured).
// Its stdout, a line each, flushed:
//   matched the daemons        its readers matched a writer of assignments (the coordinator's)
//                              and one of worker statuses (the worker's), peers aside
//   forged a reply to ID       when a client's reply reader was matched at the time
//   sent ...; heard N (...); forged F replies; heard from peers P      at the end
//   rlpos-hostile-peer DOMAIN TAG|CYCLONE_XML DB WORKER_ID SCENARIO_JSON SECONDS [--write-only]
#include <dds/dds.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"
#include "idl/dds/dds_config.h"
#include "rlpos_messages.h"
#include "tests/support/program_usage.h"

namespace {

using Clock = std::chrono::steady_clock;

constexpr char kPeerMark[] = "rlpos-hostile-peer";

template <std::size_t N>
void Set(char (&to)[N], const std::string& from) {
  std::snprintf(to, N, "%s", from.c_str());
}

dds_sequence_octet Octets(const std::string& s) {
  dds_sequence_octet seq{};
  seq._maximum = seq._length = static_cast<uint32_t>(s.size());
  seq._buffer = reinterpret_cast<uint8_t*>(const_cast<char*>(s.data()));
  return seq;
}

void Say(const std::string& line) {
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

struct RunningJob {
  std::string id;
  int attempt;
  int slot;
};

std::vector<RunningJob> RunningJobs(const std::string& db_file) {
  std::vector<RunningJob> out;
  // What could be read is enough: a peer that finds no database (or a busy one) attacks no job.
  try {
    rlpos::Database db(db_file, /*read_only=*/true, /*busy_timeout_ms=*/0);
    rlpos::Statement running = db.Prepare(
        "SELECT id, attempt, COALESCE(slot, 0) AS slot FROM jobs WHERE state = 'running'");
    const rlpos::ResultColumn id = running.Column("id"), attempt = running.Column("attempt"),
                              slot = running.Column("slot");
    while (running.Step()) {
      out.push_back({running.Text(id), static_cast<int>(running.Int(attempt)),
                     static_cast<int>(running.Int(slot))});
    }
  } catch (const rlpos::StoreError&) {
  }
  return out;
}

// A writer that says it is a hostile peer's (USER_DATA), for other peers to tell it apart.
dds_entity_t Writer(dds_entity_t participant, const dds_topic_descriptor_t* desc, const char* name,
                    bool transient) {
  const dds_entity_t topic = dds_create_topic(participant, desc, name, nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, transient ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_userdata(qos, kPeerMark, std::strlen(kPeerMark));
  const dds_entity_t w = dds_create_writer(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  return w;
}

// A listener on what the daemons publish: transient-local, so history arrives too; keep all,
// for the peer writes the same (worker, slot) keys and its own samples must not take the place
// of the daemons' unread ones.
dds_entity_t DurableReader(dds_entity_t participant, const dds_topic_descriptor_t* desc,
                           const char* name) {
  const dds_entity_t topic = dds_create_topic(participant, desc, name, nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t r = dds_create_reader(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  return r;
}

struct Options {
  int domain;
  std::string config, db, worker, scenario;
  double seconds;
  bool write_only;
};

class HostilePeer {
 public:
  HostilePeer(dds_entity_t participant, const Options& options);
  ~HostilePeer() { dds_delete(waitset_); }
  void Run(double seconds);
  std::string Summary() const;

 private:
  struct Heard {
    const char* name;
    dds_entity_t reader;
    long count;
  };
  void AttackRound(int round);
  void WriteAssignments(const std::string& r);
  void WriteEvents();
  void WriteSubmits(const std::string& r);
  void Write(dds_entity_t w, const void* sample);
  void ForgeReplies();
  void Listen(Heard& h);
  void SayWhenMatched();
  bool Own(dds_instance_handle_t publication) const;
  bool FromPeer(dds_entity_t reader, dds_instance_handle_t publication);
  int ForeignWriters(dds_entity_t reader);

  const Options options_;
  dds_entity_t assignments_, events_, statuses_, requests_, replies_;
  dds_entity_t request_reader_ = 0, waitset_;
  std::vector<Heard> heard_;                     // what the daemons (or clients) wrote
  long from_peers_ = 0;                          // what other hostile peers wrote
  std::map<dds_instance_handle_t, bool> peers_;  // publication -> a hostile peer's
  std::vector<dds_instance_handle_t> own_;
  long sent_ = 0, refused_by_writer_ = 0, forged_ = 0;
  bool matched_ = false;
  const std::string deep_ = std::string(10000, '[');
  const std::string oversize_ = std::string(300000, ' ');
};

HostilePeer::HostilePeer(dds_entity_t p, const Options& options) : options_(options) {
  assignments_ = Writer(p, &rlpos_msg_JobAssignment_desc, "rlpos_job_assignment", true);
  events_ = Writer(p, &rlpos_msg_JobEvent_desc, "rlpos_job_event", true);
  statuses_ = Writer(p, &rlpos_msg_WorkerStatus_desc, "rlpos_worker_status", true);
  requests_ = Writer(p, &rlpos_msg_CampaignRequest_desc, "rlpos_campaign_request", false);
  replies_ = Writer(p, &rlpos_msg_CampaignReply_desc, "rlpos_campaign_reply", false);
  const dds_entity_t request_topic = dds_create_topic(p, &rlpos_msg_CampaignRequest_desc,
                                                      "rlpos_campaign_request", nullptr, nullptr);
  waitset_ = dds_create_waitset(p);
  // Its own writes reach its own readers: those are not heard.
  for (dds_entity_t w : {assignments_, events_, statuses_, requests_, replies_}) {
    dds_instance_handle_t handle = 0;
    dds_get_instance_handle(w, &handle);
    own_.push_back(handle);
  }
  if (options.write_only)
    return;
  request_reader_ = dds_create_reader(p, request_topic, nullptr, nullptr);
  heard_ = {{"rlpos_job_assignment",
             DurableReader(p, &rlpos_msg_JobAssignment_desc, "rlpos_job_assignment"), 0},
            {"rlpos_job_event", DurableReader(p, &rlpos_msg_JobEvent_desc, "rlpos_job_event"), 0},
            {"rlpos_worker_status",
             DurableReader(p, &rlpos_msg_WorkerStatus_desc, "rlpos_worker_status"), 0},
            {"rlpos_campaign_request", request_reader_, 0}};
  // Woken at once by a request, to forge its reply before the coordinator answers.
  dds_waitset_attach(waitset_, dds_create_readcondition(request_reader_, DDS_ANY_STATE), 0);
}

void HostilePeer::Run(double seconds) {
  const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(seconds));
  auto next_round = Clock::now();
  for (int round = 0; Clock::now() < end;) {
    ForgeReplies();
    if (Clock::now() >= next_round) {
      AttackRound(round++);
      for (std::size_t h = 0; h + 1 < heard_.size(); ++h)
        Listen(heard_[h]);
      SayWhenMatched();
      next_round += std::chrono::milliseconds(200);  // a pace, not a wait
    }
    const auto until = std::min(next_round, end);
    const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(until - Clock::now());
    dds_waitset_wait(waitset_, nullptr, 0, std::max<dds_duration_t>(0, left.count()));
  }
  ForgeReplies();
  for (std::size_t h = 0; h + 1 < heard_.size(); ++h)
    Listen(heard_[h]);
}

void HostilePeer::AttackRound(int round) {
  const std::string r = std::to_string(round);
  WriteAssignments(r);
  WriteEvents();
  // A dispose of the real worker's status.
  rlpos_msg_WorkerStatus status{};
  Set(status.worker_id, options_.worker);
  if (dds_dispose(statuses_, &status) < 0)
    ++refused_by_writer_;
  ++sent_;
  WriteSubmits(r);
}

void HostilePeer::Write(dds_entity_t w, const void* sample) {
  if (dds_write(w, sample) < 0)
    ++refused_by_writer_;
  ++sent_;
}

// Assignments addressed to the real worker, into its slots and slots it does not have.
void HostilePeer::WriteAssignments(const std::string& r) {
  struct Bad {
    std::string job_id, campaign, name, document, path, value;
    int kind;
    double timeout;
    int positioner;
  };
  const std::string& scenario = options_.scenario;
  const std::vector<Bad> bad{
      {"../../../tmp/evil" + r, "..", "B", scenario, "name", "B", 2, 60, 0},
      {"evil/eval/B/x/run" + r, "evil", "/bin/sh", scenario, "../../etc/passwd",
       "$(touch /tmp/rlpos-hostile-canary)", 2, 60, 0},
      {"evil/eval/B/k/run" + r, "evil", "B", scenario, "name", "B", 7, 60, 9},
      {"evil/eval/B/t0/run" + r, "evil", "B", scenario, "name", "B", 2, 0, 0},
      {"evil/eval/B/tn/run" + r, "evil", "B", scenario, "name", "B", 2, -1, 0},
      {"evil/eval/B/tb/run" + r, "evil", "B", scenario, "name", "B", 2, 1e12, 0},
      {"evil/eval/B/deep/run" + r, "evil", "B", deep_, "name", "B", 2, 60, 0},
      {"evil/eval/B/big/run" + r, "evil", "B", oversize_, "name", "B", 2, 60, 0},
      {"evil/eval/B/valid/run" + r, "evil", "B", scenario, "wifi.mode", "\"ap\"", 2, 60, 0},
  };
  const std::vector<int> slots{0, 1, 2, 3, -1, 1024, 99999, 5, 0};
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const Bad& b = bad[i];
    rlpos_msg_JobAssignment a{};
    a.slot = slots[i % slots.size()];
    Set(a.job_id, b.job_id);
    a.attempt = 1;
    Set(a.worker_id, options_.worker);
    Set(a.campaign_id, b.campaign);
    a.timeout_s = b.timeout;
    a.kind = static_cast<rlpos_msg_JobKind>(b.kind);
    Set(a.scenario, b.name);
    a.scenario_document = Octets(b.document);
    rlpos_msg_ScenarioOverride o{};
    Set(o.path, b.path);
    Set(o.value, b.value);
    a.overrides._maximum = a.overrides._length = 1;
    a.overrides._buffer = &o;
    a.positioner = static_cast<rlpos_msg_Positioner>(b.positioner);
    rlpos_msg_UavPosition position{50, 50, 25};
    a.positions._maximum = a.positions._length = 1;
    a.positions._buffer = &position;
    a.rng_run = 1;
    Write(assignments_, &a);
  }
}

// Events for the jobs the real worker holds: success with an absurd result, and failure.
void HostilePeer::WriteEvents() {
  const std::string result =
      "{\"position\": [50, 50, 25], \"aggregate_throughput_mbps\": 9999, \"mean_delay_ms\": "
      "1, \"loss_ratio\": 0, \"min_snr_db\": 1, \"n_los\": 4, \"n_ues\": 4, \"demands_met\": "
      "4}";
  for (const auto& job : RunningJobs(options_.db)) {
    rlpos_msg_JobEvent e{};
    Set(e.job_id, job.id);
    e.attempt = job.attempt;
    Set(e.worker_id, options_.worker);
    e.slot = job.slot;
    e.state = rlpos_msg_JOB_SUCCEEDED;
    e.result_json = Octets(result);
    Write(events_, &e);
    e.state = rlpos_msg_JOB_FAILED;
    e.result_json = Octets("");
    Set(e.message, "forged failure");
    Write(events_, &e);
  }
}

// Submits that fail validation.
void HostilePeer::WriteSubmits(const std::string& r) {
  const std::vector<std::string> campaigns{"{\"name\": \"evil\"}", "not json", deep_,
                                           "{\"name\": \"evil\", \"scenarios\": [\"/etc/passwd\"], "
                                           "\"rng_runs\": [1, 2]}"};
  for (std::size_t i = 0; i < campaigns.size(); ++i) {
    rlpos_msg_CampaignRequest q{};
    Set(q.request_id, "evil-" + r + "-" + std::to_string(i));
    q.kind = rlpos_msg_REQUEST_SUBMIT;
    q.campaign_json = Octets(campaigns[i]);
    Write(requests_, &q);
  }
}

// A forged reply to every request it sees; said when a client's reply reader was there to get
// it (the peer has no reader of replies itself).
void HostilePeer::ForgeReplies() {
  if (heard_.empty())
    return;  // --write-only
  ForeignWriters(request_reader_);
  void* samples[16] = {nullptr};
  dds_sample_info_t infos[16];
  const int n = dds_take(request_reader_, samples, infos, 16, 16);
  for (int i = 0; i < n; ++i) {
    if (!infos[i].valid_data || Own(infos[i].publication_handle))
      continue;
    if (FromPeer(request_reader_, infos[i].publication_handle)) {
      ++from_peers_;
      continue;
    }
    ++heard_.back().count;
    const auto* q = static_cast<const rlpos_msg_CampaignRequest*>(samples[i]);
    rlpos_msg_CampaignReply reply{};
    Set(reply.request_id, q->request_id);
    reply.ok = true;
    Set(reply.campaign_id, "forged000000");
    reply.jobs = 1;
    dds_publication_matched_status_t clients{};
    dds_get_publication_matched_status(replies_, &clients);
    Write(replies_, &reply);
    if (clients.current_count > 0) {
      ++forged_;
      Say(std::string("forged a reply to ") + q->request_id);
    }
  }
  if (n > 0)
    dds_return_loan(request_reader_, samples, n);
}

void HostilePeer::Listen(Heard& h) {
  ForeignWriters(h.reader);  // who each matched writer is, looked up while it is there
  void* samples[16] = {nullptr};
  dds_sample_info_t infos[16];
  int n;
  while ((n = dds_take(h.reader, samples, infos, 16, 16)) > 0) {
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data || Own(infos[i].publication_handle))
        continue;
      ++(FromPeer(h.reader, infos[i].publication_handle) ? from_peers_ : h.count);
    }
    dds_return_loan(h.reader, samples, n);
  }
}

// Once: its readers of assignments and of worker statuses each matched a writer that is
// neither its own nor a peer's, i.e. the coordinator and the worker discovered it.
void HostilePeer::SayWhenMatched() {
  if (!matched_ && !heard_.empty() && ForeignWriters(heard_[0].reader) > 0 &&
      ForeignWriters(heard_[2].reader) > 0) {
    matched_ = true;
    Say("matched the daemons");
  }
}

bool HostilePeer::Own(dds_instance_handle_t publication) const {
  return std::find(own_.begin(), own_.end(), publication) != own_.end();
}

// Whether a publication is another hostile peer's, by its USER_DATA, remembered: a writer that
// is gone can no longer be looked up, and its last samples may still be unread.
bool HostilePeer::FromPeer(dds_entity_t reader, dds_instance_handle_t publication) {
  const auto known = peers_.find(publication);
  if (known != peers_.end())
    return known->second;
  dds_builtintopic_endpoint_t* writer = dds_get_matched_publication_data(reader, publication);
  if (writer == nullptr)
    return false;
  void* value = nullptr;
  size_t size = 0;
  const bool peer = dds_qget_userdata(writer->qos, &value, &size) &&
                    size == std::strlen(kPeerMark) && std::memcmp(value, kPeerMark, size) == 0;
  dds_free(value);
  dds_builtintopic_free_endpoint(writer);
  peers_[publication] = peer;
  return peer;
}

// The writers matched with `reader` that are neither its own nor another peer's (FromPeer
// remembers which are a peer's).
int HostilePeer::ForeignWriters(dds_entity_t reader) {
  dds_instance_handle_t writers[64];
  const int n = std::min<int>(dds_get_matched_publications(reader, writers, 64), 64);
  int foreign = 0;
  for (int i = 0; i < n; ++i)
    foreign += !Own(writers[i]) && !FromPeer(reader, writers[i]) ? 1 : 0;
  return foreign;
}

std::string HostilePeer::Summary() const {
  long total = 0;
  std::string per_topic;
  for (const auto& h : heard_) {
    total += h.count;
    per_topic +=
        std::string(per_topic.empty() ? "" : ", ") + h.name + " " + std::to_string(h.count);
  }
  return "sent " + std::to_string(sent_) + " hostile samples (" +
         std::to_string(refused_by_writer_) + " refused by the local writer); heard " +
         std::to_string(total) + " (" + per_topic + "); forged " + std::to_string(forged_) +
         " replies; heard from peers " + std::to_string(from_peers_);
}

std::string ReadFile(const char* path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] =
      "usage: rlpos-hostile-peer DOMAIN TAG DB WORKER_ID SCENARIO SECONDS [--write-only]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  const bool write_only = argc == 8 && std::strcmp(argv[7], "--write-only") == 0;
  if (argc != 7 && !write_only)
    return rlpos::testing::UsageError(kUsage);
  Options options;
  options.domain = std::atoi(argv[1]);
  // A tag means loopback; an XML document is the Cyclone configuration itself (another link).
  options.config = argv[2][0] == '<' ? argv[2] : rlpos::LoopbackConfigXml(argv[2]);
  options.db = argv[3];
  options.worker = argv[4];
  options.scenario = ReadFile(argv[5]);
  options.seconds = std::atof(argv[6]);
  options.write_only = write_only;

  const dds_entity_t dom = dds_create_domain(options.domain, options.config.c_str());
  const dds_entity_t p = dds_create_participant(options.domain, nullptr, nullptr);
  if (dom < 0 || p < 0) {
    std::fprintf(stderr, "rlpos-hostile-peer: no DDS participant\n");
    return 1;
  }
  {
    HostilePeer peer(p, options);
    peer.Run(options.seconds);
    Say(peer.Summary());
  }
  dds_delete(p);
  dds_delete(dom);
  return 0;
}
