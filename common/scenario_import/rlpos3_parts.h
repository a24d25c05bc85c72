#pragma once
// The steps of the RLpos-3 import, one per part of the source (internal to this library).
#include "common/scenario/scenario.h"
#include "common/scenario_import/rlpos3_object.h"

namespace rlpos {

// RLpos-3's Gym.venueSize: the box the UAV may fly in, in the source's coordinates (x and y
// may be negative). Our venue starts at (0, 0): x and y shift by -Xmin and -Ymin. z does not
// shift: it is the height above the ground in both (RLpos-3's buildings stand on z = 0, its UEs
// at z = 1, and Zmin is the UAV's lowest altitude, not the ground).
struct Rlpos3Frame {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
  Vec3 ToVenue(const Vec3& p) const { return {p.x - xmin, p.y - ymin, p.z}; }
  bool HoldsXy(double x, double y) const {
    return x >= xmin && x <= xmax && y >= ymin && y <= ymax;
  }
};

// Gym: venueSize (venue, zone, move size), decisionInterval and what is not carried.
Rlpos3Frame ReadGym(Rlpos3Object& gym, Scenario& s);
// ns3Sim.configSim: Wi-Fi standard, rate manager, traffic, UE mobility, the UAV's moves.
void ReadConfigSim(Rlpos3Object& config_sim, Scenario& s);
// ns3Sim.defaultValues' radio and run settings (not the nodes).
void ReadRadio(Rlpos3Object& defaults, Scenario& s);
// ns3Sim.defaultValues' Buildings, UENodes and UAVNodes, into the venue's frame.
void ReadNodes(Rlpos3Object& defaults, const Rlpos3Frame& frame, Scenario& s);
// Agent: the DQN's hyperparameters.
void ReadAgent(Rlpos3Object& agent, Scenario& s);

// "(x, y, z)" with the shortest exact numbers.
std::string FormatPoint(const Vec3& p);

}  // namespace rlpos
