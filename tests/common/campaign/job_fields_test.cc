// The content hash is made from JobParams' field declaration (job/job_fields.h): every declared
// field changes the key of exactly the kinds of job whose run it changes. (A field of JobParams
// missing from the declaration fails the build: see the static_assert there.)
#include "common/job/job_fields.h"

#include <gtest/gtest.h>

#include "common/campaign/job_content.h"
#include "common/job/job_settings.h"

namespace rlpos {
namespace {

// A different value of each field's type.
void Change(JobKind& kind) {
  kind = kind == JobKind::kEval ? JobKind::kTrain : JobKind::kEval;
}
void Change(std::string& text) {
  text += "x";
}
template <typename T>
void Change(std::optional<T>& value) {
  value = value.value_or(T{}) + 1;
}
void Change(std::vector<ScenarioOverride>& overrides) {
  overrides.push_back({"wifi.mode", "adhoc"});
}

// Params of `kind` with every field set.
JobParams EveryFieldSet(JobKind kind) {
  JobParams p;
  p.kind = kind;
  p.scenario = "B";
  p.train_seed = 1;
  p.fidelity = "analytic";
  p.train_episodes = 10;
  p.positioner = "oracle";
  p.policy_sha256 = std::string(64, 'a');
  p.rng_run = 3;
  p.duration_s = 2;
  p.warmup_s = 0.5;
  p.overrides = {{"uav.step", "5"}};
  return p;
}

// `params` with the field at `index` (declaration order) changed; its declared kinds.
JobParams WithFieldChanged(JobParams params, std::size_t index, unsigned& kinds,
                           std::string& name) {
  std::size_t i = 0;
  ForEachField(params, [&](const auto& field, auto& value) {
    if (i++ != index)
      return;
    kinds = field.kinds;
    name = field.name;
    Change(value);
  });
  return params;
}

TEST(JobFields, EachFieldChangesTheKeyOfTheKindsItIsDeclaredFor) {
  constexpr std::size_t kFields = std::tuple_size_v<decltype(kJobFields)>;
  for (const JobKind kind : {JobKind::kTrain, JobKind::kPosition, JobKind::kEval}) {
    const JobParams base = EveryFieldSet(kind);
    const std::string key = JobContentBase(base, "aa", "v1");
    for (std::size_t i = 0; i < kFields; ++i) {
      unsigned kinds = 0;
      std::string name;
      const JobParams changed = WithFieldChanged(base, i, kinds, name);
      EXPECT_EQ(JobContentBase(changed, "aa", "v1") != key, Includes(kinds, kind))
          << name << " of a " << ToString(kind) << " job";
    }
  }
}

TEST(JobFields, TheSettingsOfAJobAreItsDeclaredFieldsOfItsKind) {
  const auto paths = [](const JobParams& p) {
    std::vector<std::string> out;
    for (const auto& s : JobSettings(p))
      out.push_back(ToString(s.setting));
    return out;
  };
  EXPECT_EQ(paths(EveryFieldSet(JobKind::kTrain)),
            (std::vector<std::string>{"/agent/seed=1", "/env/fidelity=analytic",
                                      "/agent/train_episodes=10", "/simulation/duration=2",
                                      "/simulation/warmup=0.5"}));
  EXPECT_EQ(paths(EveryFieldSet(JobKind::kPosition)),
            (std::vector<std::string>{"/simulation/duration=2", "/simulation/warmup=0.5"}));
  EXPECT_EQ(paths(EveryFieldSet(JobKind::kEval)),
            (std::vector<std::string>{"/simulation/run=3", "/simulation/duration=2",
                                      "/simulation/warmup=0.5"}));
  JobParams open = EveryFieldSet(JobKind::kTrain);  // unset: the scenario's own value stands
  open.train_episodes.reset();
  open.warmup_s.reset();
  EXPECT_EQ(paths(open), (std::vector<std::string>{"/agent/seed=1", "/env/fidelity=analytic",
                                                   "/simulation/duration=2"}));
}

TEST(JobFields, AContradictionIsAnOverrideThatGivesASettingAnotherValue) {
  const std::vector<ScenarioOverride> settings{{"/env/fidelity", "analytic"},
                                               {"/simulation/duration", "2"}};
  const auto found = [&](const std::vector<ScenarioOverride>& overrides) {
    const auto c = FindContradiction(overrides, settings);
    return c ? std::to_string(c->override_index) + "," + std::to_string(c->setting_index) : "none";
  };
  EXPECT_EQ(found({{"wifi.mode", "adhoc"}, {"env.fidelity", "analytic"}}), "none");
  EXPECT_EQ(found({{"simulation.duration", "2.0"}}), "none");  // the same number
  EXPECT_EQ(found({{"wifi.mode", "adhoc"}, {"env.fidelity", "packet"}}), "1,0");
  EXPECT_EQ(found({{"/simulation/duration", "3"}}), "0,1");
  EXPECT_EQ(found({{"simulation", "{\"duration\": 3}"}}), "0,1");  // an object holding it
  EXPECT_EQ(found({{"simulation", "{\"run\": 3}"}}), "none");      // one not holding it
}

}  // namespace
}  // namespace rlpos
