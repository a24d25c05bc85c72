#pragma once
// Every algorithm's declared hyperparameters as text: the docs table that
// `rlpos-sim describe hyperparameters` prints and docs/hyperparameters.md holds.
#include <string>
#include <vector>

#include "common/config/object_reader.h"

namespace rlpos {

// One row of a docs table: everything as text.
struct HyperparameterRow {
  std::string key;            // dotted, as --set takes it: "agent.ppo.clip"
  std::string type;           // real | integer | boolean | real or null
  std::string default_value;  // as JSON; in the shared section, the first algorithm's it covers
  // The docs' default cell: default_value, or where the algorithms the section covers have
  // different defaults, each one's: "dqn 1000, ppo 4000, sac 2500".
  std::string default_text;
  std::string range;  // "(0, 1]", "[1, 1000]", ">= 0"; empty for booleans
  std::string doc;
  NumberRange bounds;  // the range as declared, for tests that probe it
};

struct HyperparameterSection {
  std::string section;  // "agent" (every algorithm's) or the algorithm
  std::string path;     // its JSON object: "/agent", "/agent/ppo", ...
  std::string summary;
  std::vector<HyperparameterRow> rows;
};

// The shared section ("agent", with every algorithm's defaults) first, then each algorithm's in
// AllAlgorithms() order.
std::vector<HyperparameterSection> AllHyperparameterSections();

// The sections that apply to `algorithm`: the shared one with that algorithm's defaults, and its
// own. Empty: all of them.
std::vector<HyperparameterSection> HyperparameterSectionsFor(const std::string& algorithm);

// A markdown page: one heading, summary and table per section.
std::string HyperparametersMarkdown(const std::vector<HyperparameterSection>& sections);

}  // namespace rlpos
