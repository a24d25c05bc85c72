#include "worker/sim/describe_hyperparameters.h"

#include <iostream>

#include "common/scenario/hyperparameter_docs.h"
#include "common/scenario/scenario_parser.h"
#include "worker/sim/commands.h"

namespace rlpos::sim {

CLI::App* AddDescribeHyperparameters(CLI::App* describe, DescribeHyperparametersOptions& options) {
  auto* command = describe->add_subcommand(
      "hyperparameters", "Print the agents' hyperparameters (key, type, default, range, doc)");
  command
      ->add_option("--algorithm", options.algorithm,
                   "dqn|ppo|sac: its own and the shared ones (default: every algorithm)")
      ->check(CLI::IsMember(AllAlgorithms()));
  return command;
}

int RunDescribeHyperparameters(const DescribeHyperparametersOptions& options) {
  std::cout << HyperparametersMarkdown(HyperparameterSectionsFor(options.algorithm));
  return kExitOk;
}

}  // namespace rlpos::sim
