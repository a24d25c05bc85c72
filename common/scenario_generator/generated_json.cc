#include "common/scenario_generator/generated_json.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

using nlohmann::json;
using Ordered = nlohmann::ordered_json;

// The shipped scenarios' key order, one list for every object of the document: no two of its
// objects order the same two keys differently (top level; venue; building; UE; UAV and its zone;
// Wi-Fi; an ns-3 object and the ITU-R models' attributes; traffic; simulation). Keys not listed
// follow in alphabetical order, so that a field ToJson gains is written, not lost.
const std::vector<std::string>& KeyOrder() {
  static const std::vector<std::string> order{"name",
                                              "description",
                                              "venue",
                                              "buildings",
                                              "ues",
                                              "uav",
                                              "uavs",
                                              "wifi",
                                              "traffic",
                                              "propagation",
                                              "simulation",
                                              "log_level",
                                              "position",
                                              "demand",
                                              "zone",
                                              "standard",
                                              "channel",
                                              "width",
                                              "depth",
                                              "x",
                                              "y",
                                              "z",
                                              "height",
                                              "floors",
                                              "rooms",
                                              "type",
                                              "attributes",
                                              "walls",
                                              "guard_interval",
                                              "spatial_streams",
                                              "tx_power",
                                              "antenna_gain",
                                              "noise_floor",
                                              "rate_manager",
                                              "mode",
                                              "rts_cts",
                                              "protocol",
                                              "packet_size",
                                              "LosModel",
                                              "NlosModel",
                                              "RooftopLevel",
                                              "StreetsWidth",
                                              "BuildingSeparation",
                                              "duration",
                                              "warmup",
                                              "seed",
                                              "run"};
  return order;
}

// `value` laid out: objects' keys in KeyOrder, whole numbers as integers (nlohmann writes a
// double 12 as 12.0), and an ns-3 object's empty "attributes" left out.
Ordered Laid(const json& value) {
  if (value.is_object()) {
    std::vector<std::string> keys;
    for (const auto& item : value.items())
      keys.push_back(item.key());
    const auto& order = KeyOrder();
    const auto rank = [&](const std::string& key) {
      return std::distance(order.begin(), std::find(order.begin(), order.end(), key));
    };
    std::stable_sort(keys.begin(), keys.end(),
                     [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
    Ordered out = Ordered::object();
    for (const auto& key : keys) {
      const json& v = value.at(key);
      if (key == "attributes" && v.is_object() && v.empty())
        continue;
      out[key] = Laid(v);
    }
    return out;
  }
  if (value.is_array()) {
    Ordered out = Ordered::array();
    for (const auto& v : value)
      out.push_back(Laid(v));
    return out;
  }
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (std::floor(v) == v && std::fabs(v) < 1e15)
      return static_cast<long long>(v);
    return v;
  }
  if (value.is_number_unsigned())
    return value.get<unsigned long long>();
  if (value.is_number_integer())
    return value.get<long long>();
  if (value.is_string())
    return value.get<std::string>();
  if (value.is_boolean())
    return value.get<bool>();
  return nullptr;
}

}  // namespace

ObjectSpec GeneratedPropagation(bool has_buildings) {
  json nlos = {{"type", "ns3::ItuR1411NlosOverRooftopPropagationLossModel"}};
  if (has_buildings)
    nlos["attributes"] = {{"RooftopLevel", 12}, {"StreetsWidth", 20}, {"BuildingSeparation", 30}};
  return {"ns3::ObstacleAwarePropagationLossModel",
          {{"LosModel", {{"type", "ns3::ItuR1411LosPropagationLossModel"}}}, {"NlosModel", nlos}}};
}

std::string GeneratedJsonText(const Scenario& s) {
  json doc = ToJson(s);
  doc.erase("env");
  doc.erase("agent");
  for (auto& ue : doc.at("ues")) {
    if (ue.at("mobility").at("model") == "static")
      ue.erase("mobility");
  }
  return Laid(doc).dump(2) + "\n";
}

}  // namespace rlpos
