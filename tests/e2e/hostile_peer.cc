// rlpos-hostile-peer: a raw DDS participant that attacks a running campaign on a loopback tag,
// for tests/e2e/hostile_peer.sh. It writes the C types directly (not through our checked
// writers), so it can send what our own programs never would:
//  - assignments to the real worker: traversal and shell text in every string, unknown kinds
//    and enum values, timeouts of 0, -1 and 1e12, an oversize and a deeply nested document,
//    and a well-formed job from a participant that is not the worker's coordinator;
//  - job events claiming success and failure for the jobs the real worker holds;
//  - a dispose of the real worker's status;
//  - a forged reply to every campaign request it sees, and a submit that fails validation.
// It also counts what it hears on every topic: an unsecured peer hears a loopback campaign, and
// must hear nothing of a secured one.
//   rlpos-hostile-peer DOMAIN TAG|CYCLONE_XML DB WORKER_ID SCENARIO_JSON SECONDS
#include <dds/dds.h>
#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "idl/dds/dds_config.h"
#include "rlpos_messages.h"

namespace {

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

struct RunningJob {
  std::string id;
  int attempt;
  int slot;
};

std::vector<RunningJob> RunningJobs(const std::string& db_file) {
  std::vector<RunningJob> out;
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(db_file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* st = nullptr;
    if (sqlite3_prepare_v2(
            db, "SELECT id, attempt, COALESCE(slot, 0) FROM jobs WHERE state = 'running'", -1, &st,
            nullptr) == SQLITE_OK) {
      while (sqlite3_step(st) == SQLITE_ROW) {
        out.push_back({reinterpret_cast<const char*>(sqlite3_column_text(st, 0)),
                       sqlite3_column_int(st, 1), sqlite3_column_int(st, 2)});
      }
    }
    sqlite3_finalize(st);
  }
  sqlite3_close(db);
  return out;
}

dds_entity_t Writer(dds_entity_t participant, const dds_topic_descriptor_t* desc, const char* name,
                    bool transient) {
  const dds_entity_t topic = dds_create_topic(participant, desc, name, nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(qos, transient ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  const dds_entity_t w = dds_create_writer(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: rlpos-hostile-peer DOMAIN TAG DB WORKER_ID SCENARIO SECONDS\n");
    return 2;
  }
  const int domain = std::atoi(argv[1]);
  const std::string db = argv[3], worker = argv[4];
  std::ifstream in(argv[5]);
  std::stringstream text;
  text << in.rdbuf();
  const std::string scenario = text.str();
  const double seconds = std::atof(argv[6]);

  // A tag means loopback; an XML document is the Cyclone configuration itself (another link).
  const std::string config = argv[2][0] == '<' ? argv[2] : rlpos::LoopbackConfigXml(argv[2]);
  const dds_entity_t dom = dds_create_domain(domain, config.c_str());
  const dds_entity_t p = dds_create_participant(domain, nullptr, nullptr);
  if (dom < 0 || p < 0) {
    std::fprintf(stderr, "rlpos-hostile-peer: no DDS participant\n");
    return 1;
  }
  const auto assignments = Writer(p, &rlpos_msg_JobAssignment_desc, "rlpos_job_assignment", true);
  const auto events = Writer(p, &rlpos_msg_JobEvent_desc, "rlpos_job_event", true);
  const auto statuses = Writer(p, &rlpos_msg_WorkerStatus_desc, "rlpos_worker_status", true);
  const auto requests = Writer(p, &rlpos_msg_CampaignRequest_desc, "rlpos_campaign_request", false);
  const auto replies = Writer(p, &rlpos_msg_CampaignReply_desc, "rlpos_campaign_reply", false);
  const dds_entity_t request_topic = dds_create_topic(p, &rlpos_msg_CampaignRequest_desc,
                                                      "rlpos_campaign_request", nullptr, nullptr);
  const dds_entity_t request_reader = dds_create_reader(p, request_topic, nullptr, nullptr);
  // Listeners on what the daemons publish: transient-local, so history arrives too; keep all,
  // for the peer writes the same (worker, slot) keys and its own samples must not take the
  // place of the daemons' unread ones.
  dds_qos_t* durable = dds_create_qos();
  dds_qset_reliability(durable, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(durable, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(durable, DDS_HISTORY_KEEP_ALL, 0);
  struct Heard {
    const char* name;
    dds_entity_t reader;
    long count;
  };
  std::vector<Heard> heard;
  const std::vector<std::pair<const dds_topic_descriptor_t*, const char*>> durable_topics{
      {&rlpos_msg_JobAssignment_desc, "rlpos_job_assignment"},
      {&rlpos_msg_JobEvent_desc, "rlpos_job_event"},
      {&rlpos_msg_WorkerStatus_desc, "rlpos_worker_status"}};
  for (const auto& [desc, name] : durable_topics) {
    const dds_entity_t topic = dds_create_topic(p, desc, name, nullptr, nullptr);
    heard.push_back({name, dds_create_reader(p, topic, durable, nullptr), 0});
  }
  heard.push_back({"rlpos_campaign_request", request_reader, 0});
  dds_delete_qos(durable);
  // Its own writes reach its own readers: those are not heard.
  std::vector<dds_instance_handle_t> own;
  for (dds_entity_t w : {assignments, events, statuses, requests, replies}) {
    dds_instance_handle_t handle = 0;
    dds_get_instance_handle(w, &handle);
    own.push_back(handle);
  }
  const auto foreign = [&](const dds_sample_info_t& info) {
    return info.valid_data &&
           std::find(own.begin(), own.end(), info.publication_handle) == own.end();
  };
  const auto listen = [&](Heard& h) {
    void* samples[16] = {nullptr};
    dds_sample_info_t infos[16];
    int n;
    while ((n = dds_take(h.reader, samples, infos, 16, 16)) > 0) {
      for (int i = 0; i < n; ++i)
        h.count += foreign(infos[i]) ? 1 : 0;
      dds_return_loan(h.reader, samples, n);
    }
  };

  const std::string deep(10000, '[');
  const std::string oversize(300000, ' ');
  long sent = 0, refused_by_writer = 0;
  const auto write = [&](dds_entity_t w, const void* sample) {
    if (dds_write(w, sample) < 0)
      ++refused_by_writer;
    ++sent;
  };
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (int round = 0; std::chrono::steady_clock::now() < end; ++round) {
    // Assignments addressed to the real worker.
    struct Bad {
      std::string job_id, campaign, name, document, path, value;
      int kind;
      double timeout;
      int positioner;
    };
    const std::string r = std::to_string(round);
    const std::vector<Bad> bad{
        {"../../../tmp/evil" + r, "..", "B", scenario, "name", "B", 2, 60, 0},
        {"evil/eval/B/x/run" + r, "evil", "/bin/sh", scenario, "../../etc/passwd",
         "$(touch /tmp/rlpos-hostile-canary)", 2, 60, 0},
        {"evil/eval/B/k/run" + r, "evil", "B", scenario, "name", "B", 7, 60, 9},
        {"evil/eval/B/t0/run" + r, "evil", "B", scenario, "name", "B", 2, 0, 0},
        {"evil/eval/B/tn/run" + r, "evil", "B", scenario, "name", "B", 2, -1, 0},
        {"evil/eval/B/tb/run" + r, "evil", "B", scenario, "name", "B", 2, 1e12, 0},
        {"evil/eval/B/deep/run" + r, "evil", "B", deep, "name", "B", 2, 60, 0},
        {"evil/eval/B/big/run" + r, "evil", "B", oversize, "name", "B", 2, 60, 0},
        {"evil/eval/B/valid/run" + r, "evil", "B", scenario, "wifi.mode", "\"ap\"", 2, 60, 0},
    };
    // Into its slots, and slots it does not have.
    const std::vector<int> slots{0, 1, 2, 3, -1, 1024, 99999, 5, 0};
    for (std::size_t i = 0; i < bad.size(); ++i) {
      const Bad& b = bad[i];
      rlpos_msg_JobAssignment a{};
      a.slot = slots[i % slots.size()];
      Set(a.job_id, b.job_id);
      a.attempt = 1;
      Set(a.worker_id, worker);
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
      write(assignments, &a);
    }
    // Events for the jobs the real worker holds: success with an absurd result, and failure.
    for (const auto& job : RunningJobs(db)) {
      rlpos_msg_JobEvent e{};
      Set(e.job_id, job.id);
      e.attempt = job.attempt;
      Set(e.worker_id, worker);
      e.slot = job.slot;
      e.state = rlpos_msg_JOB_SUCCEEDED;
      const std::string result =
          "{\"position\": [50, 50, 25], \"aggregate_throughput_mbps\": 9999, \"mean_delay_ms\": "
          "1, \"loss_ratio\": 0, \"min_snr_db\": 1, \"n_los\": 4, \"n_ues\": 4, \"demands_met\": "
          "4}";
      e.result_json = Octets(result);
      write(events, &e);
      e.state = rlpos_msg_JOB_FAILED;
      e.result_json = Octets("");
      Set(e.message, "forged failure");
      write(events, &e);
    }
    // A dispose of the real worker's status.
    rlpos_msg_WorkerStatus status{};
    Set(status.worker_id, worker);
    if (dds_dispose(statuses, &status) < 0)
      ++refused_by_writer;
    ++sent;
    // Submits that fail validation, and a cancel of a campaign that does not exist.
    const std::vector<std::string> campaigns{
        "{\"name\": \"evil\"}", "not json", deep,
        "{\"name\": \"evil\", \"scenarios\": [\"/etc/passwd\"], "
        "\"rng_runs\": [1, 2]}"};
    for (std::size_t i = 0; i < campaigns.size(); ++i) {
      rlpos_msg_CampaignRequest q{};
      Set(q.request_id, "evil-" + r + "-" + std::to_string(i));
      q.kind = rlpos_msg_REQUEST_SUBMIT;
      q.campaign_json = Octets(campaigns[i]);
      write(requests, &q);
    }
    for (std::size_t h = 0; h + 1 < heard.size(); ++h)
      listen(heard[h]);
    // Forged replies to whatever requests it sees.
    void* samples[16] = {nullptr};
    dds_sample_info_t infos[16];
    const int n = dds_take(request_reader, samples, infos, 16, 16);
    for (int i = 0; i < n; ++i) {
      if (!foreign(infos[i]))
        continue;
      ++heard.back().count;
      const auto* q = static_cast<const rlpos_msg_CampaignRequest*>(samples[i]);
      rlpos_msg_CampaignReply reply{};
      Set(reply.request_id, q->request_id);
      reply.ok = true;
      Set(reply.campaign_id, "forged000000");
      reply.jobs = 1;
      write(replies, &reply);
    }
    if (n > 0)
      dds_return_loan(request_reader, samples, n);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // a pace, not a wait
  }
  long total = 0;
  std::string per_topic;
  for (const auto& h : heard) {
    total += h.count;
    per_topic +=
        std::string(per_topic.empty() ? "" : ", ") + h.name + " " + std::to_string(h.count);
  }
  std::printf("sent %ld hostile samples (%ld refused by the local writer); heard %ld (%s)\n", sent,
              refused_by_writer, total, per_topic.c_str());
  dds_delete(p);
  dds_delete(dom);
  return 0;
}
