#pragma once
// rlpos-sim describe hyperparameters [--algorithm dqn|ppo|sac]: the agents' hyperparameters as
// markdown tables, from their declarations (common/scenario/*_hyperparameters.h).
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos::sim {

struct DescribeHyperparametersOptions {
  std::string algorithm;  // empty: every algorithm
};

// Adds the "hyperparameters" subcommand under `describe`.
CLI::App* AddDescribeHyperparameters(CLI::App* describe, DescribeHyperparametersOptions& options);

int RunDescribeHyperparameters(const DescribeHyperparametersOptions& options);

}  // namespace rlpos::sim
