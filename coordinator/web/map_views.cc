#include "coordinator/web/map_views.h"

#include <map>

#include "common/campaign/campaign_spec.h"
#include "common/config/config_error.h"
#include "common/scenario/geometry.h"
#include "common/scenario/scenario_parser.h"
#include "coordinator/reporting/run_groups.h"
#include "coordinator/web/track_frames.h"

namespace rlpos::web {
namespace {

using nlohmann::json;

json PointJson(const Vec3& p) {
  return {{"x", p.x}, {"y", p.y}, {"z", p.z}};
}

json GeometryJson(const Scenario& s) {
  json buildings = json::array(), ues = json::array(), uavs = json::array();
  for (const auto& b : s.buildings) {
    json building = {{"name", b.name}, {"xmin", b.xmin},     {"xmax", b.xmax},    {"ymin", b.ymin},
                     {"ymax", b.ymax}, {"height", b.height}, {"floors", b.floors}};
    // A footprint building's exact shape; its xmin..ymax are then its bounding box. A box
    // keeps the keys it always had.
    if (b.HasFootprint()) {
      building["footprint"] = RingJson(b.footprint.outer);
      building["holes"] = RingsJson(b.footprint.holes);
      building["min_height"] = b.min_height;
    }
    buildings.push_back(std::move(building));
  }
  for (const auto& u : s.ues) {
    json ue = PointJson(u.position);
    ue["name"] = u.name;
    ue["demand_mbps"] = u.demand_mbps;
    ue["uav"] = u.uav;
    ues.push_back(ue);
  }
  for (const auto& u : s.uavs) {
    uavs.push_back({{"name", u.name},
                    {"initial", PointJson(u.initial)},
                    {"zone",
                     {{"xmin", u.zone.xmin},
                      {"xmax", u.zone.xmax},
                      {"ymin", u.zone.ymin},
                      {"ymax", u.zone.ymax},
                      {"zmin", u.zone.zmin},
                      {"zmax", u.zone.zmax}}}});
  }
  return {
      {"name", s.name},
      {"description", s.description},
      {"venue", {{"width", s.venue.width}, {"depth", s.venue.depth}, {"height", s.venue.height}}},
      {"buildings", buildings},
      {"ues", ues},
      {"uavs", uavs}};
}

// Per scenario, per label (report order): the UAVs' positions in the label's first run.
std::map<std::string, json> PlacementsByScenario(const std::vector<UavMetricRow>& rows) {
  std::map<std::string, std::map<std::string, json>> by_label;
  for (const auto& row : rows) {
    json& placement = by_label[row.scenario][row.label];
    if (placement.is_null())
      placement = {{"positioner", row.label}, {"rng_run", row.rng_run}, {"uavs", json::array()}};
    if (placement["rng_run"] != row.rng_run)
      continue;
    placement["uavs"].push_back({{"name", row.name}, {"x", row.x}, {"y", row.y}, {"z", row.z}});
  }
  std::map<std::string, json> out;
  for (auto& [scenario, labels] : by_label) {
    std::vector<std::string> order;
    for (const auto& entry : labels)
      order.push_back(entry.first);
    std::sort(order.begin(), order.end(), ReportLabelLess);
    json list = json::array();
    for (const auto& label : order)
      list.push_back(std::move(labels[label]));
    out[scenario] = std::move(list);
  }
  return out;
}

}  // namespace

std::optional<json> ScenarioMapsJson(ResultsReader& store, const std::string& campaign_id) {
  const auto part = store.CampaignSpecPart(campaign_id, "scenarios");
  if (!part)
    return std::nullopt;
  auto placements = PlacementsByScenario(store.UavMetrics(campaign_id));
  const auto intervals = store.TrackIntervals(campaign_id, TrackRunsRead::kFirstRunOnly);
  const auto tracks = TracksByScenario(intervals, store.TrackRuns(campaign_id));
  json scenarios = json::array();
  for (const auto& entry : part->value("scenarios", json::array())) {
    const std::string file = entry.value("file", "");
    try {
      const json document = StatedScenarioDocument(entry);
      json map = GeometryJson(ParseScenario(document));
      map["file"] = file;
      const std::string name = map["name"];
      const auto it = placements.find(name);
      map["placements"] = it == placements.end() ? json::array() : it->second;
      const auto track = tracks.find(name);
      if (track != tracks.end())
        map["tracks"] = TrackFramesJson(document, track->second);
      scenarios.push_back(std::move(map));
    } catch (const ConfigError& e) {
      scenarios.push_back({{"file", file}, {"error", e.describe()}});
    } catch (const json::exception& e) {
      scenarios.push_back({{"file", file}, {"error", e.what()}});
    }
  }
  return json{{"scenarios", scenarios}};
}

}  // namespace rlpos::web
