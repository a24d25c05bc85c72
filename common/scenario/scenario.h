#pragma once
// The scenario model: everything one experiment needs. Defaults follow the paper's Tables I and
// II where it gives a value; where ours differ, the declaration says so (e.g.
// dqn_hyperparameters.h). Plain data, no ns-3: the worker turns it into ns-3 objects.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/agent_hyperparameters.h"
#include "common/scenario/dqn_hyperparameters.h"
#include "common/scenario/ppo_hyperparameters.h"
#include "common/scenario/sac_hyperparameters.h"

namespace rlpos {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// An axis-aligned box [xmin,xmax] x [ymin,ymax] x [zmin,zmax].
struct Box {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
  bool Contains(const Vec3& p) const {
    return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax && p.z >= zmin && p.z <= zmax;
  }
};

// An ns-3 object chosen the ns-3 way: a TypeId name and attribute values. An attribute value is a
// JSON scalar (converted to the attribute's string form) or a nested {"type", "attributes"} spec
// for pointer attributes.
struct ObjectSpec {
  std::string type;
  nlohmann::json attributes = nlohmann::json::object();
};

struct Venue {
  double width = 100.0;  // x extent, m
  double depth = 100.0;  // y extent, m
  double height = 60.0;  // height limit for anything in the venue, m
};

struct BuildingSpec {
  std::string name;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  double height = 10.0;
  int floors = 1;
  int rooms_x = 1;
  int rooms_y = 1;
  std::string type = "residential";             // residential | office | commercial
  std::string walls = "concrete_with_windows";  // ns-3 Building::ExtWallsType
  Box Footprint3d() const { return {xmin, xmax, ymin, ymax, 0.0, height}; }
};

// How a UE moves (docs/scenarios.md, "UE mobility"). The trajectory itself is computed from
// this, the scenario's geometry and the RngRun by common/mobility, the same at every fidelity.
enum class MobilityModel { kStatic, kRandomWalk, kRandomWaypoint, kGaussMarkov, kCrowd };

// A straight leg of `change_interval` s at `speed` in a direction drawn anew each leg.
struct RandomWalkSpec {
  double speed = 1.0;            // m/s
  double change_interval = 2.0;  // s per leg
};

// Walk to a point drawn uniformly in the venue at a speed drawn from [speed_min, speed_max],
// pause, draw the next.
struct RandomWaypointSpec {
  double speed_min = 0.5;  // m/s
  double speed_max = 1.5;  // m/s
  double pause = 2.0;      // s at each waypoint
};

// Gauss-Markov: every `step` s, speed and direction are alpha x their last value plus
// (1 - alpha) x their mean plus sqrt(1 - alpha^2) x Gaussian noise (alpha 0: a random walk of
// independent draws, 1: a straight line).
struct GaussMarkovSpec {
  double speed = 1.0;  // mean speed, m/s
  double alpha = 0.75;
  double step = 1.0;  // s between updates
};

// A crowd: from `start` s, walk at `speed` to a spot within `radius` of `target`, stay there
// `dwell` s, then walk away to a spot drawn in the venue. UEs given the same crowd settings are
// one group.
struct CrowdSpec {
  Vec3 target;           // z ignored: the UE keeps its height
  double radius = 10.0;  // m
  double speed = 1.2;    // m/s
  double start = 0.0;    // s
  double dwell = 30.0;   // s
};

struct MobilitySpec {
  MobilityModel model = MobilityModel::kStatic;
  RandomWalkSpec random_walk;
  RandomWaypointSpec random_waypoint;
  GaussMarkovSpec gauss_markov;
  CrowdSpec crowd;
};

// "static", "random_walk", "random_waypoint", "gauss_markov", "crowd".
std::string MobilityModelName(MobilityModel model);
const std::vector<std::string>& MobilityModelNames();
// The model of `name`, or nullopt.
std::optional<MobilityModel> ParseMobilityModel(const std::string& name);

// One position per UAV, in the scenario's order of `uavs`.
using Placement = std::vector<Vec3>;

struct UeSpec {
  std::string name;
  Vec3 position;
  std::string uav;  // fixed association: the serving UAV's name; empty: the UAV of best SNR
  double demand_mbps = 0.0;  // resolved from "mbps" or "mcs"
  int demand_mcs = -1;       // the MCS the demand was given as, or -1 when given in Mbit/s
  MobilitySpec mobility;
};

// One UAV: an access point (or ad hoc peer) with the UEs' sink, on its own Wi-Fi channel.
struct UavSpec {
  std::string name = "uav";
  Vec3 initial{50.0, 50.0, 10.0};
  Box zone{0, 100, 0, 100, 1, 60};
  // 0: wifi.channel for the first UAV, then the next channels of wifi.width in ns-3's channel
  // table (distinct). UAVs given the same channel share the air: their BSSs contend and
  // interfere.
  int channel = 0;
  // How fast it may fly (m/s) when a positioner re-decides during a run (rlpos-sim track):
  // horizontally and vertically, each within (0, kMaxUavSpeed].
  double max_speed = 10.0;
  double max_climb = 3.0;
};

// The bound of uav.max_speed and uav.max_climb (m/s): faster than any multirotor flies.
constexpr double kMaxUavSpeed = 100.0;

// UAVs closer than this (m) overlap: two airframes cannot hold the same spot.
constexpr double kMinUavSeparation = 1.0;
// The most UAVs a scenario holds (bounded like every list from a document).
constexpr std::size_t kMaxUavs = 8;

struct WifiSpec {
  std::string standard = "802.11ac";  // 802.11n | 802.11ac | 802.11ax
  int channel = 50;
  int width_mhz = 160;
  int guard_interval_ns = 800;
  int spatial_streams = 1;
  double tx_power_dbm = 20.0;
  double antenna_gain_dbi = 0.0;
  double noise_floor_dbm = -85.0;
  ObjectSpec rate_manager{"ns3::IdealWifiManager", nlohmann::json::object()};
  std::string mode = "ap_sta";  // adhoc | ap_sta
  bool rts_cts = false;
};

struct TrafficSpec {
  std::string protocol = "udp_cbr";  // udp_cbr | tcp_bulk
  int packet_size = 1400;            // application bytes per packet
};

struct SimulationSpec {
  double duration = 10.0;  // s of simulated time, traffic included
  double warmup = 1.0;     // s excluded from metrics (association, ARP)
  std::uint32_t seed = 1;  // RngSeedManager seed
  std::uint64_t run = 1;   // RngRun
};

// The gym: how the agent moves the UAV, what it sees, what it is rewarded for.
struct RewardSpec {
  std::string name = "paper";  // registry name (worker/gym/reward.h)
  double w1 = 0.8;             // weight of nLoS / N
  double w2 = 0.2;             // weight of throughput / total demand
  double w3 = 0.0;             // weight of demands met / N (demand_aware)
};

struct EnvSpec {
  std::string fidelity = "packet";  // packet (full ns-3) | analytic (no packets)
  double step = 5.0;                // m per move
  // Moves: up/down = +-z, forward/backward = +-y, right/left = +-x, stay.
  std::vector<std::string> actions = {"up", "down", "forward", "backward", "left", "right", "stay"};
  // x, y, z, n_los, throughput, demands_met, snr (one per UE); and the same in every scenario
  // (worker/gym/general_observation.h): zone, ues, heights, others
  std::vector<std::string> observations = {"x", "y", "z", "n_los"};
  int observed_ues = 16;  // UE slots of the "ues" observation, nearest first
  int height_map = 9;     // cells per side of the "heights" observation (odd), env.step each
  int coverage_map = 8;   // cells per side of the "coverage" observation, over the UAV's zone
  // Moves (x and y) around the map's best cell the "coverage" pointer also searches, at every
  // altitude: it points at the best column found (0: the best cell's own column).
  int coverage_refine = 0;
  double decision_interval = 0.1;   // s between actions
  double episode_duration = 100.0;  // s per episode
  // Moves into a wall of the zone or a building are masked out (not only clamped): otherwise
  // a policy can press "up" at the ceiling for the whole episode (README, RL).
  bool action_mask = true;
  // "discrete": the moves above. "continuous": a displacement (dx, dy, dz) in metres, each
  // component within [-step, step] (Gymnasium's Box), clamped to the zone like a move.
  std::string action_space = "discrete";
  // Several UAVs take turns: each moves this many consecutive steps before the next one's turn.
  int turn_steps = 1;
  RewardSpec reward;
};

// The agent: its algorithm, network and hyperparameters. Each algorithm declares its own in
// one file (scenario/dqn_hyperparameters.h, ppo_..., sac_...) and reads only its own member;
// the keys every algorithm shares (agent_hyperparameters.h) are the base, as their keys sit in
// "agent" itself. DQN's keys sit in "agent" too (DQN came first), but in C++ they are
// agent.dqn: a PPO or SAC that named DQN's gamma or replay would not compile.
// agent.ue_encoder's bounds: a few small layers, applied to each UE slot.
constexpr int kMaxUeEncoderLayers = 4;
constexpr int kMaxUeEncoderWidth = 512;

struct AgentSpec : AgentCommonSpec {
  std::string algorithm = "dqn";  // dqn | ppo | sac (sac needs env.action_space "continuous")
  std::vector<int> hidden = {32, 32};
  // PPO only, with "ues" in env.observations: the widths of a network shared by the UE slots
  // (ReLU after each), whose mean over the present slots stands in for the slots in the input of
  // the hidden layers, so the policy takes the UEs as a set. Empty: none, the slots go in as they
  // are.
  std::vector<int> ue_encoder;
  DqnSpec dqn;
  PpoSpec ppo;
  SacSpec sac;
};

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
