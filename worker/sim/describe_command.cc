#include "worker/sim/describe_command.h"

#include <iostream>

#include "common/metrics/eval_metrics.h"
#include "common/metrics/track_metrics.h"
#include "common/scenario/hyperparameter_docs.h"
#include "common/scenario/names.h"
#include "common/scenario/scenario_parser.h"
#include "worker/sim/commands.h"

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
}

int RunDescribe(const DescribeCommand& describe) {
  if (*describe.metrics)
    std::cout << EvalMetricsMarkdown();
  else if (*describe.track_metrics)
    std::cout << TrackMetricsMarkdown();
  else
    std::cout << HyperparametersMarkdown(HyperparameterSectionsFor(describe.algorithm));
  return kExitOk;
}

}  // namespace rlpos::sim
