#pragma once
// JobParams' fields, declared once: each one's name (as the wire, the store and the content hash
// spell it), the kinds of job whose run it changes, and the scenario setting it fixes, if any.
// The content hash (campaign/job_content.h) and the job's scenario settings (job/job_settings.h)
// are made from this list; the build fails when JobParams has a field that is not on it.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/job/job.h"

namespace rlpos {

// Sets of job kinds, for JobField::kinds.
enum JobKinds : unsigned {
  kNoKind = 0,
  kTrainJob = 1u << static_cast<unsigned>(JobKind::kTrain),
  kPositionJob = 1u << static_cast<unsigned>(JobKind::kPosition),
  kEvalJob = 1u << static_cast<unsigned>(JobKind::kEval),
  kTrackJob = 1u << static_cast<unsigned>(JobKind::kTrack),
  kEveryKind = kTrainJob | kPositionJob | kEvalJob | kTrackJob,
};

constexpr bool Includes(unsigned kinds, JobKind kind) {
  return (kinds >> static_cast<unsigned>(kind)) & 1u;
}

template <typename T>
struct JobField {
  const char* name;
  T JobParams::*member;
  // The kinds of job whose run the field changes: part of their content, and the only kinds
  // whose scenario gets its setting. A field outside them only says where a job comes from.
  unsigned kinds;
  // The scenario path (a JSON pointer) the field's value is set at, or nullptr: a field that is
  // no scenario setting (the overrides themselves; what the command line of the kind says).
  const char* setting;
};

template <typename T>
constexpr JobField<T> Field(const char* name, T JobParams::*member, unsigned kinds,
                            const char* setting) {
  return {name, member, kinds, setting};
}

inline constexpr auto kJobFields = std::make_tuple(
    Field("kind", &JobParams::kind, kEveryKind, nullptr),
    // The name in its campaign: the content is the document's sha256, not what it is called.
    Field("scenario", &JobParams::scenario, kNoKind, nullptr),
    // An eval carries its train job's seed to say where its position came from.
    Field("train_seed", &JobParams::train_seed, kTrainJob, "/agent/seed"),
    // Track's goes on its command line (--fidelity), as the positioner does.
    Field("fidelity", &JobParams::fidelity, kTrainJob | kTrackJob, "/env/fidelity"),
    Field("train_episodes", &JobParams::train_episodes, kTrainJob, "/agent/train_episodes"),
    Field("positioner", &JobParams::positioner, kPositionJob | kTrackJob, nullptr),  // --positioner
    // The policy a named-policy rl position job flies (--policy): another policy, another
    // placement, so it is part of the content.
    Field("policy_sha256", &JobParams::policy_sha256, kPositionJob, nullptr),
    Field("rng_run", &JobParams::rng_run, kEvalJob | kTrackJob, "/simulation/run"),
    Field("duration_s", &JobParams::duration_s, kEveryKind, "/simulation/duration"),
    Field("warmup_s", &JobParams::warmup_s, kEveryKind, "/simulation/warmup"),
    Field("overrides", &JobParams::overrides, kEveryKind, nullptr));

// How many fields an aggregate has: the most initialisers T{...} takes.
namespace detail {
struct AnyField {
  template <typename T>
  operator T() const;
};
template <typename T, typename Indices, typename = void>
struct TakesInitialisers : std::false_type {};
template <typename T, std::size_t... I>
struct TakesInitialisers<T, std::index_sequence<I...>,
                         std::void_t<decltype(T{(void(I), AnyField{})...})>> : std::true_type {};
}  // namespace detail

template <typename T, std::size_t N = 0>
constexpr std::size_t AggregateFieldCount() {
  static_assert(std::is_aggregate_v<T>);
  if constexpr (detail::TakesInitialisers<T, std::make_index_sequence<N + 1>>::value) {
    return AggregateFieldCount<T, N + 1>();
  } else {
    return N;
  }
}

static_assert(std::tuple_size_v<decltype(kJobFields)> == AggregateFieldCount<JobParams>(),
              "a field of JobParams is missing from kJobFields (common/job/job_fields.h): "
              "declare it there, or the content hash would not see it");

// Calls visit(field, value) for each field of `params` (const or not), in declaration order.
template <typename Params, typename Visit>
void ForEachField(Params& params, Visit&& visit) {
  std::apply([&](const auto&... field) { (visit(field, params.*(field.member)), ...); },
             kJobFields);
}

// A field's value as JSON: null when unset (an empty text is unset), the kind by its name, an
// override as [path, value]. What the content hash hashes and a setting is made of.
nlohmann::json FieldJson(JobKind kind);
nlohmann::json FieldJson(const std::string& text);
nlohmann::json FieldJson(const std::optional<std::uint64_t>& value);
nlohmann::json FieldJson(const std::optional<int>& value);
nlohmann::json FieldJson(const std::optional<double>& value);
nlohmann::json FieldJson(const std::vector<ScenarioOverride>& overrides);

}  // namespace rlpos
