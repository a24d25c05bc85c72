#include "common/scenario/hyperparameter_docs.h"

#include <sstream>
#include <type_traits>
#include <utility>

#include "common/scenario/scenario.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

std::string NumberText(double x, bool integer) {
  if (integer)
    return std::to_string(static_cast<long long>(x));
  std::ostringstream out;
  out << x;
  return out.str();
}

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

template <typename T>
std::string TypeText() {
  if (std::is_same_v<T, std::optional<double>>)
    return "real or null";
  if (std::is_same_v<T, bool>)
    return "boolean";
  return std::is_integral_v<T> ? "integer" : "real";
}

// One algorithm's defaults for a table: its name and the spec that holds them.
template <typename Spec>
using NamedDefaults = std::vector<std::pair<std::string, Spec>>;

// The default cell: the value all `defaults` share, or each algorithm's.
std::string DefaultText(const std::vector<std::pair<std::string, std::string>>& defaults) {
  bool same = true;
  for (const auto& d : defaults)
    same = same && d.second == defaults.front().second;
  if (same)
    return defaults.front().second;
  std::string text;
  for (const auto& d : defaults)
    text += (text.empty() ? "" : ", ") + d.first + " " + d.second;
  return text;
}

// `table`'s rows, with the defaults of each algorithm in `defaults` (at least one).
template <typename Spec>
HyperparameterSection DescribeTable(const HyperparameterTable<Spec>& table,
                                    const NamedDefaults<Spec>& defaults) {
  HyperparameterSection out{table.section, table.path, table.summary, {}};
  std::string prefix = std::string(table.path).substr(1);
  for (auto& c : prefix)
    c = (c == '/') ? '.' : c;
  std::vector<std::pair<std::string, nlohmann::json>> values;
  for (const auto& [algorithm, spec] : defaults) {
    values.emplace_back(algorithm, nlohmann::json::object());
    WriteHyperparameters(spec, table, values.back().second);
  }
  for (const auto& h : table.entries) {
    std::vector<std::pair<std::string, std::string>> texts;
    for (const auto& [algorithm, json] : values)
      texts.emplace_back(algorithm, json.at(h.key).dump());
    HyperparameterRow row{
        prefix + "." + h.key, "", texts.front().second, DefaultText(texts), "", h.doc, h.range};
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(std::declval<Spec&>().*member)>;
          row.type = TypeText<T>();
          if (!std::is_same_v<T, bool>)
            row.range = RangeText(h.range, std::is_integral_v<T>);
        },
        h.member);
    out.rows.push_back(row);
  }
  return out;
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

// The shared keys, with the one-UAV defaults of each of `algorithms`.
HyperparameterSection DescribeShared(const std::vector<std::string>& algorithms) {
  NamedDefaults<AgentCommonSpec> defaults;
  for (const auto& algorithm : algorithms)
    defaults.emplace_back(algorithm, AgentCommonDefaults(algorithm, 1));
  return DescribeTable(AgentCommonHyperparameters(), defaults);
}

// An algorithm's own keys, with the defaults its spec declares.
template <typename Spec>
HyperparameterSection DescribeOwn(const HyperparameterTable<Spec>& table) {
  return DescribeTable(table, NamedDefaults<Spec>{{table.section, Spec{}}});
}

}  // namespace

std::vector<HyperparameterSection> AllHyperparameterSections() {
  return {DescribeShared(AllAlgorithms()), DescribeOwn(DqnHyperparameters()),
          DescribeOwn(PpoHyperparameters()), DescribeOwn(SacHyperparameters())};
}

std::vector<HyperparameterSection> HyperparameterSectionsFor(const std::string& algorithm) {
  if (algorithm.empty())
    return AllHyperparameterSections();
  std::vector<HyperparameterSection> out{DescribeShared({algorithm})};
  for (auto& section : AllHyperparameterSections()) {
    if (section.section == algorithm)
      out.push_back(std::move(section));
  }
  return out;
}

std::string HyperparametersMarkdown(const std::vector<HyperparameterSection>& sections) {
  std::ostringstream out;
  out << "# Agent hyperparameters\n\n"
      << "Generated from their declarations (`common/scenario/*_hyperparameters.h`) by\n"
      << "`rlpos-sim describe hyperparameters`. Set one in the scenario's JSON or with\n"
      << "`--set KEY=VALUE`.\n";
  for (const auto& section : sections) {
    out << "\n## " << section.section << "\n\n"
        << section.summary << "\n\n"
        << "| key | type | default | range | |\n"
        << "|---|---|---|---|---|\n";
    for (const auto& row : section.rows) {
      out << "| `" << row.key << "` | " << row.type << " | " << Cell(row.default_text) << " | "
          << Cell(row.range) << " | " << Cell(row.doc) << " |\n";
    }
  }
  return out.str();
}

}  // namespace rlpos
