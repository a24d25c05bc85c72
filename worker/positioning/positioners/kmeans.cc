#include "worker/positioning/positioners/kmeans.h"

#include <cmath>
#include <limits>

namespace rlpos {
namespace {

double Distance2(double x, double y, const Vec3& p) {
  return (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y);
}

}  // namespace

std::vector<Cluster> KMeansUes(const Scenario& s, std::size_t k) {
  const auto& ues = s.ues;
  std::vector<Cluster> clusters;
  if (k == 0 || ues.empty())
    return clusters;
  double wx = 0, wy = 0, w = 0;
  for (const auto& ue : ues) {
    wx += ue.demand_mbps * ue.position.x;
    wy += ue.demand_mbps * ue.position.y;
    w += ue.demand_mbps;
  }
  std::size_t first = 0;
  for (std::size_t i = 1; i < ues.size(); ++i) {
    if (Distance2(wx / w, wy / w, ues[i].position) < Distance2(wx / w, wy / w, ues[first].position))
      first = i;
  }
  clusters.push_back({ues[first].position.x, ues[first].position.y, {}});
  while (clusters.size() < k) {
    std::size_t farthest = 0;
    double best = -1.0;
    for (std::size_t i = 0; i < ues.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& c : clusters)
        nearest = std::min(nearest, Distance2(c.x, c.y, ues[i].position));
      if (nearest > best) {
        best = nearest;
        farthest = i;
      }
    }
    clusters.push_back({ues[farthest].position.x, ues[farthest].position.y, {}});
  }
  std::vector<int> assignment(ues.size(), -1);
  for (int iteration = 0; iteration < 1000; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < ues.size(); ++i) {
      int nearest = 0;
      for (std::size_t c = 1; c < clusters.size(); ++c) {
        if (Distance2(clusters[c].x, clusters[c].y, ues[i].position) <
            Distance2(clusters[nearest].x, clusters[nearest].y, ues[i].position))
          nearest = static_cast<int>(c);
      }
      changed = changed || assignment[i] != nearest;
      assignment[i] = nearest;
    }
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      double cx = 0, cy = 0, cw = 0;
      clusters[c].ues.clear();
      for (std::size_t i = 0; i < ues.size(); ++i) {
        if (assignment[i] != static_cast<int>(c))
          continue;
        clusters[c].ues.push_back(static_cast<int>(i));
        cx += ues[i].demand_mbps * ues[i].position.x;
        cy += ues[i].demand_mbps * ues[i].position.y;
        cw += ues[i].demand_mbps;
      }
      if (cw > 0) {  // an emptied cluster keeps its centre
        clusters[c].x = cx / cw;
        clusters[c].y = cy / cw;
      }
    }
    if (!changed)
      break;
  }
  return clusters;
}

}  // namespace rlpos
