#pragma once
// The scenario model: everything one experiment needs. Defaults follow the paper's Tables I and
// II where it gives a value; where ours differ, the declaration says so (e.g.
// dqn_hyperparameters.h). Plain data, no ns-3: the worker turns it into ns-3 objects.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/config/object_spec.h"
#include "common/scenario/agent_settings.h"
#include "common/scenario/building_settings.h"
#include "common/scenario/env_settings.h"
#include "common/scenario/geometry.h"
#include "common/scenario/mobility_settings.h"
#include "common/scenario/traffic_settings.h"
#include "common/scenario/uav_settings.h"
#include "common/scenario/ue_settings.h"
#include "common/scenario/venue_settings.h"
#include "common/scenario/wifi_settings.h"

namespace rlpos {

// One position per UAV, in the scenario's order of `uavs`.
using Placement = std::vector<Vec3>;

// UAVs closer than this (m) overlap: two airframes cannot hold the same spot.
constexpr double kMinUavSeparation = 1.0;
// The most UAVs a scenario holds (bounded like every list from a document).
constexpr std::size_t kMaxUavs = 8;

struct Scenario {
  std::string name;
  std::string description;
  Venue venue;
  std::vector<BuildingSpec> buildings;
  std::vector<UeSpec> ues;
  std::vector<UavSpec> uavs = {UavSpec{}};  // "uav" in the JSON is one; "uavs" one or more
  bool uavs_listed = false;                 // given as "uavs": errors name /uavs/<i>
  WifiSpec wifi;
  TrafficSpec traffic;
  ObjectSpec propagation;
  SimulationSpec simulation;
  std::string log_level = "warning";  // error | warning | info | debug
  EnvSpec env;
  AgentSpec agent;

  double TotalDemandMbps() const;
  Placement InitialPlacement() const;
  // Index of the UAV named `name`, or -1.
  int UavIndex(const std::string& name) const;
  // The JSON path of UAV `i`: "/uav" or "/uavs/<i>".
  std::string UavPath(std::size_t i) const;
};

// The default propagation: our obstacle-aware model with the paper's ITU-R P.1411 LoS/NLoS pair.
ObjectSpec DefaultPropagation();

}  // namespace rlpos
