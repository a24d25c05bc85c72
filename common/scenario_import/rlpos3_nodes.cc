// ns3Sim.defaultValues' nodes: Buildings, UENodes (position, data rate -> MCS demand) and
// UAVNodes, moved into the venue's frame and checked there with the source's paths.
#include <algorithm>
#include <cstdio>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario_import/data_rate.h"
#include "common/scenario_import/rlpos3_parts.h"

namespace rlpos {
namespace {

using nlohmann::json;

// The source's array at `key` (absent: empty when `required` is false).
const json& ArrayAt(Rlpos3Object& defaults, const std::string& key, bool required) {
  static const json empty = json::array();
  const json* v = required ? &defaults.Required(key, "an array") : defaults.Optional(key);
  if (!v)
    return empty;
  if (!v->is_array())
    throw ConfigError(defaults.PathOf(key), "expected an array, got " + TypeName(*v));
  return *v;
}

Vec3 ReadPositionVector(Rlpos3Object& node) {
  const json& v = node.Required("positionVector", "[x, y, z]");
  const std::string path = node.PathOf("positionVector");
  if (!v.is_array() || v.size() != 3)
    throw ConfigError(path, "expected [x, y, z], got " + (v.is_array() ? v.dump() : TypeName(v)));
  return {Rlpos3Number(v[0], JoinPath(path, 0)), Rlpos3Number(v[1], JoinPath(path, 1)),
          Rlpos3Number(v[2], JoinPath(path, 2))};
}

// A node's position must lie over the venue (RLpos-3's venueSize): ours has no ground outside.
void CheckOverVenue(const Rlpos3Frame& frame, const Vec3& p, const std::string& path,
                    const char* what) {
  if (!frame.HoldsXy(p.x, p.y)) {
    throw ConfigError(path, std::string(what) + " at " + FormatPoint(p) +
                                " lies outside Gym.venueSize [" + FormatNumber(frame.xmin) + ", " +
                                FormatNumber(frame.xmax) + "] x [" + FormatNumber(frame.ymin) +
                                ", " + FormatNumber(frame.ymax) + "]");
  }
  if (p.z < 0)
    throw ConfigError(JoinPath(path, 2), std::string(what) + " below the ground (z < 0)");
}

// [xmin, xmax, ymin, ymax, zmin, zmax, floors, rooms x, rooms y]. RLpos-3's own reader takes
// rooms x from the fifth entry (zmin); the format's description, followed here, has it eighth.
BuildingSpec ReadBuilding(Rlpos3Object& node, const Rlpos3Frame& frame, std::size_t index) {
  const json& v = node.Required("BuildingPosition",
                                "[xmin, xmax, ymin, ymax, zmin, zmax, floors, rooms x, rooms y]");
  const std::string path = node.PathOf("BuildingPosition");
  if (!v.is_array() || v.size() != 9) {
    throw ConfigError(path,
                      "expected [xmin, xmax, ymin, ymax, zmin, zmax, floors, rooms x, rooms "
                      "y] (9 numbers), got " +
                          (v.is_array() ? std::to_string(v.size()) + " entries" : TypeName(v)));
  }
  double c[6];
  for (std::size_t i = 0; i < 6; ++i)
    c[i] = Rlpos3Number(v[i], JoinPath(path, i));
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t a = 0; a < 3; ++a) {
    if (c[2 * a] >= c[2 * a + 1]) {
      throw ConfigError(path, std::string(axes[a]) + "min (" + FormatNumber(c[2 * a]) +
                                  ") must be below " + axes[a] + "max (" +
                                  FormatNumber(c[2 * a + 1]) + ")");
    }
  }
  if (!frame.HoldsXy(c[0], c[2]) || !frame.HoldsXy(c[1], c[3])) {
    throw ConfigError(path, "the building's footprint reaches outside Gym.venueSize");
  }
  if (c[5] <= 0)
    throw ConfigError(JoinPath(path, 5), "the building's top must be above the ground");
  BuildingSpec b;
  b.name = "building" + std::to_string(index);
  const Vec3 low = frame.ToVenue({c[0], c[2], 0.0});
  const Vec3 high = frame.ToVenue({c[1], c[3], 0.0});
  b.xmin = low.x;
  b.xmax = high.x;
  b.ymin = low.y;
  b.ymax = high.y;
  b.height = c[5];
  b.floors = static_cast<int>(Rlpos3Integer(v[6], JoinPath(path, 6), 1, 200));
  b.rooms_x = static_cast<int>(Rlpos3Integer(v[7], JoinPath(path, 7), 1, 255));
  b.rooms_y = static_cast<int>(Rlpos3Integer(v[8], JoinPath(path, 8), 1, 255));
  if (c[4] != 0.0) {
    node.Warn("BuildingPosition", "zmin " + FormatNumber(c[4]) +
                                      " not carried: buildings here stand on the ground (z from "
                                      "0 to zmax " +
                                      FormatNumber(c[5]) + ")");
  }
  return b;
}

// A PHY rate for people: 5 significant digits ("433.33", "58.5").
std::string RateText(double mbps) {
  char text[32];
  std::snprintf(text, sizeof text, "%.5g", mbps);
  return text;
}

// The UE's DataRate as the MCS whose rate is the smallest at or above it.
void ReadDemand(Rlpos3Object& node, const PhyProfile& phy, UeSpec& ue) {
  const json& v = node.Required("DataRate", "an ns-3 DataRate such as \"58.5Mbps\"");
  if (!v.is_string()) {
    throw ConfigError(node.PathOf("DataRate"),
                      "expected a string such as \"58.5Mbps\", got " + TypeName(v));
  }
  const double mbps = DataRateMbps(v.get<std::string>(), node.PathOf("DataRate"));
  const int mcs = RequiredMcs(phy, mbps);
  const std::string phy_text = phy.standard + ", " + std::to_string(phy.width_mhz) + " MHz, GI " +
                               std::to_string(phy.guard_interval_ns) + " ns";
  if (mcs < 0) {
    const int top = MaxMcs(phy.standard);
    ue.demand_mbps = mbps;
    node.Warn("DataRate", FormatNumber(mbps) + " Mbit/s is above the top MCS " +
                              std::to_string(top) + " (" + RateText(McsDataRateMbps(phy, top)) +
                              " Mbit/s, " + phy_text + "): kept in Mbit/s, a demand no MCS meets");
    return;
  }
  ue.demand_mcs = mcs;
  ue.demand_mbps = McsDataRateMbps(phy, mcs);
  if (ue.demand_mbps > mbps * (1.0 + 1e-9)) {
    node.Warn("DataRate", FormatNumber(mbps) + " Mbit/s rounded up to MCS " + std::to_string(mcs) +
                              " (" + RateText(ue.demand_mbps) + " Mbit/s, " + phy_text +
                              "): the UE offers that rate");
  }
}

UeSpec ReadUe(Rlpos3Object& node, const Rlpos3Frame& frame, const Scenario& s, std::size_t index) {
  const Vec3 source = ReadPositionVector(node);
  const std::string path = node.PathOf("positionVector");
  CheckOverVenue(frame, source, path, "UE");
  UeSpec ue;
  ue.name = "ue" + std::to_string(index);
  ue.position = frame.ToVenue(source);
  const int inside = BuildingContaining(s, ue.position);
  if (inside >= 0) {
    throw ConfigError(path, "UE at " + FormatPoint(source) +
                                " is inside the building /ns3Sim/defaultValues/Buildings/" +
                                std::to_string(inside));
  }
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  ReadDemand(node, phy, ue);
  node.NotCarried("SNR",
                  "RLpos-3 keeps its UAV where this UE's free-space SNR reaches this value; here "
                  "the SNR a UE needs follows from its demand's MCS");
  node.Finish();
  return ue;
}

UavSpec ReadUav(Rlpos3Object& node, const Rlpos3Frame& frame, const Scenario& s, bool listed,
                std::size_t index) {
  const Vec3 source = ReadPositionVector(node);
  const std::string path = node.PathOf("positionVector");
  CheckOverVenue(frame, source, path, "UAV");
  if (source.z < frame.zmin || source.z > frame.zmax) {
    throw ConfigError(JoinPath(path, 2), "UAV altitude " + FormatNumber(source.z) +
                                             " is outside Gym.venueSize's Zmin..Zmax [" +
                                             FormatNumber(frame.zmin) + ", " +
                                             FormatNumber(frame.zmax) + "]");
  }
  UavSpec uav;
  uav.name = listed ? "uav" + std::to_string(index + 1) : "uav";
  uav.initial = frame.ToVenue(source);
  uav.zone = {0, s.venue.width, 0, s.venue.depth, std::max(0.0, frame.zmin), frame.zmax};
  node.Finish();
  return uav;
}

}  // namespace

std::string FormatPoint(const Vec3& p) {
  return "(" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ", " + FormatNumber(p.z) + ")";
}

void ReadNodes(Rlpos3Object& defaults, const Rlpos3Frame& frame, Scenario& s) {
  const json& buildings = ArrayAt(defaults, "Buildings", false);
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    Rlpos3Object node(buildings[i], JoinPath(defaults.PathOf("Buildings"), i), defaults.warnings());
    s.buildings.push_back(ReadBuilding(node, frame, i));
    node.Finish();
  }
  const json& ues = ArrayAt(defaults, "UENodes", true);
  if (ues.empty())
    throw ConfigError(defaults.PathOf("UENodes"), "expected at least one UE");
  for (std::size_t i = 0; i < ues.size(); ++i) {
    Rlpos3Object node(ues[i], JoinPath(defaults.PathOf("UENodes"), i), defaults.warnings());
    s.ues.push_back(ReadUe(node, frame, s, i));
  }
  const json& uavs = ArrayAt(defaults, "UAVNodes", true);
  if (uavs.empty() || uavs.size() > kMaxUavs) {
    throw ConfigError(defaults.PathOf("UAVNodes"), "expected 1 to " + std::to_string(kMaxUavs) +
                                                       " UAVs, got " + std::to_string(uavs.size()));
  }
  s.uavs.clear();
  s.uavs_listed = uavs.size() > 1;
  for (std::size_t i = 0; i < uavs.size(); ++i) {
    Rlpos3Object node(uavs[i], JoinPath(defaults.PathOf("UAVNodes"), i), defaults.warnings());
    s.uavs.push_back(ReadUav(node, frame, s, s.uavs_listed, i));
  }
  if (s.uavs_listed) {
    defaults.Warn("UAVNodes", "RLpos-3 positions and moves only the first UAV; here each of the " +
                                  std::to_string(uavs.size()) +
                                  " is an access point on a channel of its own (uavs[])");
  }
}

}  // namespace rlpos
