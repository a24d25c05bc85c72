#include "worker/programs/rlpos_sim/describe_command.h"

#include <iostream>

#include "common/metrics/eval_metrics.h"
#include "common/metrics/track_metrics.h"
#include "common/scenario/names.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario/settings_docs.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {

void AddDescribe(CLI::App& app, DescribeCommand& describe) {
  describe.command = app.add_subcommand("describe", "Print a table of the docs as Markdown");
  describe.command->require_subcommand(1);
  describe.metrics = describe.command->add_subcommand(
      "metrics", "Print the eval metrics (name, unit, JSON key, SQL column, doc)");
  describe.track_metrics = describe.command->add_subcommand(
      "track-metrics", "Print the metrics of a track run (JSON key and SQL column, unit, doc)");
  describe.hyperparameters = describe.command->add_subcommand(
      "hyperparameters", "Print the agents' hyperparameters (key, type, default, range, doc)");
  describe.hyperparameters
      ->add_option(
          "--algorithm", describe.algorithm,
          Choices(kAlgorithms) + ": its own and the shared ones (default: every algorithm)")
      ->check(CLI::IsMember(AllAlgorithms()));
  describe.settings = describe.command->add_subcommand(
      "settings",
      "Print every setting of a scenario, section by section (key, type, default, values, doc)");
  std::vector<std::string> sections;
  std::string listed;
  for (const auto& section : AllSettingsSections()) {
    sections.push_back(section.section);
    listed += (listed.empty() ? "" : ", ") + section.section;
  }
  describe.settings
      ->add_option("--section", describe.section,
                   "One section's table alone, without heading: " + listed)
      ->check(CLI::IsMember(sections));
  describe.defaults = describe.command->add_subcommand(
      "defaults", "Print the named default sets a kind of run starts from (name, use, settings)");
  describe.settings->add_flag("--json", describe.json,
                              "As JSON: [{section, path, summary, settings: [{key, ...}]}]");
}

int RunDescribe(const DescribeCommand& describe) {
  if (*describe.metrics)
    std::cout << EvalMetricsMarkdown();
  else if (*describe.track_metrics)
    std::cout << TrackMetricsMarkdown();
  else if (*describe.defaults)
    std::cout << DefaultSetsMarkdown();
  else if (*describe.hyperparameters)
    std::cout << HyperparametersMarkdown(HyperparameterSectionsFor(describe.algorithm));
  else if (describe.json)
    std::cout << SettingsSectionsJson(describe.section.empty()
                                          ? AllSettingsSections()
                                          : std::vector{SettingsSectionNamed(describe.section)})
                     .dump(2)
              << "\n";
  else if (!describe.section.empty())
    std::cout << SettingsTableMarkdown(SettingsSectionNamed(describe.section));
  else
    std::cout << SettingsSectionsMarkdown(AllSettingsSections());
  return kExitOk;
}

}  // namespace rlpos::sim
