#pragma once
// Every section's declared settings as text: the docs tables that `rlpos-sim describe settings`
// and `describe hyperparameters` print, and docs/hyperparameters.md and the settings tables of
// docs/scenarios.md, mobility.md, env.md and agents.md hold.
#include <string>
#include <vector>

#include "common/config/setting_rows.h"

namespace rlpos {

// The scenario's sections (its top level, "scenario"; venue, building, ue, uav, each mobility
// model's, wifi, traffic, simulation, env, env.reward), then the agent's
// (AllHyperparameterSections).
std::vector<SettingsSection> AllSettingsSections();

// The section named `section` ("wifi", "env.reward", "ppo", ...); throws std::invalid_argument
// naming the known ones when there is none.
SettingsSection SettingsSectionNamed(const std::string& section);

// The shared hyperparameters ("agent", with every algorithm's defaults) first, then each
// algorithm's own in AllAlgorithms() order.
std::vector<SettingsSection> AllHyperparameterSections();

// The sections that apply to `algorithm`: the shared one with that algorithm's defaults, and its
// own. Empty: all of them.
std::vector<SettingsSection> HyperparameterSectionsFor(const std::string& algorithm);

// The named default sets (default_sets.h) as a Markdown table: name, when it applies, settings.
std::string DefaultSetsMarkdown();

// docs/hyperparameters.md: a title, then each section's heading, summary and table.
std::string HyperparametersMarkdown(const std::vector<SettingsSection>& sections);

}  // namespace rlpos
