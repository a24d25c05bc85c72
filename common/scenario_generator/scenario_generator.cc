#include "common/scenario_generator/scenario_generator.h"

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/building_layouts.h"
#include "common/scenario_generator/generated_json.h"
#include "common/scenario_generator/generated_mobility.h"
#include "common/scenario_generator/hidden_ues.h"
#include "common/scenario_generator/portable_random.h"
#include "common/scenario_generator/uav_baseline.h"
#include "common/scenario_generator/ue_placement.h"

namespace rlpos {
namespace {

std::string Plural(int n, const std::string& one) {
  return std::to_string(n) + " " + one + (n == 1 ? "" : "s");
}

std::string ScenarioName(const GeneratorOptions& o) {
  return "gen-" + StyleName(*o.style) + "-" + std::to_string(o.uavs) + "uav-s" +
         std::to_string(o.seed);
}

// One draw: layout, UEs, baseline; nullopt when a placement did not fit.
std::optional<Scenario> DrawScenario(const GeneratorOptions& o, PortableRandom& random) {
  const auto layout = DrawLayout(*o.style, random);
  if (!layout)
    return std::nullopt;
  Scenario s;
  s.wifi.width_mhz = GeneratedChannelWidthMhz(o.uavs);
  s.wifi.channel = GeneratedUavChannels(o.uavs).front();
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  const auto ues = DrawUes(*layout, *o.ues, o.uavs, phy, random);
  if (!ues)
    return std::nullopt;
  s.name = ScenarioName(o);
  s.venue = layout->venue;
  s.buildings = layout->buildings;
  s.ues = ues->ues;
  s.uavs = BaselineUavs(s.venue, s.buildings, o.uavs);
  s.uavs_listed = o.uavs > 1;
  s.propagation = GeneratedPropagation(!s.buildings.empty());
  s.description = "Generated " + StyleName(*o.style) + " scenario: " + layout->summary + "; " +
                  ues->summary + "; " + Plural(o.uavs, "UAV") + ", baseline " +
                  BaselineSummary(s.venue, s.buildings) + ". Reproduce: " + GenerateCommandLine(o) +
                  ".";
  return s;
}

}  // namespace

std::string GenerateCommandLine(const GeneratorOptions& o) {
  return "rlpos-sim generate --seed " + std::to_string(o.seed) + " --style " +
         StyleName(ResolvedStyle(o)) + " --uavs " + std::to_string(o.uavs) +
         (o.ues ? " --ues " + std::to_string(*o.ues) : "") +
         (o.mobility ? " --mobility " + MobilityModelName(*o.mobility) : "");
}

GeneratedScenario GenerateScenario(const GeneratorOptions& options, int max_attempts) {
  GeneratedScenario result;
  result.options = ResolvedOptions(options);
  const GeneratorOptions& o = result.options;
  const bool has_buildings = *result.options.style != GeneratorStyle::kOpen;
  PortableRandom random(options.seed);
  for (int attempt = 1; attempt <= max_attempts; ++attempt) {
    auto drawn = DrawScenario(result.options, random);
    if (!drawn)
      continue;
    const int hidden = UesHiddenFromAll(*drawn, drawn->InitialPlacement());
    if (has_buildings && hidden == 0)
      continue;  // the baseline would see every UE: nothing for a positioner to find
    std::string moves;
    if (o.mobility && !DrawMobility(*drawn, *o.mobility, o.seed + attempt, moves))
      continue;  // no crowd target with room, or a UE the buildings leave no way to walk
    if (has_buildings) {
      drawn->description += " At the baseline " + std::to_string(hidden) + " of " +
                            std::to_string(drawn->ues.size()) + " UEs are " +
                            (o.uavs == 1 ? "NLoS." : "hidden from every UAV.");
    }
    if (!moves.empty())
      drawn->description += " " + moves + ".";
    std::string text = GeneratedJsonText(*drawn);
    Scenario parsed;
    try {
      parsed = ParseScenario(ParseJsonText(text));
    } catch (const ConfigError&) {
      continue;  // a draw the checks reject is drawn again like one that did not fit
    }
    result.json_text = std::move(text);
    result.scenario = std::move(parsed);
    result.attempts = attempt;
    result.hidden_at_baseline = hidden;
    return result;
  }
  throw GeneratorError(
      "seed " + std::to_string(options.seed) + " (" + StyleName(*result.options.style) + ", " +
      Plural(result.options.uavs, "UAV") + ", " + Plural(*result.options.ues, "UE") +
      "): no valid scenario in " + std::to_string(max_attempts) + " draws");
}

}  // namespace rlpos
