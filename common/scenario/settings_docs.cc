#include "common/scenario/settings_docs.h"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "common/scenario/default_sets.h"
#include "common/scenario/scenario.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario/scenario_settings.h"

namespace rlpos {
namespace {

// The shared keys, with the one-UAV defaults of each of `algorithms`.
SettingsSection DescribeShared(const std::vector<std::string>& algorithms) {
  NamedDefaults<AgentCommonSpec> defaults;
  for (const auto& algorithm : algorithms)
    defaults.emplace_back(algorithm, AgentCommonDefaults(algorithm, 1));
  return DescribeSettings(AgentCommonHyperparameters(), defaults);
}

// The top level: its settings (path "", so its keys take no prefix), then its lists.
SettingsSection DescribeTopLevel() {
  const SettingsTable<Scenario>& table = ScenarioSettings();
  SettingsSection out = DescribeSettings(table, {{table.section, ScenarioDefaults()}});
  for (auto& row : ScenarioListRows())
    out.rows.push_back(std::move(row));
  return out;
}

}  // namespace

std::vector<SettingsSection> AllHyperparameterSections() {
  return {DescribeShared(AllAlgorithms()), DescribeSettings(DqnHyperparameters()),
          DescribeSettings(PpoHyperparameters()), DescribeSettings(SacHyperparameters())};
}

std::vector<SettingsSection> AllSettingsSections() {
  std::vector<SettingsSection> out{DescribeTopLevel(),
                                   DescribeSettings(VenueSettings()),
                                   DescribeSettings(BuildingSettings()),
                                   DescribeSettings(UeSettings()),
                                   DescribeSettings(UavSettings()),
                                   DescribeSettings(RandomWalkSettings()),
                                   DescribeSettings(RandomWaypointSettings()),
                                   DescribeSettings(GaussMarkovSettings()),
                                   DescribeSettings(CrowdSettings()),
                                   DescribeSettings(WifiSettings()),
                                   DescribeSettings(TrafficSettings()),
                                   DescribeSettings(SimulationSettings()),
                                   DescribeSettings(EnvSettings()),
                                   DescribeSettings(RewardSettings()),
                                   DescribeSettings(AgentNetworkSettings())};
  for (auto& section : AllHyperparameterSections())
    out.push_back(std::move(section));
  return out;
}

SettingsSection SettingsSectionNamed(const std::string& section) {
  std::string known;
  for (auto& s : AllSettingsSections()) {
    if (s.section == section)
      return s;
    known += (known.empty() ? "" : ", ") + s.section;
  }
  throw std::invalid_argument("no settings section \"" + section + "\" (known: " + known + ")");
}

std::vector<SettingsSection> HyperparameterSectionsFor(const std::string& algorithm) {
  if (algorithm.empty())
    return AllHyperparameterSections();
  std::vector<SettingsSection> out{DescribeShared({algorithm})};
  for (auto& section : AllHyperparameterSections()) {
    if (section.section == algorithm)
      out.push_back(std::move(section));
  }
  return out;
}

std::string DefaultSetsMarkdown() {
  std::ostringstream out;
  out << "| set | applies to | settings (--set, in order) |\n|---|---|---|\n";
  for (const DefaultSet& set : DefaultSets()) {
    std::string settings;
    for (const std::string& o : set.overrides)
      settings += (settings.empty() ? "`" : ", `") + o + "`";
    out << "| `" << set.name << "` | " << set.summary << " | " << settings << " |\n";
  }
  return out.str();
}

std::string HyperparametersMarkdown(const std::vector<SettingsSection>& sections) {
  std::ostringstream out;
  out << "# Agent hyperparameters\n\n"
      << "Generated from their declarations (`common/scenario/*_hyperparameters.h`) by\n"
      << "`rlpos-sim describe hyperparameters`. Set one in the scenario's JSON or with\n"
      << "`--set KEY=VALUE`.\n"
      << SettingsSectionsMarkdown(sections);
  return out.str();
}

}  // namespace rlpos
