#pragma once
// A setting declared once: its JSON key, the spec member it sets (whose initialiser is its
// default), its range or choices, its unit and its doc. Each section of a scenario (venue, wifi,
// env, ..., and each algorithm's hyperparameters) lists its own in one table; the parser, ToJson,
// --set's errors ("did you mean") and the docs tables (rlpos-sim describe settings) all read
// that list, as ns-3's attributes and CleanRL's Args do.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/config/object_spec.h"

namespace rlpos {

// (0, hi]: a rate or a fraction that must not be zero.
inline NumberRange PositiveAtMost(double hi) {
  return {0.0, hi, true};
}
// Booleans, strings, lists and objects have none.
inline NumberRange NoRange() {
  return {};
}
// [lo, hi] for an integer setting (exact in a double up to 2^53).
inline NumberRange Integers(long long lo, long long hi) {
  return {static_cast<double>(lo), static_cast<double>(hi), false};
}

// A value of its own shape ([x, y, z], [min, max], {"mbps": R} or {"mcs": I}, ...): how it is
// read into the spec (errors name `path`), written back, and named in the docs.
template <typename Spec>
struct CustomValue {
  void (*read)(Spec& spec, const nlohmann::json& value, const std::string& path);
  nlohmann::json (*write)(const Spec& spec);
  const char* type;  // the docs' type column: "[x, y, z]", "[min, max]", ...
};

template <typename Spec>
struct Setting {
  // The member's type is the setting's: an unset optional is JSON null, a string list a JSON
  // array of strings, an ObjectSpec an ns-3 object {"type", "attributes"}.
  using Member =
      std::variant<double Spec::*, int Spec::*, std::int64_t Spec::*, std::uint32_t Spec::*,
                   std::uint64_t Spec::*, bool Spec::*, std::optional<double> Spec::*,
                   std::string Spec::*, std::vector<std::string> Spec::*, ObjectSpec Spec::*,
                   CustomValue<Spec>>;
  const char* key;
  Member member;
  NumberRange range;  // numbers only; an integer's bounds are whole
  const char* doc;
  const char* unit = "";  // "m", "s", "dBm", ...; empty where none
  // A string's (or each list item's) allowed values; empty: any. A list is never empty.
  std::vector<std::string> choices = {};
  // Non-null: the key is required, and its absence is "is required (<this>)"; "": no hint.
  const char* required = nullptr;
  // Whether ToJson writes it; null: always. A key added after documents existed is written only
  // when it is set, so that those documents keep their bytes (and campaigns their ids).
  bool (*written)(const Spec& spec) = nullptr;
  // Sets the default from the settings read before it (declaration order); null: the
  // initialiser's. Where it is set, `doc` says how.
  void (*default_from)(Spec& spec) = nullptr;
};

// One section's settings, read from (and written to) the JSON object at `path`.
template <typename Spec>
struct SettingsTable {
  const char* section;  // "wifi", "env", "ppo", ...: the heading of its docs table
  const char* path;     // its JSON object: "/wifi", "/agent/ppo", ...
  const char* summary;  // one line above its docs table
  std::vector<Setting<Spec>> entries;
  // Checks that span several keys (e.g. minibatches <= rollout_steps), after every key is read;
  // may be null. Errors name the key at fault through `reader`.
  void (*check)(const Spec& spec, const ObjectReader& reader) = nullptr;
};

// One setting's value read from `reader` into `spec` (absent: unchanged).
template <typename Spec, typename Member>
void ReadMember(ObjectReader& reader, const Setting<Spec>& s, const Member& member, Spec& spec) {
  if constexpr (std::is_same_v<Member, CustomValue<Spec>>) {
    if (const nlohmann::json* v = reader.Child(s.key))
      member.read(spec, *v, reader.PathOf(s.key));
  } else {
    auto& value = spec.*member;
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, double>) {
      value = reader.Number(s.key, value, s.range);
    } else if constexpr (std::is_same_v<T, bool>) {
      value = reader.Bool(s.key, value);
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      const nlohmann::json* v = reader.Child(s.key);
      if (v && !v->is_null())
        value = CheckedNumber(*v, reader.PathOf(s.key), s.range);
    } else if constexpr (std::is_same_v<T, std::string>) {
      value = reader.String(s.key, value, s.choices);
    } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
      if (const nlohmann::json* v = reader.Child(s.key))
        value = ReadStringList(*v, reader.PathOf(s.key), s.choices);
    } else if constexpr (std::is_same_v<T, ObjectSpec>) {
      if (const nlohmann::json* v = reader.Child(s.key))
        value = ReadObjectSpec(*v, reader.PathOf(s.key));
    } else {
      value = static_cast<T>(reader.Integer(s.key, static_cast<long long>(value),
                                            static_cast<long long>(s.range.min),
                                            static_cast<long long>(s.range.max)));
    }
  }
}

// One setting's value in `spec` as JSON (an unset optional: null).
template <typename Spec, typename Member>
nlohmann::json MemberJson(const Spec& spec, const Member& member) {
  if constexpr (std::is_same_v<Member, CustomValue<Spec>>) {
    return member.write(spec);
  } else {
    const auto& value = spec.*member;
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, std::optional<double>>)
      return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
    else if constexpr (std::is_same_v<T, ObjectSpec>)
      return ObjectSpecJson(value);
    else
      return value;
  }
}

// Reads every declared key present in `reader`'s object into `spec` (absent keys keep the
// member's default), in declaration order, with the declared range or choices; then the table's
// check. The caller's reader then rejects any key nobody read.
template <typename Spec>
void ReadSettings(ObjectReader& reader, const SettingsTable<Spec>& table, Spec& spec) {
  for (const auto& s : table.entries) {
    if (s.default_from)
      s.default_from(spec);
    if (s.required && !reader.Has(s.key)) {
      const std::string hint = s.required;
      throw ConfigError(reader.PathOf(s.key),
                        "is required" + (hint.empty() ? "" : " (" + hint + ")"));
    }
    std::visit([&](auto member) { ReadMember(reader, s, member, spec); }, s.member);
  }
  if (table.check)
    table.check(spec, reader);
}

// The object `v` at `path` (a list's element: "/ues/3") read into `spec`, which holds its
// defaults; any key the table does not declare is an error with a "did you mean".
template <typename Spec>
Spec ReadObject(const nlohmann::json& v, const std::string& path, const SettingsTable<Spec>& table,
                Spec spec) {
  ObjectReader reader(v, path);
  ReadSettings(reader, table, spec);
  reader.Finish();
  return spec;
}

// A section's object at the table's path (absent: {}) read into a spec that starts from
// `defaults`.
template <typename Spec>
Spec ReadSection(const nlohmann::json* object, const SettingsTable<Spec>& table,
                 Spec defaults = {}) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  return ReadObject(object ? *object : kEmpty, table.path, table, std::move(defaults));
}

// Writes every declared setting of `spec` that is written into `object` under its key.
template <typename Spec>
void WriteSettings(const Spec& spec, const SettingsTable<Spec>& table, nlohmann::json& object) {
  for (const auto& s : table.entries) {
    if (s.written && !s.written(spec))
      continue;
    std::visit([&](auto member) { object[s.key] = MemberJson(spec, member); }, s.member);
  }
}

// The table's settings of `spec` as one JSON object.
template <typename Spec>
nlohmann::json SettingsJson(const Spec& spec, const SettingsTable<Spec>& table) {
  nlohmann::json object = nlohmann::json::object();
  WriteSettings(spec, table, object);
  return object;
}

}  // namespace rlpos
