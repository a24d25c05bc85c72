#include "dds/topics.h"

#include <dds/dds.h>

#include <memory>

#include "rlpos_messages.h"

namespace rlpos {
namespace {

using QosPtr = std::unique_ptr<dds_qos_t, void (*)(dds_qos_t*)>;

QosPtr NewQos() {
  return QosPtr(dds_create_qos(), dds_delete_qos);
}

// Writing borrows the C++ strings: dds_write serializes before returning, so pointers into
// them stay valid for as long as Cyclone looks at them.
char* Borrow(const std::string& s) {
  return const_cast<char*>(s.c_str());
}
std::string Copy(const char* s) {
  return s ? std::string(s) : std::string();
}

struct BorrowedStrings {
  std::vector<char*> pointers;
  dds_sequence_string Sequence(const std::vector<std::string>& strings) {
    pointers.clear();
    for (const auto& s : strings)
      pointers.push_back(Borrow(s));
    dds_sequence_string seq{};
    seq._maximum = seq._length = static_cast<uint32_t>(pointers.size());
    seq._buffer = pointers.empty() ? nullptr : pointers.data();
    seq._release = false;
    return seq;
  }
};

std::vector<std::string> Copy(const dds_sequence_string& seq) {
  std::vector<std::string> out;
  for (uint32_t i = 0; i < seq._length; ++i)
    out.push_back(Copy(seq._buffer[i]));
  return out;
}

template <typename M>
struct Traits;

template <>
struct Traits<msg::WorkerStatus> {
  using C = rlpos_msg_WorkerStatus;
  static constexpr const char* kTopic = "rlpos_worker_status";
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
    BorrowedStrings jobs;
  };
  static void ToC(const msg::WorkerStatus& m, Holder& h) {
    h.c.worker_id = Borrow(m.worker_id);
    h.c.host = Borrow(m.host);
    h.c.pid = m.pid;
    h.c.slots = m.slots;
    h.c.busy = m.busy;
    h.c.jobs = h.jobs.Sequence(m.jobs);
  }
  static msg::WorkerStatus FromC(const C& c, bool valid) {
    msg::WorkerStatus m;
    m.worker_id = Copy(c.worker_id);
    if (!valid)
      return m;
    m.host = Copy(c.host);
    m.pid = c.pid;
    m.slots = c.slots;
    m.busy = c.busy;
    m.jobs = Copy(c.jobs);
    return m;
  }
};

template <>
struct Traits<msg::JobAssignment> {
  using C = rlpos_msg_JobAssignment;
  static constexpr const char* kTopic = "rlpos_job_assignment";
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_JobAssignment_desc; }
  static void Qos(dds_qos_t* qos, bool writer) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    if (writer)
      dds_qset_writer_data_lifecycle(qos, false);
  }
  struct Holder {
    C c{};
    BorrowedStrings argv;
  };
  static void ToC(const msg::JobAssignment& m, Holder& h) {
    h.c.job_id = Borrow(m.job_id);
    h.c.attempt = m.attempt;
    h.c.worker_id = Borrow(m.worker_id);
    h.c.campaign_id = Borrow(m.campaign_id);
    h.c.argv = h.argv.Sequence(m.argv);
    h.c.scenario_document = Borrow(m.scenario_document);
    h.c.timeout_s = m.timeout_s;
  }
  static msg::JobAssignment FromC(const C& c, bool valid) {
    msg::JobAssignment m;
    m.job_id = Copy(c.job_id);
    if (!valid)
      return m;
    m.attempt = c.attempt;
    m.worker_id = Copy(c.worker_id);
    m.campaign_id = Copy(c.campaign_id);
    m.argv = Copy(c.argv);
    m.scenario_document = Copy(c.scenario_document);
    m.timeout_s = c.timeout_s;
    return m;
  }
};

template <>
struct Traits<msg::JobEvent> {
  using C = rlpos_msg_JobEvent;
  static constexpr const char* kTopic = "rlpos_job_event";
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
  };
  static void ToC(const msg::JobEvent& m, Holder& h) {
    h.c.job_id = Borrow(m.job_id);
    h.c.attempt = m.attempt;
    h.c.worker_id = Borrow(m.worker_id);
    h.c.state = static_cast<rlpos_msg_JobState>(m.state);
    h.c.result_json = Borrow(m.result_json);
    h.c.message = Borrow(m.message);
  }
  static msg::JobEvent FromC(const C& c, bool valid) {
    msg::JobEvent m;
    m.job_id = Copy(c.job_id);
    if (!valid)
      return m;
    m.attempt = c.attempt;
    m.worker_id = Copy(c.worker_id);
    m.state = static_cast<msg::JobState>(c.state);
    m.result_json = Copy(c.result_json);
    m.message = Copy(c.message);
    return m;
  }
};

template <>
struct Traits<msg::CampaignRequest> {
  using C = rlpos_msg_CampaignRequest;
  static constexpr const char* kTopic = "rlpos_campaign_request";
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignRequest_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  }
  struct Holder {
    C c{};
  };
  static void ToC(const msg::CampaignRequest& m, Holder& h) {
    h.c.request_id = Borrow(m.request_id);
    h.c.kind = static_cast<rlpos_msg_RequestKind>(m.kind);
    h.c.campaign_id = Borrow(m.campaign_id);
    h.c.campaign_json = Borrow(m.campaign_json);
  }
  static msg::CampaignRequest FromC(const C& c, bool valid) {
    msg::CampaignRequest m;
    m.request_id = Copy(c.request_id);
    if (!valid)
      return m;
    m.kind = static_cast<msg::RequestKind>(c.kind);
    m.campaign_id = Copy(c.campaign_id);
    m.campaign_json = Copy(c.campaign_json);
    return m;
  }
};

template <>
struct Traits<msg::CampaignReply> {
  using C = rlpos_msg_CampaignReply;
  static constexpr const char* kTopic = "rlpos_campaign_reply";
  static const dds_topic_descriptor_t* Descriptor() { return &rlpos_msg_CampaignReply_desc; }
  static void Qos(dds_qos_t* qos, bool) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  }
  struct Holder {
    C c{};
  };
  static void ToC(const msg::CampaignReply& m, Holder& h) {
    h.c.request_id = Borrow(m.request_id);
    h.c.ok = m.ok;
    h.c.campaign_id = Borrow(m.campaign_id);
    h.c.jobs = m.jobs;
    h.c.created = m.created;
    h.c.message = Borrow(m.message);
  }
  static msg::CampaignReply FromC(const C& c, bool valid) {
    msg::CampaignReply m;
    m.request_id = Copy(c.request_id);
    if (!valid)
      return m;
    m.ok = c.ok;
    m.campaign_id = Copy(c.campaign_id);
    m.jobs = c.jobs;
    m.created = c.created;
    m.message = Copy(c.message);
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
int Writer<M>::MatchedReaders() const {
  dds_publication_matched_status_t status{};
  CheckDds(dds_get_publication_matched_status(writer_, &status), "publication status");
  return static_cast<int>(status.current_count);
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
      const auto& c = *static_cast<const typename Traits<M>::C*>(samples[i]);
      Received<M> r;
      r.valid = infos[i].valid_data;
      r.state = StateOf(infos[i]);
      r.data = Traits<M>::FromC(c, r.valid);
      out.push_back(std::move(r));
    }
    if (n > 0)
      dds_return_loan(reader_, samples, n);
    if (static_cast<std::size_t>(n) < kBatch)
      return out;
  }
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

}  // namespace rlpos
