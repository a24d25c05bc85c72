#include "common/scenario/hyperparameter_docs.h"

#include <sstream>
#include <type_traits>
#include <utility>

#include "common/scenario/scenario.h"

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

template <typename Spec>
HyperparameterSection DescribeTable(const HyperparameterTable<Spec>& table) {
  HyperparameterSection out{table.section, table.path, table.summary, {}};
  std::string prefix = std::string(table.path).substr(1);
  for (auto& c : prefix)
    c = (c == '/') ? '.' : c;
  nlohmann::json defaults;
  WriteHyperparameters(Spec{}, table, defaults);
  for (const auto& h : table.entries) {
    HyperparameterRow row{prefix + "." + h.key, "", defaults.at(h.key).dump(), "", h.doc, h.range};
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

}  // namespace

std::vector<HyperparameterSection> AllHyperparameterSections() {
  return {DescribeTable(AgentCommonHyperparameters()), DescribeTable(DqnHyperparameters()),
          DescribeTable(PpoHyperparameters()), DescribeTable(SacHyperparameters())};
}

std::vector<HyperparameterSection> HyperparameterSectionsFor(const std::string& algorithm) {
  std::vector<HyperparameterSection> out;
  for (auto& section : AllHyperparameterSections()) {
    if (algorithm.empty() || section.section == "agent" || section.section == algorithm) {
      out.push_back(std::move(section));
    }
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
      out << "| `" << row.key << "` | " << row.type << " | " << Cell(row.default_value) << " | "
          << Cell(row.range) << " | " << Cell(row.doc) << " |\n";
    }
  }
  return out.str();
}

}  // namespace rlpos
