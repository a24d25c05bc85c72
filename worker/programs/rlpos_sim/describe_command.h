#pragma once
// rlpos-sim describe metrics | track-metrics | hyperparameters [--algorithm dqn|ppo|sac] |
// settings [--section S] [--json] | defaults: the tables that mirror the code, printed as Markdown
// (or JSON) from their one declaration (common/metrics/eval_metrics.h, track_metrics.h,
// common/scenario/*_settings.h, *_hyperparameters.h and default_sets.h). The docs hold this output
// (docs/*.md between their "GENERATED metrics" and "GENERATED settings-<section>" markers,
// docs/campaigns.md between its "GENERATED track-metrics" ones, docs/hyperparameters.md), and
// tests check that they still do.
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos::sim {

struct DescribeCommand {
  CLI::App* command = nullptr;
  CLI::App* metrics = nullptr;
  CLI::App* track_metrics = nullptr;
  CLI::App* hyperparameters = nullptr;
  CLI::App* settings = nullptr;
  CLI::App* defaults = nullptr;
  std::string algorithm;  // hyperparameters: dqn|ppo|sac; empty: every algorithm
  std::string section;    // settings: one section's table alone; empty: every section
  bool json = false;      // settings: as JSON
};

// Adds `describe` and its subcommands to `app`.
void AddDescribe(CLI::App& app, DescribeCommand& describe);
// Prints the table of the subcommand that was parsed.
int RunDescribe(const DescribeCommand& describe);

}  // namespace rlpos::sim
