#include "idl/dds/topics.h"

#include <dds/dds.h>

#include <cstring>
#include <memory>

#include "idl/dds/topic_names.h"
#include "rlpos_messages.h"
#include "common/wire/limits.h"

namespace rlpos {
namespace {

using QosPtr = std::unique_ptr<dds_qos_t, void (*)(dds_qos_t*)>;

QosPtr NewQos() {
  return QosPtr(dds_create_qos(), dds_delete_qos);
}

// Bounded strings are inline arrays in Cyclone's C mapping: copy in, refusing what does not fit
// (the validators keep the daemons' own messages within bounds, so this only catches a bug).
template <std::size_t N>
void CopyIn(char (&to)[N], const std::string& from, const char* field) {
  if (from.size() >= N || from.find('\0') != std::string::npos) {
    throw DdsError(std::string(field) + ": " + std::to_string(from.size()) +
                   " bytes do not fit the message's bound of " + std::to_string(N - 1));
  }
  std::memcpy(to, from.data(), from.size());
  to[from.size()] = '\0';
}

// A received array is NUL-terminated by Cyclone's decoder; strnlen keeps to the array anyway.
template <std::size_t N>
std::string CopyOut(const char (&from)[N]) {
  return std::string(from, strnlen(from, N));
}

// Octet sequences borrow the C++ string for the write (dds_write serializes before returning).
dds_sequence_octet BorrowOctets(const std::string& s, std::size_t bound, const char* field) {
  if (s.size() > bound) {
    throw DdsError(std::string(field) + ": " + std::to_string(s.size()) +
                   " bytes exceed the message's bound of " + std::to_string(bound));
  }
  dds_sequence_octet seq{};
  seq._maximum = seq._length = static_cast<uint32_t>(s.size());
  seq._buffer = reinterpret_cast<uint8_t*>(const_cast<char*>(s.data()));
  seq._release = false;
  return seq;
}

// Sets `error` when the sequence exceeds `bound` (a decoder that let it through).
std::string CopyOctets(const dds_sequence_octet& seq, std::size_t bound, const char* field,
                       std::string& error) {
  if (seq._length > bound || (seq._length > 0 && seq._buffer == nullptr)) {
    error = std::string(field) + " exceeds its bound";
    return {};
  }
  return std::string(reinterpret_cast<const char*>(seq._buffer), seq._length);
}

// The integer in a received enum field, read as bytes: loading a C enum that holds a value
// outside its enumerators is undefined behaviour in C++, and the wire may hold any value.
template <typename E>
int RawEnum(const E& field) {
  static_assert(sizeof(E) == sizeof(std::int32_t), "Cyclone's C enums are 32-bit");
  std::int32_t value;
  std::memcpy(&value, &field, sizeof value);
  return value;
}

// An enum from the wire: `error` unless 0 <= value < count.
template <typename E>
E CheckedEnum(int value, int count, const char* field, std::string& error) {
  if (value < 0 || value >= count) {
    error = std::string(field) + " " + std::to_string(value) + " is unknown";
    return E{};
  }
  return static_cast<E>(value);
}

template <typename M>
struct Traits;

template <>
struct Traits<msg::WorkerStatus> {
  using C = rlpos_msg_WorkerStatus;
  static constexpr const char* kTopic = topic::kWorkerStatus;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_WorkerStatus_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    // Automatic liveliness rides on the participant's lease (short in the loopback config).
    if (writer) {
      dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
      // A worker that stops cleanly disposes its status itself; a lost one must show as
      // no-writers, and Cyclone would otherwise dispose on its behalf.
      dds_qset_writer_data_lifecycle(qos, false);
    }
  }
  struct Holder {
    C c{};
    struct JobKey {
      char text[301];
    };
    std::vector<JobKey> jobs;
  };
  static void ToC(const msg::WorkerStatus& m, Holder& h) {
    CopyIn(h.c.worker_id, m.worker_id, "worker_id");
    CopyIn(h.c.host, m.host, "host");
    h.c.pid = m.pid;
    h.c.slots = m.slots;
    h.c.busy = m.busy;
    if (m.jobs.size() > wire::kMaxWorkerJobs)
      throw DdsError("jobs: too many");
    h.jobs.assign(m.jobs.size(), Holder::JobKey{});
    for (std::size_t i = 0; i < m.jobs.size(); ++i)
      CopyIn(h.jobs[i].text, m.jobs[i], "jobs");
    static_assert(sizeof(Holder::JobKey) == sizeof(*h.c.jobs._buffer));
    h.c.jobs._maximum = h.c.jobs._length = static_cast<uint32_t>(m.jobs.size());
    h.c.jobs._buffer =
        h.jobs.empty() ? nullptr : reinterpret_cast<decltype(h.c.jobs._buffer)>(h.jobs.data());
    h.c.jobs._release = false;
  }
  static msg::WorkerStatus FromC(const C& c, bool valid, std::string& error) {
    msg::WorkerStatus m;
    m.worker_id = CopyOut(c.worker_id);
    if (!valid)
      return m;
    m.host = CopyOut(c.host);
    m.pid = c.pid;
    m.slots = c.slots;
    m.busy = c.busy;
    if (c.jobs._length > wire::kMaxWorkerJobs || (c.jobs._length > 0 && !c.jobs._buffer)) {
      error = "jobs exceed their bound";
      return m;
    }
    for (uint32_t i = 0; i < c.jobs._length; ++i)
      m.jobs.push_back(CopyOut(c.jobs._buffer[i]));
    return m;
  }
};

template <>
struct Traits<msg::JobAssignment> {
  using C = rlpos_msg_JobAssignment;
  static constexpr const char* kTopic = topic::kJobAssignment;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_JobAssignment_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    if (writer) {
      dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
      dds_qset_writer_data_lifecycle(qos, false);
    } else {
      // Every sample of a slot, in order: an emptied slot followed by its next job, and no
      // other writer's sample of the same slot can take the coordinator's place unread.
      dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    }
  }
  struct Holder {
    C c{};
    std::vector<rlpos_msg_ScenarioOverride> overrides;
    std::vector<rlpos_msg_UavPosition> positions;
  };
  static void ToC(const msg::JobAssignment& m, Holder& h) {
    const JobOrder& o = m.order;
    const JobParams& p = o.params;
    CopyIn(h.c.worker_id, m.worker_id, "worker_id");
    h.c.slot = m.slot;
    CopyIn(h.c.job_id, o.job_id, "job_id");
    h.c.attempt = o.attempt;
    CopyIn(h.c.campaign_id, o.campaign_id, "campaign_id");
    h.c.timeout_s = o.timeout_s;
    h.c.kind = static_cast<rlpos_msg_JobKind>(p.kind);
    CopyIn(h.c.scenario, p.scenario, "scenario");
    h.c.scenario_document =
        BorrowOctets(o.scenario_document, wire::kMaxScenarioDocument, "scenario_document");
    if (p.overrides.size() > wire::kMaxOverrides)
      throw DdsError("overrides: too many");
    h.overrides.assign(p.overrides.size(), rlpos_msg_ScenarioOverride{});
    for (std::size_t i = 0; i < p.overrides.size(); ++i) {
      CopyIn(h.overrides[i].path, p.overrides[i].path, "override path");
      CopyIn(h.overrides[i].value, p.overrides[i].value, "override value");
    }
    h.c.overrides._maximum = h.c.overrides._length = static_cast<uint32_t>(h.overrides.size());
    h.c.overrides._buffer = h.overrides.empty() ? nullptr : h.overrides.data();
    h.c.overrides._release = false;
    h.c.has_train_seed = p.train_seed.has_value();
    h.c.train_seed = p.train_seed.value_or(0);
    h.c.fidelity = p.fidelity == "packet" ? rlpos_msg_FIDELITY_PACKET : rlpos_msg_FIDELITY_ANALYTIC;
    h.c.train_episodes = p.train_episodes.value_or(0);
    h.c.positioner = p.positioner == "baseline"   ? rlpos_msg_POSITIONER_BASELINE
                     : p.positioner == "centroid" ? rlpos_msg_POSITIONER_CENTROID
                     : p.positioner == "oracle"   ? rlpos_msg_POSITIONER_ORACLE
                                                  : rlpos_msg_POSITIONER_NONE;
    const Placement none;
    const Placement& placement = o.placement ? *o.placement : none;
    if (placement.size() > wire::kMaxUavPositions)
      throw DdsError("positions: too many");
    h.positions.clear();
    for (const Vec3& q : placement)
      h.positions.push_back({q.x, q.y, q.z});
    h.c.positions._maximum = h.c.positions._length = static_cast<uint32_t>(h.positions.size());
    h.c.positions._buffer = h.positions.empty() ? nullptr : h.positions.data();
    h.c.positions._release = false;
    h.c.rng_run = p.rng_run.value_or(0);
    h.c.has_duration = p.duration_s.has_value();
    h.c.duration_s = p.duration_s.value_or(0);
    h.c.has_warmup = p.warmup_s.has_value();
    h.c.warmup_s = p.warmup_s.value_or(0);
  }
  static msg::JobAssignment FromC(const C& c, bool valid, std::string& error) {
    msg::JobAssignment m;
    JobOrder& o = m.order;
    JobParams& p = o.params;
    m.worker_id = CopyOut(c.worker_id);
    m.slot = c.slot;
    if (!valid)
      return m;
    o.job_id = CopyOut(c.job_id);
    o.attempt = c.attempt;
    o.campaign_id = CopyOut(c.campaign_id);
    o.timeout_s = c.timeout_s;
    p.kind = CheckedEnum<JobKind>(RawEnum(c.kind), 3, "kind", error);
    p.scenario = CopyOut(c.scenario);
    o.scenario_document =
        CopyOctets(c.scenario_document, wire::kMaxScenarioDocument, "scenario_document", error);
    if (c.overrides._length > wire::kMaxOverrides ||
        (c.overrides._length > 0 && !c.overrides._buffer)) {
      error = "overrides exceed their bound";
      return m;
    }
    for (uint32_t i = 0; i < c.overrides._length; ++i) {
      p.overrides.push_back(
          {CopyOut(c.overrides._buffer[i].path), CopyOut(c.overrides._buffer[i].value)});
    }
    if (c.has_train_seed)
      p.train_seed = c.train_seed;
    const int fidelity = RawEnum(c.fidelity);
    if (fidelity < 0 || fidelity > 1)
      error = "fidelity " + std::to_string(fidelity) + " is unknown";
    if (p.kind == JobKind::kTrain)
      p.fidelity = fidelity == 1 ? "packet" : "analytic";
    if (c.train_episodes != 0)
      p.train_episodes = c.train_episodes;
    switch (RawEnum(c.positioner)) {
      case rlpos_msg_POSITIONER_NONE:
        break;
      case rlpos_msg_POSITIONER_BASELINE:
        p.positioner = "baseline";
        break;
      case rlpos_msg_POSITIONER_CENTROID:
        p.positioner = "centroid";
        break;
      case rlpos_msg_POSITIONER_ORACLE:
        p.positioner = "oracle";
        break;
      default:
        error = "positioner " + std::to_string(RawEnum(c.positioner)) + " is unknown";
    }
    if (c.positions._length > wire::kMaxUavPositions ||
        (c.positions._length > 0 && !c.positions._buffer)) {
      error = "positions exceed their bound";
      return m;
    }
    if (c.positions._length > 0) {
      o.placement.emplace();
      for (uint32_t i = 0; i < c.positions._length; ++i) {
        const rlpos_msg_UavPosition& q = c.positions._buffer[i];
        o.placement->push_back({q.x, q.y, q.z});
      }
    }
    if (p.kind == JobKind::kEval)
      p.rng_run = c.rng_run;
    if (c.has_duration)
      p.duration_s = c.duration_s;
    if (c.has_warmup)
      p.warmup_s = c.warmup_s;
    return m;
  }
};

template <>
struct Traits<msg::JobEvent> {
  using C = rlpos_msg_JobEvent;
  static constexpr const char* kTopic = topic::kJobEvent;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_JobEvent_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    if (writer) {
      dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    } else {
      dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    }
  }
  struct Holder {
    C c{};
    std::vector<rlpos_msg_ArtifactFile> artifacts;
  };
  static void ToC(const msg::JobEvent& m, Holder& h) {
    CopyIn(h.c.worker_id, m.worker_id, "worker_id");
    h.c.slot = m.slot;
    CopyIn(h.c.job_id, m.job_id, "job_id");
    h.c.attempt = m.attempt;
    h.c.state = static_cast<rlpos_msg_JobState>(m.state);
    h.c.result_json = BorrowOctets(m.result_json, wire::kMaxResultJson, "result_json");
    CopyIn(h.c.message, m.message, "message");
    const Provenance& p = m.provenance;
    auto& cp = h.c.provenance;
    CopyIn(cp.host, p.host, "provenance host");
    CopyIn(cp.rlpos_version, p.rlpos_version, "provenance rlpos_version");
    CopyIn(cp.ns3_version, p.ns3_version, "provenance ns3_version");
    CopyIn(cp.torch_version, p.torch_version, "provenance torch_version");
    CopyIn(cp.cyclonedds_version, p.cyclonedds_version, "provenance cyclonedds_version");
    CopyIn(cp.scenario_sha256, p.scenario_sha256, "provenance scenario_sha256");
    if (m.artifacts.size() > wire::kMaxArtifacts)
      throw DdsError("artifacts: too many");
    h.artifacts.assign(m.artifacts.size(), rlpos_msg_ArtifactFile{});
    for (std::size_t i = 0; i < m.artifacts.size(); ++i) {
      CopyIn(h.artifacts[i].name, m.artifacts[i].name, "artifact name");
      CopyIn(h.artifacts[i].sha256, m.artifacts[i].sha256, "artifact sha256");
      h.artifacts[i].data = BorrowOctets(m.artifacts[i].data, wire::kMaxArtifactBytes, "artifact");
    }
    h.c.artifacts._maximum = h.c.artifacts._length = static_cast<uint32_t>(h.artifacts.size());
    h.c.artifacts._buffer = h.artifacts.empty() ? nullptr : h.artifacts.data();
    h.c.artifacts._release = false;
  }
  static msg::JobEvent FromC(const C& c, bool valid, std::string& error) {
    msg::JobEvent m;
    m.worker_id = CopyOut(c.worker_id);
    m.slot = c.slot;
    if (!valid)
      return m;
    m.job_id = CopyOut(c.job_id);
    m.attempt = c.attempt;
    m.state = CheckedEnum<msg::JobState>(RawEnum(c.state), 4, "state", error);
    m.result_json = CopyOctets(c.result_json, wire::kMaxResultJson, "result_json", error);
    m.message = CopyOut(c.message);
    m.provenance = {CopyOut(c.provenance.host),
                    CopyOut(c.provenance.rlpos_version),
                    CopyOut(c.provenance.ns3_version),
                    CopyOut(c.provenance.torch_version),
                    CopyOut(c.provenance.cyclonedds_version),
                    CopyOut(c.provenance.scenario_sha256)};
    if (c.artifacts._length > wire::kMaxArtifacts ||
        (c.artifacts._length > 0 && !c.artifacts._buffer)) {
      error = "artifacts exceed their bound";
      return m;
    }
    for (uint32_t i = 0; i < c.artifacts._length; ++i) {
      const auto& a = c.artifacts._buffer[i];
      m.artifacts.push_back({CopyOut(a.name), CopyOut(a.sha256),
                             CopyOctets(a.data, wire::kMaxArtifactBytes, "artifact", error)});
    }
    return m;
  }
};

template <>
struct Traits<msg::CampaignRequest> {
  using C = rlpos_msg_CampaignRequest;
  static constexpr const char* kTopic = topic::kCampaignRequest;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignRequest_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  }
  struct Holder {
    C c{};
    std::vector<rlpos_msg_ScenarioFile> scenarios;
  };
  static void ToC(const msg::CampaignRequest& m, Holder& h) {
    CopyIn(h.c.request_id, m.request_id, "request_id");
    h.c.kind = static_cast<rlpos_msg_RequestKind>(m.kind);
    CopyIn(h.c.campaign_id, m.campaign_id, "campaign_id");
    h.c.campaign_json = BorrowOctets(m.campaign_json, wire::kMaxCampaignJson, "campaign_json");
    h.c.no_cache = m.no_cache;
    if (m.scenarios.size() > wire::kMaxCampaignScenarios)
      throw DdsError("scenarios: too many");
    h.scenarios.assign(m.scenarios.size(), rlpos_msg_ScenarioFile{});
    for (std::size_t i = 0; i < m.scenarios.size(); ++i) {
      CopyIn(h.scenarios[i].file, m.scenarios[i].file, "scenario file");
      h.scenarios[i].document =
          BorrowOctets(m.scenarios[i].document, wire::kMaxScenarioDocument, "scenario document");
    }
    h.c.scenarios._maximum = h.c.scenarios._length = static_cast<uint32_t>(h.scenarios.size());
    h.c.scenarios._buffer = h.scenarios.empty() ? nullptr : h.scenarios.data();
    h.c.scenarios._release = false;
  }
  static msg::CampaignRequest FromC(const C& c, bool valid, std::string& error) {
    msg::CampaignRequest m;
    m.request_id = CopyOut(c.request_id);
    if (!valid)
      return m;
    m.kind = CheckedEnum<msg::RequestKind>(RawEnum(c.kind), 3, "kind", error);
    m.campaign_id = CopyOut(c.campaign_id);
    m.campaign_json = CopyOctets(c.campaign_json, wire::kMaxCampaignJson, "campaign_json", error);
    m.no_cache = c.no_cache;
    if (c.scenarios._length > wire::kMaxCampaignScenarios ||
        (c.scenarios._length > 0 && !c.scenarios._buffer)) {
      error = "scenarios exceed their bound";
      return m;
    }
    for (uint32_t i = 0; i < c.scenarios._length; ++i) {
      m.scenarios.push_back({CopyOut(c.scenarios._buffer[i].file),
                             CopyOctets(c.scenarios._buffer[i].document, wire::kMaxScenarioDocument,
                                        "scenario document", error)});
    }
    return m;
  }
};

template <>
struct Traits<msg::CampaignReply> {
  using C = rlpos_msg_CampaignReply;
  static constexpr const char* kTopic = topic::kCampaignReply;
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignReply_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  }
  struct Holder {
    C c{};
  };
  static void ToC(const msg::CampaignReply& m, Holder& h) {
    CopyIn(h.c.request_id, m.request_id, "request_id");
    h.c.ok = m.ok;
    CopyIn(h.c.campaign_id, m.campaign_id, "campaign_id");
    h.c.jobs = m.jobs;
    h.c.created = m.created;
    CopyIn(h.c.message, m.message.substr(0, wire::kMaxMessage), "message");
  }
  static msg::CampaignReply FromC(const C& c, bool valid, std::string&) {
    msg::CampaignReply m;
    m.request_id = CopyOut(c.request_id);
    if (!valid)
      return m;
    m.ok = c.ok;
    m.campaign_id = CopyOut(c.campaign_id);
    m.jobs = c.jobs;
    m.created = c.created;
    m.message = CopyOut(c.message);
    return m;
  }
};

template <typename M>
std::int32_t CreateTopic(Participant& participant) {
  return CheckDds(dds_create_topic(participant.handle(), Traits<M>::Descriptor(), Traits<M>::kTopic,
                                   nullptr, nullptr),
                  std::string("DDS topic ") + Traits<M>::kTopic);
}

InstanceState StateOf(const dds_sample_info_t& info) {
  switch (info.instance_state) {
    case DDS_IST_NOT_ALIVE_DISPOSED:
      return InstanceState::kDisposed;
    case DDS_IST_NOT_ALIVE_NO_WRITERS:
      return InstanceState::kNoWriters;
    default:
      return InstanceState::kAlive;
  }
}

}  // namespace

template <typename M>
Writer<M>::Writer(Participant& participant) {
  topic_ = CreateTopic<M>(participant);
  QosPtr qos = NewQos();
  Traits<M>::Qos(qos.get(), true);
  writer_ = CheckDds(dds_create_writer(participant.handle(), topic_, qos.get(), nullptr),
                     std::string("DDS writer of ") + Traits<M>::kTopic);
}

template <typename M>
Writer<M>::~Writer() {
  dds_delete(writer_);
}

template <typename M>
void Writer<M>::Write(const M& message) {
  typename Traits<M>::Holder holder;
  Traits<M>::ToC(message, holder);
  CheckDds(dds_write(writer_, &holder.c), std::string("writing ") + Traits<M>::kTopic);
}

template <typename M>
void Writer<M>::Dispose(const M& key) {
  typename Traits<M>::Holder holder;
  Traits<M>::ToC(key, holder);
  CheckDds(dds_dispose(writer_, &holder.c), std::string("disposing in ") + Traits<M>::kTopic);
}

template <typename M>
void Writer<M>::Unregister(const M& key) {
  typename Traits<M>::Holder holder;
  Traits<M>::ToC(key, holder);
  CheckDds(dds_unregister_instance(writer_, &holder.c),
           std::string("unregistering in ") + Traits<M>::kTopic);
}

template <typename M>
int Writer<M>::MatchedReaders() const {
  dds_publication_matched_status_t status{};
  CheckDds(dds_get_publication_matched_status(writer_, &status), "publication status");
  return static_cast<int>(status.current_count);
}

template <typename M>
Received<M> DecodeSample(const void* c_sample, bool valid) {
  Received<M> r;
  r.valid = valid;
  r.data =
      Traits<M>::FromC(*static_cast<const typename Traits<M>::C*>(c_sample), valid, r.decode_error);
  return r;
}

template <typename M>
Reader<M>::Reader(Participant& participant) {
  topic_ = CreateTopic<M>(participant);
  QosPtr qos = NewQos();
  Traits<M>::Qos(qos.get(), false);
  reader_ = CheckDds(dds_create_reader(participant.handle(), topic_, qos.get(), nullptr),
                     std::string("DDS reader of ") + Traits<M>::kTopic);
}

template <typename M>
Reader<M>::~Reader() {
  dds_delete(reader_);
}

template <typename M>
std::vector<Received<M>> Reader<M>::Take() {
  constexpr std::size_t kBatch = 64;
  std::vector<Received<M>> out;
  for (;;) {
    void* samples[kBatch] = {nullptr};
    dds_sample_info_t infos[kBatch];
    const dds_return_t n = dds_take(reader_, samples, infos, kBatch, kBatch);
    CheckDds(n, std::string("taking from ") + Traits<M>::kTopic);
    for (dds_return_t i = 0; i < n; ++i) {
      Received<M> r = DecodeSample<M>(samples[i], infos[i].valid_data);
      r.state = StateOf(infos[i]);
      r.writer = infos[i].publication_handle;
      out.push_back(std::move(r));
    }
    if (n > 0)
      dds_return_loan(reader_, samples, n);
    if (static_cast<std::size_t>(n) < kBatch)
      return out;
  }
}

template <typename M>
std::string Reader<M>::WriterParticipant(std::uint64_t publication_handle) {
  if (const auto it = participants_.find(publication_handle); it != participants_.end()) {
    return it->second;
  }
  dds_builtintopic_endpoint_t* endpoint =
      dds_get_matched_publication_data(reader_, publication_handle);
  if (!endpoint)
    return "";
  static const char kHex[] = "0123456789abcdef";
  std::string guid;
  for (const unsigned char byte : endpoint->participant_key.v) {
    guid += kHex[byte >> 4];
    guid += kHex[byte & 15];
  }
  dds_builtintopic_free_endpoint(endpoint);
  // Writers come and go (clients, restarted workers): keep the cache from growing without end.
  if (participants_.size() >= 4096)
    participants_.clear();
  participants_.emplace(publication_handle, guid);
  return guid;
}

template <typename M>
bool Reader<M>::HasMatchedWriterOf(const std::string& guid) {
  // Every matched writer, however many there are: a peer that adds writers to the topic must
  // not hide the one looked for.
  std::vector<dds_instance_handle_t> handles(64);
  for (;;) {
    const dds_return_t n = dds_get_matched_publications(reader_, handles.data(), handles.size());
    if (n < 0)
      return false;
    const bool complete = static_cast<std::size_t>(n) <= handles.size();
    handles.resize(static_cast<std::size_t>(n));
    if (complete)
      break;
  }
  for (const dds_instance_handle_t handle : handles) {
    if (WriterParticipant(handle) == guid)
      return true;
  }
  return false;
}

template <typename M>
int Reader<M>::MatchedWriters() const {
  dds_subscription_matched_status_t status{};
  CheckDds(dds_get_subscription_matched_status(reader_, &status), "subscription status");
  return static_cast<int>(status.current_count);
}

template class Writer<msg::WorkerStatus>;
template class Writer<msg::JobAssignment>;
template class Writer<msg::JobEvent>;
template class Writer<msg::CampaignRequest>;
template class Writer<msg::CampaignReply>;
template class Reader<msg::WorkerStatus>;
template class Reader<msg::JobAssignment>;
template class Reader<msg::JobEvent>;
template class Reader<msg::CampaignRequest>;
template class Reader<msg::CampaignReply>;
template Received<msg::WorkerStatus> DecodeSample(const void*, bool);
template Received<msg::JobAssignment> DecodeSample(const void*, bool);
template Received<msg::JobEvent> DecodeSample(const void*, bool);
template Received<msg::CampaignRequest> DecodeSample(const void*, bool);
template Received<msg::CampaignReply> DecodeSample(const void*, bool);

}  // namespace rlpos
