#pragma once
// Each message's fields, listed once for both directions: Message<M>::Fields(io, message, c)
// runs with io an Encoder (message -> C sample) or a Decoder (C sample -> message), see
// dds/field_codec.h. Key fields come first: a sample without data holds only them. The bound of
// a text is its C array's (the IDL's); the bound of a sequence is common/wire/limits.h's, which
// declares the IDL's numbers. Only message_codec.cc includes this (it needs the generated C).
#include <array>

#include "common/scenario/names.h"
#include "common/wire/limits.h"
#include "idl/dds/field_codec.h"
#include "idl/dds/messages.h"
#include "rlpos_messages.h"

namespace rlpos::codec {

// The C++ enums are the IDL's, value for value.
static_assert(static_cast<int>(JobKind::kTrain) == rlpos_msg_JOB_TRAIN &&
              static_cast<int>(JobKind::kPosition) == rlpos_msg_JOB_POSITION &&
              static_cast<int>(JobKind::kEval) == rlpos_msg_JOB_EVAL &&
              static_cast<int>(JobKind::kTrack) == rlpos_msg_JOB_TRACK);
static_assert(static_cast<int>(msg::JobState::kStarted) == rlpos_msg_JOB_STARTED &&
              static_cast<int>(msg::JobState::kProgress) == rlpos_msg_JOB_PROGRESS &&
              static_cast<int>(msg::JobState::kSucceeded) == rlpos_msg_JOB_SUCCEEDED &&
              static_cast<int>(msg::JobState::kFailed) == rlpos_msg_JOB_FAILED);
static_assert(static_cast<int>(msg::RequestKind::kSubmit) == rlpos_msg_REQUEST_SUBMIT &&
              static_cast<int>(msg::RequestKind::kCancel) == rlpos_msg_REQUEST_CANCEL &&
              static_cast<int>(msg::RequestKind::kRetry) == rlpos_msg_REQUEST_RETRY);

// JobParams' texts that travel as enums, indexed by the IDL's values: the names of
// common/scenario/names.h, in the IDL's order.
constexpr std::array<const char*, 2> kFidelities{"analytic", "packet"};
// "rl": a named policy's position job (its policy travels with it). The tracking ones: track
// jobs.
constexpr std::array<const char*, 7> kPositioners{"",   "baseline",     "centroid",      "oracle",
                                                  "rl", "oracle-track", "centroid-track"};
static_assert(rlpos_msg_FIDELITY_PACKET == 1 && rlpos_msg_POSITIONER_ORACLE == 3 &&
              rlpos_msg_POSITIONER_RL == 4 && rlpos_msg_POSITIONER_ORACLE_TRACK == 5 &&
              rlpos_msg_POSITIONER_CENTROID_TRACK == 6);
static_assert(kFidelities.size() == rlpos::kFidelities.size() &&
              kFidelities[0] == rlpos::kFidelities[0] && kFidelities[1] == rlpos::kFidelities[1]);
static_assert(kPositioners.size() ==
                  rlpos::kPlacingPositioners.size() + 2 + rlpos::kTrackingPositioners.size() &&
              kPositioners[1] == rlpos::kPlacingPositioners[0] &&
              kPositioners[2] == rlpos::kPlacingPositioners[1] &&
              kPositioners[3] == rlpos::kPlacingPositioners[2] &&
              kPositioners[5] == rlpos::kTrackingPositioners[0] &&
              kPositioners[6] == rlpos::kTrackingPositioners[1]);

// A policy file's fields, the same in a job's order and in a campaign's request.
template <typename Io>
auto PolicyFileFields(Io& io) {
  return [&io](auto& f, auto& c_f) {
    io.Text(f.name, c_f.name, "policy file name");
    io.Octets(f.data, c_f.data, wire::kMaxPolicyFileBytes, "policy file");
  };
}

template <typename M>
struct Message;

template <>
struct Message<msg::WorkerStatus> {
  using C = rlpos_msg_WorkerStatus;
  template <typename Io, typename M, typename CM>
  static void Fields(Io& io, M& m, CM& c) {
    io.Text(m.worker_id, c.worker_id, "worker_id");
    if (io.KeysOnly())
      return;
    io.Text(m.host, c.host, "host");
    io.Value(m.pid, c.pid);
    io.Value(m.slots, c.slots);
    io.Value(m.busy, c.busy);
    io.Sequence(m.jobs, c.jobs, wire::kMaxWorkerJobs, "jobs",
                [&](auto& job, auto& c_job) { io.Text(job, c_job, "jobs"); });
  }
};

template <>
struct Message<msg::JobAssignment> {
  using C = rlpos_msg_JobAssignment;
  template <typename Io, typename M, typename CM>
  static void Fields(Io& io, M& m, CM& c) {
    io.Text(m.worker_id, c.worker_id, "worker_id");
    io.Value(m.slot, c.slot);
    if (io.KeysOnly())
      return;
    auto& order = m.order;
    auto& p = order.params;
    io.Text(order.job_id, c.job_id, "job_id");
    io.Value(order.attempt, c.attempt);
    io.Text(order.campaign_id, c.campaign_id, "campaign_id");
    io.Value(order.timeout_s, c.timeout_s);
    io.Enum(p.kind, c.kind, rlpos_msg_JOB_TRACK, "kind");
    io.Text(p.scenario, c.scenario, "scenario");
    io.Octets(order.scenario_document, c.scenario_document, wire::kMaxScenarioDocument,
              "scenario_document");
    io.Sequence(p.overrides, c.overrides, wire::kMaxOverrides, "overrides",
                [&](auto& o, auto& c_o) {
                  io.Text(o.path, c_o.path, "override path");
                  io.Text(o.value, c_o.value, "override value");
                });
    io.Optional(p.train_seed, c.has_train_seed, c.train_seed);
    // Each kind carries only its own parameters: a fidelity for train and track, an rng run
    // for eval and track.
    const bool track = p.kind == JobKind::kTrack;
    io.NamedEnum(p.fidelity, c.fidelity, kFidelities, "fidelity",
                 p.kind == JobKind::kTrain || track);
    io.OptionalOrZero(p.train_episodes, c.train_episodes);
    io.NamedEnum(p.positioner, c.positioner, kPositioners, "positioner");
    io.OptionalSequence(order.placement, c.positions, wire::kMaxUavPositions, "positions",
                        [&](auto& q, auto& c_q) {
                          io.Value(q.x, c_q.x);
                          io.Value(q.y, c_q.y);
                          io.Value(q.z, c_q.z);
                        });
    io.OptionalWhen(p.rng_run, c.rng_run, p.kind == JobKind::kEval || track);
    io.Optional(p.duration_s, c.has_duration, c.duration_s);
    io.Optional(p.warmup_s, c.has_warmup, c.warmup_s);
    io.Text(p.policy_sha256, c.policy_sha256, "policy_sha256");
    io.Policy(order.policy, c.policy_files, p.policy_sha256, PolicyFileFields(io));
  }
};

template <>
struct Message<msg::JobEvent> {
  using C = rlpos_msg_JobEvent;
  template <typename Io, typename M, typename CM>
  static void Fields(Io& io, M& m, CM& c) {
    io.Text(m.worker_id, c.worker_id, "worker_id");
    io.Value(m.slot, c.slot);
    if (io.KeysOnly())
      return;
    io.Text(m.job_id, c.job_id, "job_id");
    io.Value(m.attempt, c.attempt);
    io.Enum(m.state, c.state, rlpos_msg_JOB_FAILED, "state");
    io.Octets(m.result_json, c.result_json, wire::kMaxResultJson, "result_json");
    io.Text(m.message, c.message, "message");
    auto& p = m.provenance;
    io.Text(p.host, c.provenance.host, "provenance host");
    io.Text(p.rlpos_version, c.provenance.rlpos_version, "provenance rlpos_version");
    io.Text(p.ns3_version, c.provenance.ns3_version, "provenance ns3_version");
    io.Text(p.torch_version, c.provenance.torch_version, "provenance torch_version");
    io.Text(p.cyclonedds_version, c.provenance.cyclonedds_version, "provenance cyclonedds_version");
    io.Text(p.scenario_sha256, c.provenance.scenario_sha256, "provenance scenario_sha256");
    io.Sequence(m.artifacts, c.artifacts, wire::kMaxArtifacts, "artifacts",
                [&](auto& a, auto& c_a) {
                  io.Text(a.name, c_a.name, "artifact name");
                  io.Text(a.sha256, c_a.sha256, "artifact sha256");
                  io.Octets(a.data, c_a.data, wire::kMaxArtifactBytes, "artifact");
                });
  }
};

template <>
struct Message<msg::CampaignRequest> {
  using C = rlpos_msg_CampaignRequest;
  template <typename Io, typename M, typename CM>
  static void Fields(Io& io, M& m, CM& c) {
    io.Text(m.request_id, c.request_id, "request_id");
    if (io.KeysOnly())
      return;
    io.Enum(m.kind, c.kind, rlpos_msg_REQUEST_RETRY, "kind");
    io.Text(m.campaign_id, c.campaign_id, "campaign_id");
    io.Octets(m.campaign_json, c.campaign_json, wire::kMaxCampaignJson, "campaign_json");
    io.Sequence(m.scenarios, c.scenarios, wire::kMaxCampaignScenarios, "scenarios",
                [&](auto& s, auto& c_s) {
                  io.Text(s.file, c_s.file, "scenario file");
                  io.Octets(s.document, c_s.document, wire::kMaxScenarioDocument,
                            "scenario document");
                });
    io.Value(m.no_cache, c.no_cache);
    io.Sequence(m.policies, c.policies, wire::kMaxPolicyFolders, "policies",
                [&](auto& p, auto& c_p) {
                  io.Text(p.folder, c_p.folder, "policy folder");
                  io.Sequence(p.files, c_p.files, wire::kMaxPolicyFiles, "policy files",
                              PolicyFileFields(io));
                });
  }
};

template <>
struct Message<msg::CampaignReply> {
  using C = rlpos_msg_CampaignReply;
  template <typename Io, typename M, typename CM>
  static void Fields(Io& io, M& m, CM& c) {
    io.Text(m.request_id, c.request_id, "request_id");
    if (io.KeysOnly())
      return;
    io.Value(m.ok, c.ok);
    io.Text(m.campaign_id, c.campaign_id, "campaign_id");
    io.Value(m.jobs, c.jobs);
    io.Value(m.created, c.created);
    io.CutText(m.message, c.message, "message");  // an error too long is cut, not lost
  }
};

}  // namespace rlpos::codec
