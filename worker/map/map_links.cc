#include "worker/map/map_links.h"

#include "worker/env/network/uav_network.h"

namespace rlpos::map {

std::vector<MapLink> LinksAt(const Scenario& scenario, const Placement& placement) {
  // One UavNetwork at a time (it owns the simulator): this one lives only in here.
  const UavNetwork network(scenario, placement);
  const std::vector<LinkState> links = network.Links();
  const std::vector<int>& serving = network.Association();
  std::vector<MapLink> out;
  for (std::size_t i = 0; i < links.size(); ++i)
    out.push_back({serving[i], links[i].los});
  return out;
}

void AddLinks(MapScene& scene) {
  for (MapPlacement& p : scene.placements) {
    const std::vector<MapLink> links = LinksAt(scene.scenario, p.positions);
    p.n_los = 0;
    for (const MapLink& link : links)
      p.n_los += link.los ? 1 : 0;
    if (scene.placements.size() == 1)
      scene.links = links;
  }
}

}  // namespace rlpos::map
