#include "common/config/setting_rows.h"

#include <sstream>
#include <string_view>

namespace rlpos {
namespace {

std::string NumberText(double x, bool integer) {
  if (integer)
    return std::to_string(static_cast<long long>(x));
  std::ostringstream out;
  out << x;
  return out.str();
}

// A table cell: a "|" would end it.
std::string Cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string RangeText(const NumberRange& range, bool integer) {
  const bool bounded_below = range.min > -1e300;
  const bool bounded_above = range.max < 1e300;
  const std::string lo = NumberText(range.min, integer);
  if (!bounded_above) {
    if (!bounded_below)
      return "any";
    return (range.min_exclusive ? "> " : ">= ") + lo;
  }
  return (range.min_exclusive ? "(" : "[") + lo + ", " + NumberText(range.max, integer) + "]";
}

std::string DefaultText(const std::vector<std::pair<std::string, std::string>>& defaults,
                        const std::string& unit) {
  const std::string suffix = unit.empty() ? "" : " " + unit;
  bool same = true;
  for (const auto& d : defaults)
    same = same && d.second == defaults.front().second;
  if (same)
    return defaults.front().second + suffix;
  std::string text;
  for (const auto& d : defaults)
    text += (text.empty() ? "" : ", ") + d.first + " " + d.second + suffix;
  return text;
}

std::string TypeText(const char* cpp_kind) {
  const std::string_view kind = cpp_kind;
  if (kind == "optional")
    return "real or null";
  if (kind == "bool")
    return "boolean";
  if (kind == "strings")
    return "list of strings";
  if (kind == "object")
    return "ns-3 object";
  return std::string(kind);  // integer, real, string
}

std::string SettingsTableMarkdown(const SettingsSection& section) {
  std::ostringstream out;
  out << "| key | type | default | values | |\n"
      << "|---|---|---|---|---|\n";
  for (const auto& row : section.rows) {
    out << "| `" << row.key << "` | " << row.type << " | " << Cell(row.default_text) << " | "
        << Cell(row.values) << " | " << Cell(row.doc) << " |\n";
  }
  return out.str();
}

std::string SettingsSectionsMarkdown(const std::vector<SettingsSection>& sections) {
  std::ostringstream out;
  for (const auto& section : sections) {
    out << "\n## " << section.section << "\n\n"
        << section.summary << "\n\n"
        << SettingsTableMarkdown(section);
  }
  return out.str();
}

nlohmann::json SettingsSectionsJson(const std::vector<SettingsSection>& sections) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& section : sections) {
    nlohmann::json settings = nlohmann::json::array();
    for (const auto& row : section.rows) {
      settings.push_back({{"key", row.key},
                          {"type", row.type},
                          {"default", nlohmann::json::parse(row.default_value)},
                          {"default_text", row.default_text},
                          {"values", row.values},
                          {"unit", row.unit},
                          {"doc", row.doc}});
    }
    out.push_back({{"section", section.section},
                   {"path", section.path},
                   {"summary", section.summary},
                   {"settings", settings}});
  }
  return out;
}

}  // namespace rlpos
