#include "common/scenario/scenario_checks.h"

#include <cmath>
#include <sstream>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/scenario/building_checks.h"
#include "common/scenario/building_obstacles.h"

namespace rlpos {
namespace {

std::string Format(const Vec3& p) {
  std::ostringstream out;
  out << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return out.str();
}

void CheckInVenue(const Venue& venue, const Vec3& p, const std::string& path, const char* what) {
  if (p.x < 0 || p.x > venue.width || p.y < 0 || p.y > venue.depth || p.z < 0 ||
      p.z > venue.height) {
    std::ostringstream out;
    out << what << " at " << Format(p) << " is outside the venue [0, " << venue.width << "] x [0, "
        << venue.depth << "] x [0, " << venue.height << "]";
    throw ConfigError(path, out.str());
  }
}

std::string UavNames(const Scenario& s) {
  std::string names = " (UAVs:";
  for (const auto& uav : s.uavs)
    names += " \"" + uav.name + "\"";
  return names + ")";
}

void CheckUav(const Scenario& s, std::size_t i) {
  const UavSpec& uav = s.uavs[i];
  const std::string base = s.UavPath(i);
  const Box& z = uav.zone;
  if (z.xmin < 0 || z.xmax > s.venue.width || z.ymin < 0 || z.ymax > s.venue.depth || z.zmin < 0 ||
      z.zmax > s.venue.height) {
    throw ConfigError(base + "/zone", "the zone reaches outside the venue");
  }
  CheckInVenue(s.venue, uav.initial, base + "/position", "UAV");
  if (!z.Contains(uav.initial)) {
    std::ostringstream out;
    out << "the zone [" << z.xmin << ", " << z.xmax << "] x [" << z.ymin << ", " << z.ymax
        << "] x [" << z.zmin << ", " << z.zmax << "] excludes the initial position "
        << Format(uav.initial);
    throw ConfigError(base + "/zone", out.str());
  }
  const int inside = BuildingContaining(s, uav.initial);
  if (inside >= 0) {
    throw ConfigError(base + "/position", "UAV at " + Format(uav.initial) + " is inside building " +
                                              std::to_string(inside) + " (\"" +
                                              s.buildings[inside].name + "\")");
  }
  for (std::size_t j = 0; j < i; ++j) {
    if (s.uavs[j].name == uav.name) {
      throw ConfigError(base + "/name",
                        "UAV " + std::to_string(j) + " has the name \"" + uav.name + "\" already");
    }
    if (UavsOverlap(s.uavs[j].initial, uav.initial)) {
      std::ostringstream out;
      out << "UAV \"" << uav.name << "\" at " << Format(uav.initial) << " overlaps UAV " << j
          << " (\"" << s.uavs[j].name << "\") at " << Format(s.uavs[j].initial)
          << ": UAVs must be at least " << kMinUavSeparation << " m apart";
      throw ConfigError(base + "/position", out.str());
    }
  }
}

// A mobile UE walks on the ground between buildings: it starts off every footprint, and a
// crowd's target is a reachable spot of the venue.
void CheckUeMobility(const Scenario& s, std::size_t i) {
  const UeSpec& ue = s.ues[i];
  if (ue.mobility.model == MobilityModel::kStatic)
    return;
  const std::string path = JoinPath("/ues", i);
  const int under = FootprintContaining(s, ue.position.x, ue.position.y);
  if (under >= 0) {
    throw ConfigError(JoinPath(path, "position"),
                      "UE \"" + ue.name + "\" moves (" + MobilityModelName(ue.mobility.model) +
                          ") but starts on building " + std::to_string(under) + " (\"" +
                          s.buildings[under].name + "\"): a mobile UE starts on the ground");
  }
  if (ue.mobility.model != MobilityModel::kCrowd)
    return;
  const Vec3& t = ue.mobility.crowd.target;
  const std::string target_path = JoinPath(JoinPath(path, "mobility"), "target");
  if (t.x < 0 || t.x > s.venue.width || t.y < 0 || t.y > s.venue.depth) {
    std::ostringstream out;
    out << "crowd target (" << t.x << ", " << t.y << ") is outside the venue [0, " << s.venue.width
        << "] x [0, " << s.venue.depth << "]";
    throw ConfigError(target_path, out.str());
  }
  const int inside = FootprintContaining(s, t.x, t.y);
  if (inside >= 0) {
    std::ostringstream out;
    out << "crowd target (" << t.x << ", " << t.y << ") is inside building " << inside << " (\""
        << s.buildings[inside].name << "\")";
    throw ConfigError(target_path, out.str());
  }
}

}  // namespace

int FootprintContaining(const Scenario& scenario, double x, double y) {
  for (std::size_t i = 0; i < scenario.buildings.size(); ++i) {
    if (GroundShapeHolds(scenario.buildings[i], x, y))
      return static_cast<int>(i);
  }
  return -1;
}

bool UavsOverlap(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z) < kMinUavSeparation;
}

bool OverlapsAnother(const Placement& placement, std::size_t uav, const Vec3& p) {
  for (std::size_t v = 0; v < placement.size(); ++v) {
    if (v != uav && UavsOverlap(placement[v], p))
      return true;
  }
  return false;
}

int BuildingContaining(const Scenario& scenario, const Vec3& p) {
  for (std::size_t i = 0; i < scenario.buildings.size(); ++i) {
    if (BuildingHolds(scenario.buildings[i], p))
      return static_cast<int>(i);
  }
  return -1;
}

void CheckScenarioGeometry(const Scenario& s) {
  CheckBuildings(s);
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    const std::string path = JoinPath(JoinPath("/ues", i), "position");
    CheckInVenue(s.venue, s.ues[i].position, path, "UE");
    const int inside = BuildingContaining(s, s.ues[i].position);
    if (inside >= 0) {
      throw ConfigError(path, "UE at " + Format(s.ues[i].position) + " is inside building " +
                                  std::to_string(inside) + " (\"" + s.buildings[inside].name +
                                  "\")");
    }
  }
  for (std::size_t i = 0; i < s.ues.size(); ++i)
    CheckUeMobility(s, i);
  for (std::size_t i = 0; i < s.uavs.size(); ++i)
    CheckUav(s, i);
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    const std::string& name = s.ues[i].uav;
    if (!name.empty() && s.UavIndex(name) < 0) {
      throw ConfigError(JoinPath(JoinPath("/ues", i), "uav"),
                        "no UAV is named \"" + name + "\"" + UavNames(s));
    }
  }
}

}  // namespace rlpos
