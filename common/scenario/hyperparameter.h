#pragma once
// A hyperparameter declared once: its JSON key, the spec member it sets (whose initialiser is
// its default), its range and its doc. Each algorithm lists its own in one file
// (dqn_hyperparameters.h, ppo_..., sac_..., agent_...); the scenario parser, ToJson, --set's
// "did you mean" and the docs table (rlpos-sim describe hyperparameters) all read that list.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "common/config/object_reader.h"

namespace rlpos {

// (0, hi]: a rate or a fraction that must not be zero.
inline NumberRange PositiveAtMost(double hi) {
  return {0.0, hi, true};
}
// Booleans have none.
inline NumberRange NoRange() {
  return {};
}
// [lo, hi] for an integer hyperparameter (exact in a double up to 2^53).
inline NumberRange Integers(long long lo, long long hi) {
  return {static_cast<double>(lo), static_cast<double>(hi), false};
}

template <typename Spec>
struct Hyperparameter {
  // The member's type is the hyperparameter's: an unset optional is JSON null.
  using Member = std::variant<double Spec::*, int Spec::*, std::int64_t Spec::*,
                              std::uint64_t Spec::*, bool Spec::*, std::optional<double> Spec::*>;
  const char* key;
  Member member;
  NumberRange range;  // numbers only; an integer's bounds are whole
  const char* doc;
};

// One algorithm's list, read from (and written to) the JSON object at `path`.
template <typename Spec>
struct HyperparameterTable {
  const char* section;  // "dqn", "ppo", "sac", "agent"
  const char* path;     // "/agent", "/agent/ppo", ...
  const char* summary;  // one line above its docs table
  std::vector<Hyperparameter<Spec>> entries;
  // Checks that span several keys (e.g. minibatches <= rollout_steps); may be null.
  void (*check)(const Spec& spec, const ObjectReader& reader) = nullptr;
};

// Reads every declared key present in `reader`'s object into `spec` (absent keys keep the
// member's default), in declaration order, with the declared range.
template <typename Spec>
void ReadHyperparameters(ObjectReader& reader, const HyperparameterTable<Spec>& table, Spec& spec) {
  for (const auto& h : table.entries) {
    std::visit(
        [&](auto member) {
          auto& value = spec.*member;
          using T = std::decay_t<decltype(value)>;
          if constexpr (std::is_same_v<T, double>) {
            value = reader.Number(h.key, value, h.range);
          } else if constexpr (std::is_same_v<T, bool>) {
            value = reader.Bool(h.key, value);
          } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            const nlohmann::json* v = reader.Child(h.key);
            if (v && !v->is_null())
              value = CheckedNumber(*v, reader.PathOf(h.key), h.range);
          } else {
            value = static_cast<T>(reader.Integer(h.key, static_cast<long long>(value),
                                                  static_cast<long long>(h.range.min),
                                                  static_cast<long long>(h.range.max)));
          }
        },
        h.member);
  }
  if (table.check)
    table.check(spec, reader);
}

// Writes every declared hyperparameter of `spec` into `object` under its key.
template <typename Spec>
void WriteHyperparameters(const Spec& spec, const HyperparameterTable<Spec>& table,
                          nlohmann::json& object) {
  for (const auto& h : table.entries) {
    std::visit(
        [&](auto member) {
          const auto& value = spec.*member;
          using T = std::decay_t<decltype(value)>;
          if constexpr (std::is_same_v<T, std::optional<double>>) {
            object[h.key] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
          } else {
            object[h.key] = value;
          }
        },
        h.member);
  }
}

}  // namespace rlpos
