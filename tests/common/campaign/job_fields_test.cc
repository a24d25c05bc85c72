// The content hash is made from JobParams' field declaration (job/job_fields.h): every declared
// field changes the key of exactly the kinds of job whose run it changes. (A field of JobParams
// missing from the declaration fails the build: see the static_assert there.)
#include "common/job/job_fields.h"

#include <gtest/gtest.h>

#include "common/campaign/job_content.h"

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

}  // namespace
}  // namespace rlpos
