// Each message through its field list both ways without a network: C++ -> C sample -> C++ gives
// back every field (each set to a value other than its default, so that a field the list drops
// or maps to another shows), and a field over its bound is refused with MessageError naming it,
// when written and when received.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "common/job/job_fields.h"
#include "common/wire/limits.h"
#include "idl/dds/message_checks.h"
#include "idl/dds/topics.h"
#include "rlpos_messages.h"
#include "tests/idl/dds/topics_test_messages.h"

namespace rlpos {
namespace {

template <typename M>
Received<M> RoundTrip(const M& message) {
  const EncodedSample<M> encoded(message);
  return DecodeSample<M>(encoded.c_sample(), true);
}

// The field named by the MessageError that encoding `message` throws, or "" when none is thrown.
template <typename M>
std::string RefusedField(const M& message) {
  try {
    EncodedSample<M> encoded(message);
  } catch (const MessageError& e) {
    return e.field();
  }
  return "";
}

// Every field as a tuple of standard types, for one EXPECT_EQ that names what differs.
auto Fields(const msg::WorkerStatus& m) {
  return std::make_tuple(m.worker_id, m.host, m.pid, m.slots, m.busy, m.jobs);
}

auto Fields(const msg::JobAssignment& m) {
  const JobOrder& o = m.order;
  const JobParams& p = o.params;
  std::vector<std::tuple<std::string, std::string>> overrides;
  for (const auto& x : p.overrides)
    overrides.emplace_back(x.path, x.value);
  std::optional<std::vector<std::array<double, 3>>> placement;
  if (o.placement) {
    placement.emplace();
    for (const Vec3& q : *o.placement)
      placement->push_back({q.x, q.y, q.z});
  }
  std::optional<std::tuple<int, std::vector<std::tuple<std::string, std::string>>, std::string>>
      policy;
  if (o.policy) {
    std::vector<std::tuple<std::string, std::string>> files;
    for (const auto& f : o.policy->files)
      files.emplace_back(f.name, f.data);
    policy.emplace(static_cast<int>(o.policy->format), files, o.policy->sha256);
  }
  return std::make_tuple(m.worker_id, m.slot, o.job_id, o.attempt, o.campaign_id, o.timeout_s,
                         static_cast<int>(p.kind), p.scenario, o.scenario_document, overrides,
                         p.train_seed, p.fidelity, p.train_episodes, p.positioner, placement,
                         p.rng_run, p.duration_s, p.warmup_s, p.policy_sha256, policy);
}

auto Fields(const msg::JobEvent& m) {
  const Provenance& p = m.provenance;
  std::vector<std::tuple<std::string, std::string, std::string>> artifacts;
  for (const auto& a : m.artifacts)
    artifacts.emplace_back(a.name, a.sha256, a.data);
  return std::make_tuple(m.worker_id, m.slot, m.job_id, m.attempt, static_cast<int>(m.state),
                         m.result_json, m.message, p.host, p.rlpos_version, p.ns3_version,
                         p.torch_version, p.cyclonedds_version, p.scenario_sha256, artifacts);
}

auto Fields(const msg::CampaignRequest& m) {
  std::vector<std::tuple<std::string, std::string>> scenarios;
  for (const auto& s : m.scenarios)
    scenarios.emplace_back(s.file, s.document);
  std::vector<std::tuple<std::string, std::vector<std::tuple<std::string, std::string>>>> policies;
  for (const auto& p : m.policies) {
    std::vector<std::tuple<std::string, std::string>> files;
    for (const auto& f : p.files)
      files.emplace_back(f.name, f.data);
    policies.emplace_back(p.folder, files);
  }
  return std::make_tuple(m.request_id, static_cast<int>(m.kind), m.campaign_id, m.campaign_json,
                         scenarios, m.no_cache, policies);
}

auto Fields(const msg::CampaignReply& m) {
  return std::make_tuple(m.request_id, m.ok, m.campaign_id, m.jobs, m.created, m.message);
}

template <typename M>
void ExpectRoundTrip(const M& sent) {
  const Received<M> got = RoundTrip(sent);
  EXPECT_EQ(got.decode_error, "");
  EXPECT_EQ(Fields(got.data), Fields(sent));
}

msg::WorkerStatus Status() {
  msg::WorkerStatus s;
  s.worker_id = "w-7";
  s.host = "h\xc3\xb4te";
  s.pid = (std::int64_t{1} << 40) + 3;
  s.slots = 4;
  s.busy = 2;
  s.jobs = {"c0ffee/eval/B/rl/run1#2", "c0ffee/train/B/seed3#1"};
  return s;
}

// The topics tests' eval assignment, with its remaining fields away from their defaults too.
msg::JobAssignment Eval() {
  msg::JobAssignment a = testing::Assignment("c0ffee/eval/B/rl/run2", 4, 3);
  a.worker_id = "w-7";
  a.order.params.train_seed = 9;
  a.order.params.warmup_s = 0.5;
  a.order.placement = Placement{{10, 20, 30}, {40.25, 50, 60}, {70, 80, 90.5}};
  a.order.scenario_document = R"({"name": "B"})";
  return a;
}

msg::JobAssignment Train() {
  msg::JobAssignment a = testing::WithFreshParams(Eval(), JobKind::kTrain, "C");
  a.order.params.train_seed = 11;
  a.order.params.fidelity = "packet";
  a.order.params.train_episodes = 25;
  a.order.params.duration_s = 2;
  a.order.params.warmup_s = 0.25;
  a.order.params.overrides = {{"agent.hidden", "[16]"}};
  return a;
}

msg::JobAssignment Position() {
  msg::JobAssignment a = testing::WithFreshParams(Eval(), JobKind::kPosition, "C");
  a.order.params.positioner = "oracle";
  a.order.params.duration_s = 0.25;
  a.order.params.warmup_s = 0.125;
  a.order.params.overrides = {{"uav.step", "10"}};
  return a;
}

// A named policy's position job: the policy travels with it.
msg::JobAssignment RlPosition() {
  msg::JobAssignment a = Position();
  a.order.params.positioner = "rl";
  a.order.policy = MakePolicyBundle({{"model.pt", std::string("\0\x01zip", 5)},
                                     {"policy.json", R"({"format": "torchscript"})"},
                                     {"scenario.json", R"({"name": "C"})"}});
  a.order.params.policy_sha256 = a.order.policy->sha256;
  return a;
}

msg::JobEvent Event() {
  msg::JobEvent e;
  e.worker_id = "w-7";
  e.slot = 2;
  e.job_id = "c0ffee/train/B/seed3";
  e.attempt = 5;
  e.state = msg::JobState::kSucceeded;
  e.result_json = R"({"reward": 3.5})";
  e.message = "episode 3/10";
  e.provenance = {"host-a", "v0.1-3-gabc", "3.37", "1.13.0", "0.10.2", std::string(64, 'e')};
  e.artifacts = {{"policy.pt", std::string(64, 'a'), std::string("\0\x01\xff", 3)},
                 {"learning_curve.csv", std::string(64, 'b'), "episode,reward\n1,2\n"}};
  return e;
}

msg::CampaignRequest Request() {
  msg::CampaignRequest r;
  r.request_id = "client-1-7";
  r.kind = msg::RequestKind::kRetry;
  r.campaign_id = "c0ffee";
  r.campaign_json = R"({"name": "m"})";
  r.scenarios = {{"scenarios/b.json", R"({"name": "B"})"}, {"c.json", "{}"}};
  r.no_cache = true;
  r.policies = {{"policies/p1", {{"policy.pt", std::string("\0w", 2)}, {"result.json", "{}"}}}};
  return r;
}

msg::CampaignReply Reply() {
  msg::CampaignReply r = testing::CreatedReply("client-1-7");
  r.message = "submitted";
  return r;
}

TEST(MessageCodec, WorkerStatusRoundTrips) {
  ExpectRoundTrip(Status());
  msg::WorkerStatus s = Status();
  s.jobs.push_back(std::string(301, 'j'));
  EXPECT_EQ(RefusedField(s), "jobs");
}

TEST(MessageCodec, JobAssignmentOfEachKindRoundTrips) {
  for (const auto& a : {Eval(), Train(), Position(), RlPosition()}) {
    SCOPED_TRACE(a.order.job_id + " " + ToString(a.order.params.kind));
    ExpectRoundTrip(a);
  }
  msg::JobAssignment a = Eval();
  a.order.params.overrides[1].value = std::string(4097, 'v');
  EXPECT_EQ(RefusedField(a), "override value");
}

// A field of JobParams declared to change a job's run (job/job_fields.h) travels with the job:
// the codec and Fields() above name JobParams' fields one by one, so this walks the declaration.
template <typename Field>
void ExpectTravels(const Field& field, const JobParams& sent, const JobParams& got) {
  if (!Includes(field.kinds, sent.kind))
    return;
  using Value = std::decay_t<decltype(sent.*field.member)>;
  if constexpr (!std::is_same_v<Value, JobKind>) {  // every kind is a value of its own
    EXPECT_FALSE(sent.*field.member == JobParams{}.*field.member)
        << field.name << ": the " << ToString(sent.kind) << " job above must set it";
  }
  EXPECT_TRUE(got.*field.member == sent.*field.member)
      << field.name << " is lost on the wire (" << ToString(sent.kind) << " job)";
}

TEST(MessageCodec, EveryDeclaredJobFieldOfItsKindTravels) {
  for (const auto& a : {Eval(), Train(), RlPosition()}) {
    const Received<msg::JobAssignment> got = RoundTrip(a);
    ASSERT_EQ(got.decode_error, "");
    std::apply(
        [&](const auto&... field) {
          (ExpectTravels(field, a.order.params, got.data.order.params), ...);
        },
        kJobFields);
  }
}

TEST(MessageCodec, JobEventRoundTrips) {
  ExpectRoundTrip(Event());
  msg::JobEvent e = Event();
  e.provenance.ns3_version = std::string(33, '3');
  EXPECT_EQ(RefusedField(e), "provenance ns3_version");
}

TEST(MessageCodec, CampaignRequestRoundTrips) {
  ExpectRoundTrip(Request());
  msg::CampaignRequest r = Request();
  r.scenarios.assign(wire::kMaxCampaignScenarios + 1, SubmittedScenario{"b.json", "{}"});
  EXPECT_EQ(RefusedField(r), "scenarios");
  r = Request();
  r.policies.assign(wire::kMaxPolicyFolders + 1, r.policies.front());
  EXPECT_EQ(RefusedField(r), "policies");
}

// A submit's policy folders are dropped by the coordinator's first check when no bundle could be
// made of them; the bundle's own rules (names, formats) are the planner's.
TEST(MessageChecks, ASubmitsPoliciesAreBounded) {
  msg::CampaignRequest r = Request();
  r.kind = msg::RequestKind::kSubmit;
  r.campaign_id.clear();
  EXPECT_EQ(CheckCampaignRequest(r), "");
  r.policies.front().folder.clear();
  EXPECT_EQ(CheckCampaignRequest(r), "bad policy folder name");
  r = Request();
  r.kind = msg::RequestKind::kSubmit;
  r.campaign_id.clear();
  r.policies.front().files.assign(wire::kMaxPolicyFiles + 1, PolicyFile{"policy.pt", "w"});
  EXPECT_EQ(CheckCampaignRequest(r), "too many policy files");
  r.policies.front().files = {{"policy.pt", std::string(wire::kMaxPolicyFileBytes, 'w')},
                              {"result.json", "{}"}};
  EXPECT_EQ(CheckCampaignRequest(r), "policy too large");
  r = Request();  // a retry that carries nothing but policies
  r.campaign_json.clear();
  r.scenarios.clear();
  EXPECT_EQ(CheckCampaignRequest(r), "a cancel or retry with a campaign");
}

TEST(MessageCodec, CampaignReplyRoundTrips) {
  ExpectRoundTrip(Reply());
  msg::CampaignReply r = Reply();
  r.campaign_id = std::string(65, 'c');
  EXPECT_EQ(RefusedField(r), "campaign_id");
}

TEST(MessageCodec, TheErrorNamesTheFieldItsSizeAndBound) {
  msg::WorkerStatus s = Status();
  s.host = std::string(129, 'h');
  try {
    EncodedSample<msg::WorkerStatus> encoded(s);
    FAIL() << "a host of 129 bytes was encoded";
  } catch (const MessageError& e) {
    EXPECT_STREQ(e.what(), "host: 129 bytes exceed the bound of 128");
  }
  s.host = std::string("h\0st", 4);
  EXPECT_EQ(RefusedField(s), "host");
}

// A received sample over a bound, or with an enum value the IDL does not know, gets the same
// error in decode_error; its key fields stay, so that the daemons can name its instance.
TEST(MessageCodec, AReceivedFieldOverItsBoundIsRefusedWithTheSameError) {
  std::string result(wire::kMaxResultJson + 1, 'r');
  rlpos_msg_JobEvent c{};
  std::strcpy(c.worker_id, "w-7");
  c.slot = 2;
  c.result_json._buffer = reinterpret_cast<std::uint8_t*>(result.data());
  c.result_json._length = c.result_json._maximum = static_cast<std::uint32_t>(result.size());
  Received<msg::JobEvent> got = DecodeSample<msg::JobEvent>(&c, true);
  EXPECT_EQ(got.decode_error, "result_json: 262145 bytes exceed the bound of 262144");
  EXPECT_EQ(got.data.worker_id, "w-7");
  EXPECT_EQ(got.data.slot, 2);

  c.result_json._length = c.result_json._maximum = 0;
  const std::int32_t unknown = 4;
  std::memcpy(&c.state, &unknown, sizeof unknown);
  got = DecodeSample<msg::JobEvent>(&c, true);
  EXPECT_EQ(got.decode_error, "state: 4 is not a known value");
}

TEST(MessageCodec, ASampleWithoutDataDecodesOnlyItsKey) {
  const msg::JobAssignment sent = Eval();
  const EncodedSample<msg::JobAssignment> encoded(sent);
  const Received<msg::JobAssignment> got =
      DecodeSample<msg::JobAssignment>(encoded.c_sample(), false);
  EXPECT_EQ(got.decode_error, "");
  EXPECT_EQ(got.data.worker_id, sent.worker_id);
  EXPECT_EQ(got.data.slot, sent.slot);
  EXPECT_EQ(got.data.order.job_id, "");
  EXPECT_FALSE(got.data.order.placement.has_value());
}

}  // namespace
}  // namespace rlpos
