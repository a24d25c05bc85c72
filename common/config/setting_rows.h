#pragma once
// A settings table as text: the rows of its docs table, which `rlpos-sim describe settings`
// prints (Markdown or JSON) and the docs hold between GENERATED markers.
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/config/setting.h"

namespace rlpos {

// One row of a docs table: everything as text.
struct SettingRow {
  std::string key;  // dotted, as --set takes it: "wifi.tx_power", "agent.ppo.clip"
  // real | integer | boolean | real or null | string | list of strings | ns-3 object
  std::string type;
  std::string default_value;  // as JSON; where defaults differ by case, the first case's
  // The docs' default cell: default_value with its unit, or where the cases (e.g. algorithms)
  // have different defaults, each one's: "dqn 1000, ppo 4000, sac 2500".
  std::string default_text;
  std::string values;  // "(0, 1]", "[1, 1000] MHz", ">= 0", or the choices; empty: any
  std::string unit;
  std::string doc;
  NumberRange bounds;                // the range as declared, for tests that probe it
  std::vector<std::string> choices;  // likewise
};

struct SettingsSection {
  std::string section;  // "wifi", "env.reward", "agent", "ppo", ...
  std::string path;     // its JSON object: "/wifi", "/agent/ppo", ...
  std::string summary;
  std::vector<SettingRow> rows;
};

// A case's name and the spec that holds its defaults ("dqn" and DQN's, ...).
template <typename Spec>
using NamedDefaults = std::vector<std::pair<std::string, Spec>>;

// Text helpers of the rows (setting_rows.cc).
std::string RangeText(const NumberRange& range, bool integer);
std::string DefaultText(const std::vector<std::pair<std::string, std::string>>& defaults,
                        const std::string& unit);
std::string TypeText(const char* cpp_kind);

// The value type of a member pointer; a custom value's own struct.
template <typename Spec, typename Member>
struct MemberType {
  using type = Member;
};
template <typename Spec, typename T>
struct MemberType<Spec, T Spec::*> {
  using type = T;
};

// `table`'s rows, with the defaults of each case in `defaults` (at least one; one row each).
template <typename Spec>
SettingsSection DescribeSettings(const SettingsTable<Spec>& table,
                                 const NamedDefaults<Spec>& defaults) {
  SettingsSection out{table.section, table.path, table.summary, {}};
  // "/env/reward" -> "env.reward."; the top level's "" -> "" (its keys stand alone).
  std::string prefix = *table.path == '\0' ? "" : std::string(table.path).substr(1) + ".";
  for (auto& c : prefix)
    c = (c == '/') ? '.' : c;
  std::vector<std::pair<std::string, nlohmann::json>> values;
  for (const auto& [name, spec] : defaults) {
    values.emplace_back(name, nlohmann::json::object());
    Spec copy = spec;
    for (const auto& s : table.entries) {
      if (s.default_from)
        s.default_from(copy);
    }
    for (const auto& s : table.entries) {
      std::visit([&](auto member) { values.back().second[s.key] = MemberJson(copy, member); },
                 s.member);
    }
  }
  for (const auto& s : table.entries) {
    std::vector<std::pair<std::string, std::string>> texts;
    for (const auto& [name, json] : values)
      texts.emplace_back(name, json.at(s.key).dump());
    SettingRow row{prefix + s.key,
                   "",
                   texts.front().second,
                   s.required ? "required" : DefaultText(texts, s.unit),
                   "",
                   s.unit,
                   s.doc,
                   s.range,
                   s.choices};
    std::visit(
        [&](auto member) {
          using T = typename MemberType<Spec, decltype(member)>::type;
          constexpr bool kNumber = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;
          if constexpr (std::is_same_v<decltype(member), CustomValue<Spec>>) {
            row.type = member.type;
          } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            row.type = TypeText("optional");
            row.values = RangeText(s.range, false);
          } else if constexpr (kNumber) {
            row.type = TypeText(std::is_integral_v<T> ? "integer" : "real");
            row.values = RangeText(s.range, std::is_integral_v<T>);
          } else if constexpr (std::is_same_v<T, bool>) {
            row.type = TypeText("bool");
          } else if constexpr (std::is_same_v<T, std::string>) {
            row.type = TypeText("string");
          } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
            row.type = TypeText("strings");
          } else {
            row.type = TypeText("object");
          }
        },
        s.member);
    if (!row.choices.empty()) {
      for (const auto& choice : row.choices)
        row.values += (row.values.empty() ? "" : ", ") + choice;
    } else if (!row.values.empty() && !row.unit.empty() && row.values != "any") {
      row.values += " " + row.unit;
    }
    out.rows.push_back(row);
  }
  return out;
}

// A section's own defaults, those its spec declares.
template <typename Spec>
SettingsSection DescribeSettings(const SettingsTable<Spec>& table) {
  return DescribeSettings(table, NamedDefaults<Spec>{{table.section, Spec{}}});
}

// The docs table of one section (no heading): "| key | type | default | values | |" and a row
// per setting.
std::string SettingsTableMarkdown(const SettingsSection& section);
// A heading ("## <section>"), the summary and the table of each section.
std::string SettingsSectionsMarkdown(const std::vector<SettingsSection>& sections);
// [{"section", "path", "summary", "settings": [{"key", "type", "default", "values", "unit",
// "doc"}, ...]}, ...]
nlohmann::json SettingsSectionsJson(const std::vector<SettingsSection>& sections);

}  // namespace rlpos
