#include "worker/env/network/association.h"

namespace rlpos {

std::vector<int> AssociateUes(const Scenario& s, const std::vector<std::vector<double>>& snr_db) {
  std::vector<int> serving(s.ues.size(), 0);
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    if (!s.ues[i].uav.empty()) {
      serving[i] = s.UavIndex(s.ues[i].uav);
      continue;
    }
    for (std::size_t u = 1; u < snr_db.size(); ++u) {
      if (snr_db[u][i] > snr_db[static_cast<std::size_t>(serving[i])][i])
        serving[i] = static_cast<int>(u);
    }
  }
  return serving;
}

}  // namespace rlpos
