#pragma once
// A deterministic k-means of the UEs' ground positions (x, y), weighted by demand.
// Initialisation without randomness: the first centre is the UE nearest the weighted centroid,
// each next one the UE farthest from the centres chosen (ties: the lower index). Lloyd's
// iterations until no UE changes cluster.
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

struct Cluster {
  double x = 0.0, y = 0.0;  // demand-weighted centroid
  std::vector<int> ues;     // indices into scenario.ues
};

// `k` clusters (k <= the number of UEs; fewer UEs than k leaves clusters of one UE repeated).
std::vector<Cluster> KMeansUes(const Scenario& scenario, std::size_t k);

}  // namespace rlpos
