// Fuzz of everything that reads the wire: the decoder of each message type (DecodeSample, as
// Reader::Take runs it on Cyclone's C samples) followed by its check, the worker's order check
// with its scenario document, the coordinator's campaign expansion, and the result parser.
// 100,000 inputs each, random and mutated from valid ones, from a fixed seed. Each input must be
// either refused (a decode error, a check's reason, or std::invalid_argument / ConfigError) or
// accepted with its invariants holding; anything else (another exception, a crash, an ASan or
// UBSan report in the RLPOS_SANITIZE build) fails. Each test also requires that both outcomes
// occurred, so a fuzzer that only ever produced garbage (or only valid input) fails too.
// Cyclone's own CDR deserializer, which runs before DecodeSample, is upstream's to fuzz.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/campaign/campaign_request.h"
#include "common/config/config_error.h"
#include "common/hash/sha256.h"
#include "common/store/job_result.h"
#include "common/wire/artifacts.h"
#include "common/wire/identifiers.h"
#include "common/wire/job_order.h"
#include "common/wire/json_text.h"
#include "common/wire/limits.h"
#include "idl/dds/message_checks.h"
#include "idl/dds/topics.h"
#include "rlpos_messages.h"
#include "tests/fuzz/fuzz_input.h"

namespace rlpos {
namespace {

using testing::FuzzInput;

constexpr int kInputs = 100000;
constexpr std::uint64_t kSeed = 20261123;

std::string ReadSource(const std::string& relative) {
  std::ifstream in(std::string(RLPOS_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Counts both outcomes and fails on a third.
struct Outcomes {
  long accepted = 0, refused = 0;
  void ExpectBoth(const char* what) const {
    std::printf("%s: %ld accepted, %ld refused\n", what, accepted, refused);
    EXPECT_GT(accepted, 0) << what << ": no input was accepted; the fuzz never got deep";
    EXPECT_GT(refused, 0) << what << ": no input was refused; the fuzz never mutated";
    EXPECT_EQ(accepted + refused, kInputs) << what;
  }
};

// Runs `step` and turns the two refusals every reader of the wire may throw into `false`.
template <typename F>
bool Accepts(F step, int input, const char* what) {
  try {
    return step();
  } catch (const std::invalid_argument&) {
    return false;
  } catch (const ConfigError&) {
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << " input " << input << ": unexpected exception: " << e.what();
    return false;
  }
}

// A C string field: the valid text, a mutation of it, random bytes, or a full array without a
// terminating NUL (Cyclone always terminates; the decoder must not depend on it).
template <std::size_t N>
void FuzzChars(char (&field)[N], const std::string& valid, FuzzInput& in) {
  std::string text = valid;
  switch (in.Below(40)) {  // most fields stay valid, so that inputs get past the first check
    case 0:
      text = in.RandomBytes(N + 8);
      break;
    case 1:
      std::memset(field, 'A' + static_cast<int>(in.Below(26)), N);
      return;
    case 2:
    case 3:
      text = in.Mutate(valid);
      break;
    default:
      break;
  }
  text.resize(std::min(text.size(), N - 1));
  std::memcpy(field, text.data(), text.size());
  field[text.size()] = '\0';
}

// An octet sequence over `storage`: the valid text, a mutation, random bytes, a length past the
// IDL bound (the buffer is not that long: the decoder must not read it), or a null buffer.
void FuzzOctets(dds_sequence_octet& seq, std::string& storage, const std::string& valid,
                std::size_t bound, FuzzInput& in, bool mutate_more) {
  storage = valid;
  const std::size_t mode = in.Below(20);
  if (mode >= 3 && mode < 8 && mutate_more) {
    storage = in.MutateJsonValue(valid);
  } else if (mode == 0) {
    storage = in.RandomBytes(64);
  } else if (mode == 1) {
    seq._buffer = reinterpret_cast<uint8_t*>(storage.data());
    seq._length = seq._maximum = static_cast<uint32_t>(bound + 1 + in.Below(1000));
    return;
  } else if (mode == 2) {
    seq._buffer = nullptr;
    seq._length = seq._maximum = 1 + static_cast<uint32_t>(in.Below(10));
    return;
  } else if (mode < (mutate_more ? 11u : 5u)) {
    storage = in.Mutate(valid);
  }
  seq._buffer = reinterpret_cast<uint8_t*>(storage.data());
  seq._length = seq._maximum = static_cast<uint32_t>(storage.size());
}

template <typename E>
void FuzzEnum(E& field, int valid, FuzzInput& in) {
  const std::int32_t value = in.Chance(0.95) ? valid : static_cast<std::int32_t>(in.WeirdInteger());
  std::memcpy(&field, &value, sizeof value);
}

bool Finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

TEST(WireFuzz, JobAssignmentDecoderAndOrderCheck) {
  const std::string document = ReadSource("campaigns/scenarios/b.json");
  const std::string job_id = "c0ffee012345/eval/B/baseline/run1";
  FuzzInput in(kSeed);
  Outcomes outcomes;
  for (int i = 0; i < kInputs; ++i) {
    rlpos_msg_JobAssignment c{};
    std::string doc_storage;
    std::vector<rlpos_msg_ScenarioOverride> overrides(1 + in.Below(3));
    FuzzChars(c.job_id, job_id, in);
    FuzzChars(c.worker_id, "w1", in);
    FuzzChars(c.campaign_id, "c0ffee012345", in);
    FuzzChars(c.scenario, "B", in);
    c.attempt = in.Chance(0.97) ? 1 : static_cast<std::int32_t>(in.WeirdInteger());
    c.timeout_s = in.Chance(0.97) ? 300 : in.WeirdDouble();
    FuzzEnum(c.kind, rlpos_msg_JOB_EVAL, in);
    FuzzEnum(c.fidelity, rlpos_msg_FIDELITY_ANALYTIC, in);
    FuzzEnum(c.positioner, rlpos_msg_POSITIONER_NONE, in);
    FuzzOctets(c.scenario_document, doc_storage, document, wire::kMaxScenarioDocument, in, true);
    for (auto& o : overrides) {
      FuzzChars(o.path, "simulation.duration", in);
      FuzzChars(o.value, "1.5", in);
    }
    c.overrides._buffer = overrides.data();
    c.overrides._length = c.overrides._maximum = static_cast<uint32_t>(
        in.Chance(0.02) ? wire::kMaxOverrides + 1 + in.Below(100) : overrides.size());
    // Mostly the scenario's one UAV; sometimes none, several, or more than the bound.
    std::vector<rlpos_msg_UavPosition> positions(in.Chance(0.9) ? 1 : in.Below(4));
    for (auto& q : positions) {
      q.x = in.Chance(0.97) ? 50 : in.WeirdDouble();
      q.y = in.Chance(0.97) ? 50 : in.WeirdDouble();
      q.z = in.Chance(0.97) ? 25 : in.WeirdDouble();
    }
    c.positions._buffer = positions.empty() ? nullptr : positions.data();
    c.positions._length = c.positions._maximum = static_cast<uint32_t>(
        in.Chance(0.02) ? wire::kMaxUavPositions + 1 + in.Below(100) : positions.size());
    c.rng_run = in.Chance(0.97) ? 1 : static_cast<std::uint64_t>(in.WeirdInteger());
    c.has_duration = in.Chance(0.9);
    c.duration_s = in.Chance(0.97) ? 1 : in.WeirdDouble();
    c.has_warmup = in.Chance(0.9);
    c.warmup_s = in.Chance(0.97) ? 0.5 : in.WeirdDouble();
    c.has_train_seed = in.Chance(0.1);
    c.train_seed = static_cast<std::uint64_t>(in.WeirdInteger());
    c.train_episodes = in.Chance(0.95) ? 0 : static_cast<std::int32_t>(in.WeirdInteger());

    const auto r = DecodeSample<msg::JobAssignment>(&c, true);
    const bool ok = r.decode_error.empty() &&
                    Accepts(
                        [&] {
                          const CheckedOrder checked = CheckJobOrder(r.data.order, 604800);
                          const JobOrder& o = r.data.order;
                          EXPECT_TRUE(wire::IsSafePath(o.job_id, wire::kMaxIdLength)) << i;
                          EXPECT_TRUE(o.timeout_s > 0 && o.timeout_s <= 604800) << i;
                          if (o.placement) {
                            for (const Vec3& p : *o.placement)
                              EXPECT_TRUE(Finite(p)) << i;
                          }
                          EXPECT_TRUE(checked.scenario.is_object()) << i;
                          return true;
                        },
                        i, "assignment");
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("assignment");
}

TEST(WireFuzz, JobEventDecoderAndCheck) {
  FuzzInput in(kSeed + 1);
  Outcomes outcomes;
  const std::string result = R"({"position": [50, 50, 25], "run": 1})";
  for (int i = 0; i < kInputs; ++i) {
    rlpos_msg_JobEvent c{};
    std::string storage;
    FuzzChars(c.job_id, "c0ffee012345/eval/B/baseline/run1", in);
    FuzzChars(c.worker_id, "w1", in);
    FuzzChars(c.message, "", in);
    FuzzChars(c.provenance.host, "host-a", in);
    FuzzChars(c.provenance.rlpos_version, "v0.1-12-gabcdef", in);
    FuzzChars(c.provenance.scenario_sha256, std::string(64, 'e'), in);
    c.attempt = in.Chance(0.97) ? 1 : static_cast<std::int32_t>(in.WeirdInteger());
    FuzzEnum(c.state, rlpos_msg_JOB_SUCCEEDED, in);
    FuzzOctets(c.result_json, storage, result, wire::kMaxResultJson, in, false);
    // Artifacts: mostly none or valid ones (name, data and its true sha256), sometimes a name,
    // hash or size that is off, or a length beyond the sequence's bound.
    std::vector<rlpos_msg_ArtifactFile> artifacts(in.Chance(0.7) ? 0 : in.Below(4));
    std::vector<std::string> artifact_data(artifacts.size());
    for (std::size_t k = 0; k < artifacts.size(); ++k) {
      const std::string data = "episode,reward\n" + std::to_string(k) + ",1\n";
      FuzzChars(artifacts[k].name, TrainArtifactNames()[k % TrainArtifactNames().size()], in);
      FuzzChars(artifacts[k].sha256, Sha256Hex(data), in);
      FuzzOctets(artifacts[k].data, artifact_data[k], data, wire::kMaxArtifactBytes, in, false);
    }
    c.artifacts._buffer = artifacts.empty() ? nullptr : artifacts.data();
    c.artifacts._length = c.artifacts._maximum = static_cast<uint32_t>(
        in.Chance(0.99) ? artifacts.size() : artifacts.size() + wire::kMaxArtifacts);
    if (c.artifacts._length > artifacts.size())
      c.artifacts._buffer = nullptr;  // a length the decoder must refuse without reading
    const auto r = DecodeSample<msg::JobEvent>(&c, true);
    const bool ok = r.decode_error.empty() && CheckJobEvent(r.data).empty();
    if (ok) {
      EXPECT_TRUE(wire::IsSafePath(r.data.job_id, wire::kMaxIdLength)) << i;
      EXPECT_TRUE(r.data.attempt >= 1 && r.data.attempt <= wire::kMaxAttempt) << i;
      EXPECT_LE(r.data.result_json.size(), wire::kMaxResultJson) << i;
      for (const auto& a : r.data.artifacts) {
        EXPECT_EQ(Sha256Hex(a.data), a.sha256) << i;
        EXPECT_NE(std::find(TrainArtifactNames().begin(), TrainArtifactNames().end(), a.name),
                  TrainArtifactNames().end())
            << i;
      }
    }
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("job event");
}

TEST(WireFuzz, WorkerStatusDecoderAndCheck) {
  FuzzInput in(kSeed + 2);
  Outcomes outcomes;
  for (int i = 0; i < kInputs; ++i) {
    rlpos_msg_WorkerStatus c{};
    std::vector<std::array<char, 301>> jobs(in.Below(4));
    for (auto& job : jobs) {
      char text[301];
      FuzzChars(text, "c0ffee012345/eval/B/baseline/run1#1", in);
      std::memcpy(job.data(), text, sizeof text);
    }
    FuzzChars(c.worker_id, "w1", in);
    FuzzChars(c.host, "host-a", in);
    c.pid = in.Chance(0.97) ? 4242 : in.WeirdInteger();
    c.slots = in.Chance(0.97) ? 4 : static_cast<std::int32_t>(in.WeirdInteger());
    c.busy = in.Chance(0.97) ? static_cast<std::int32_t>(jobs.size())
                             : static_cast<std::int32_t>(in.WeirdInteger());
    c.jobs._buffer = reinterpret_cast<decltype(c.jobs._buffer)>(jobs.data());
    c.jobs._length = c.jobs._maximum = static_cast<uint32_t>(
        in.Chance(0.02) ? wire::kMaxWorkerJobs + 1 + in.Below(100) : jobs.size());
    const bool valid = in.Chance(0.95);
    const auto r = DecodeSample<msg::WorkerStatus>(&c, valid);
    const bool ok = valid && r.decode_error.empty() && CheckWorkerStatus(r.data).empty();
    if (ok) {
      EXPECT_TRUE(wire::IsSafeName(r.data.worker_id, wire::kMaxNameLength)) << i;
      EXPECT_TRUE(r.data.busy >= 0 && r.data.busy <= r.data.slots && r.data.slots <= 1024) << i;
      EXPECT_LE(r.data.jobs.size(), static_cast<std::size_t>(r.data.slots)) << i;
    }
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("worker status");
}

TEST(WireFuzz, CampaignRequestDecoderCheckAndExpansion) {
  const std::string campaign =
      R"({"name": "fuzz", "scenarios": ["b.json"], "rng_runs": [1, 2],)"
      R"( "positioners": ["baseline", "centroid"], "eval": {"duration": 1, "warmup": 0.5}})";
  const std::string document = ReadSource("campaigns/scenarios/b.json");
  FuzzInput in(kSeed + 3);
  Outcomes outcomes;
  SubmitLimits limits;
  limits.max_jobs = 1000;
  for (int i = 0; i < kInputs; ++i) {
    rlpos_msg_CampaignRequest c{};
    std::string campaign_storage;
    std::vector<std::string> documents(1 + in.Below(2));
    std::vector<rlpos_msg_ScenarioFile> files(documents.size());
    FuzzChars(c.request_id, "client-1-7", in);
    FuzzChars(c.campaign_id, "", in);
    FuzzEnum(c.kind, rlpos_msg_REQUEST_SUBMIT, in);
    FuzzOctets(c.campaign_json, campaign_storage, campaign, wire::kMaxCampaignJson, in, true);
    for (std::size_t f = 0; f < files.size(); ++f) {
      FuzzChars(files[f].file, f == 0 ? "b.json" : "c.json", in);
      FuzzOctets(files[f].document, documents[f], document, wire::kMaxScenarioDocument, in, false);
    }
    c.scenarios._buffer = files.data();
    c.scenarios._length = c.scenarios._maximum = static_cast<uint32_t>(
        in.Chance(0.02) ? wire::kMaxCampaignScenarios + 1 + in.Below(100) : files.size());
    const auto r = DecodeSample<msg::CampaignRequest>(&c, true);
    bool ok = r.decode_error.empty() && CheckCampaignRequest(r.data).empty();
    if (ok && r.data.kind == msg::RequestKind::kSubmit) {
      ok = Accepts(
          [&] {
            const CampaignPlan plan =
                PlanSubmittedCampaign(r.data.campaign_json, r.data.scenarios, limits);
            EXPECT_LE(plan.JobCount(), limits.max_jobs) << i;
            EXPECT_GT(plan.JobCount(), 0u) << i;
            return true;
          },
          i, "campaign request");
    }
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("campaign request");
}

TEST(WireFuzz, CampaignReplyDecoderAndCheck) {
  FuzzInput in(kSeed + 4);
  Outcomes outcomes;
  for (int i = 0; i < kInputs; ++i) {
    rlpos_msg_CampaignReply c{};
    FuzzChars(c.request_id, "client-1-7", in);
    FuzzChars(c.campaign_id, "c0ffee012345", in);
    FuzzChars(c.message, "", in);
    c.ok = in.Chance(0.5);
    c.created = in.Chance(0.5);
    c.jobs = in.Chance(0.97) ? 6 : static_cast<std::int32_t>(in.WeirdInteger());
    const auto r = DecodeSample<msg::CampaignReply>(&c, true);
    const bool ok = r.decode_error.empty() && CheckCampaignReply(r.data, "client-1-7").empty();
    if (ok) {
      EXPECT_EQ(r.data.request_id, "client-1-7") << i;
      EXPECT_GE(r.data.jobs, 0) << i;
    }
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("campaign reply");
}

TEST(WireFuzz, ResultParser) {
  const std::string eval =
      R"({"position": [50.0, 50.0, 25.0], "aggregate_throughput_mbps": 168.7,)"
      R"( "mean_delay_ms": 69.9, "loss_ratio": 0.01, "min_snr_db": 12.5, "n_los": 1,)"
      R"( "n_ues": 4, "demands_met": 3, "run": 1})";
  const std::string eval_of_two =
      R"({"position": [50.0, 50.0, 25.0], "aggregate_throughput_mbps": 168.7,)"
      R"( "mean_delay_ms": 69.9, "loss_ratio": 0.01, "min_snr_db": 12.5, "n_los": 1,)"
      R"( "n_ues": 4, "demands_met": 3, "run": 1, "uavs": [)"
      R"({"name": "a", "position": [50.0, 50.0, 25.0], "ues_served": 3, "throughput_mbps": 100.0,)"
      R"( "mean_delay_ms": 50.0, "loss_ratio": 0.0, "n_los": 1, "worst_ue_throughput_mbps": 20.0,)"
      R"( "jain_fairness": 0.9}, {"name": "b", "position": [10.0, 10.0, 25.0], "ues_served": 1,)"
      R"( "throughput_mbps": 68.7, "mean_delay_ms": null, "loss_ratio": null, "n_los": 0,)"
      R"( "worst_ue_throughput_mbps": 68.7, "jain_fairness": 1.0}]})";
  const std::string position = R"({"position": [47.5, 37.5, 35.0], "reward": 3.2})";
  const std::string positions =
      R"({"position": [47.5, 37.5, 35.0], "positions": [[47.5, 37.5, 35.0], [5, 5, 20]]})";
  FuzzInput in(kSeed + 5);
  Outcomes outcomes;
  for (int i = 0; i < kInputs; ++i) {
    const bool is_eval = in.Chance(0.7);
    const bool several = in.Chance(0.3);
    const std::string& base =
        is_eval ? (several ? eval_of_two : eval) : (several ? positions : position);
    const double mode = in.Below(100);
    const std::string text = mode < 5    ? in.RandomBytes(200)
                             : mode < 55 ? in.MutateJsonValue(base)
                                         : in.Mutate(base);
    const bool ok = Accepts(
        [&] {
          const nlohmann::json json =
              wire::ParseBoundedJson(text, wire::kMaxResultJson, "the result");
          if (!is_eval) {
            const Placement placement = ProducedPlacement(json);
            EXPECT_TRUE(!placement.empty() && placement.size() <= kMaxUavs) << i << ": " << text;
            for (const Vec3& p : placement)
              EXPECT_TRUE(Finite(p)) << i << ": " << text;
            return true;
          }
          const EvalResult r = ParseEvalResult(json);
          EXPECT_EQ(r.placement.size(), r.uavs.size()) << i << ": " << text;
          for (const Vec3& p : r.placement)
            EXPECT_TRUE(Finite(p)) << i << ": " << text;
          EXPECT_TRUE(r.aggregate_throughput_mbps && std::isfinite(*r.aggregate_throughput_mbps) &&
                      *r.aggregate_throughput_mbps >= 0)
              << i << ": " << text;
          EXPECT_TRUE(r.n_los >= 0 && r.n_los <= r.n_ues) << i << ": " << text;
          EXPECT_TRUE(r.demands_met >= 0 && r.demands_met <= r.n_ues) << i << ": " << text;
          if (r.loss_ratio) {
            EXPECT_TRUE(*r.loss_ratio >= 0 && *r.loss_ratio <= 1) << i << ": " << text;
          }
          return true;
        },
        i, "result");
    ++(ok ? outcomes.accepted : outcomes.refused);
  }
  outcomes.ExpectBoth("result");
}

}  // namespace
}  // namespace rlpos
