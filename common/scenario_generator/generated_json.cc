#include "common/scenario_generator/generated_json.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace rlpos {
namespace {

using Json = nlohmann::ordered_json;

// 12 -> 12, 12.5 -> 12.5 (nlohmann writes a double 12 as 12.0).
Json Number(double v) {
  if (std::floor(v) == v && std::fabs(v) < 1e15)
    return static_cast<long long>(v);
  return v;
}

Json Interval(double lo, double hi) {
  return Json::array({Number(lo), Number(hi)});
}

Json Position(const Vec3& p) {
  return Json::array({Number(p.x), Number(p.y), Number(p.z)});
}

Json Buildings(const Scenario& s) {
  Json buildings = Json::array();
  for (const auto& b : s.buildings) {
    buildings.push_back({{"name", b.name},
                         {"x", Interval(b.xmin, b.xmax)},
                         {"y", Interval(b.ymin, b.ymax)},
                         {"height", Number(b.height)},
                         {"floors", b.floors},
                         {"rooms", {b.rooms_x, b.rooms_y}},
                         {"type", b.type},
                         {"walls", b.walls}});
  }
  return buildings;
}

Json Ues(const Scenario& s) {
  Json ues = Json::array();
  for (const auto& u : s.ues) {
    ues.push_back({{"name", u.name},
                   {"position", Position(u.position)},
                   {"demand", {{"mcs", u.demand_mcs}}}});
  }
  return ues;
}

Json Uav(const UavSpec& u, bool listed) {
  Json uav = Json::object();
  if (listed)
    uav["name"] = u.name;
  uav["position"] = Position(u.initial);
  const Box& z = u.zone;
  uav["zone"] = {{"x", Interval(z.xmin, z.xmax)},
                 {"y", Interval(z.ymin, z.ymax)},
                 {"z", Interval(z.zmin, z.zmax)}};
  if (u.channel > 0)
    uav["channel"] = u.channel;
  return uav;
}

// The shipped scenarios' propagation: ITU-R P.1411 with their over-rooftop parameters where
// there are buildings, its defaults in free space (as scenario A).
Json Propagation(const Scenario& s) {
  Json nlos = {{"type", "ns3::ItuR1411NlosOverRooftopPropagationLossModel"}};
  if (!s.buildings.empty())
    nlos["attributes"] = {{"RooftopLevel", 12}, {"StreetsWidth", 20}, {"BuildingSeparation", 30}};
  return {
      {"type", "ns3::ObstacleAwarePropagationLossModel"},
      {"attributes",
       {{"LosModel", {{"type", "ns3::ItuR1411LosPropagationLossModel"}}}, {"NlosModel", nlos}}}};
}

Json Wifi(const WifiSpec& w) {
  return {{"standard", w.standard},
          {"channel", w.channel},
          {"width", w.width_mhz},
          {"guard_interval", w.guard_interval_ns},
          {"spatial_streams", w.spatial_streams},
          {"tx_power", Number(w.tx_power_dbm)},
          {"antenna_gain", Number(w.antenna_gain_dbi)},
          {"noise_floor", Number(w.noise_floor_dbm)},
          {"rate_manager", {{"type", w.rate_manager.type}}},
          {"mode", w.mode},
          {"rts_cts", w.rts_cts}};
}

}  // namespace

std::string GeneratedJsonText(const Scenario& s) {
  Json doc;
  doc["name"] = s.name;
  doc["description"] = s.description;
  doc["venue"] = {{"width", Number(s.venue.width)},
                  {"depth", Number(s.venue.depth)},
                  {"height", Number(s.venue.height)}};
  doc["buildings"] = Buildings(s);
  doc["ues"] = Ues(s);
  if (s.uavs_listed) {
    doc["uavs"] = Json::array();
    for (const auto& u : s.uavs)
      doc["uavs"].push_back(Uav(u, true));
  } else {
    doc["uav"] = Uav(s.uavs.front(), false);
  }
  doc["wifi"] = Wifi(s.wifi);
  doc["traffic"] = {{"protocol", s.traffic.protocol}, {"packet_size", s.traffic.packet_size}};
  doc["propagation"] = Propagation(s);
  doc["simulation"] = {{"duration", Number(s.simulation.duration)},
                       {"warmup", Number(s.simulation.warmup)},
                       {"seed", s.simulation.seed},
                       {"run", s.simulation.run}};
  doc["log_level"] = s.log_level;
  return doc.dump(2) + "\n";
}

}  // namespace rlpos
