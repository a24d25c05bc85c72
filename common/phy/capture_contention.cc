#include "common/phy/capture_contention.h"

#include <algorithm>
#include <cmath>

#include "common/phy/dcf_contention.h"

namespace rlpos {

CaptureShares ContendWithCapture(const std::vector<double>& snr_db, double activity,
                                 const CaptureParams& params) {
  const std::size_t n = snr_db.size();
  const double rho = std::clamp(activity, 0.0, 1.0);
  const double kappa = std::clamp(params.probability, 0.0, 1.0);
  const int stages = BackoffStages(params.cw_min, params.cw_max);
  std::vector<double> p(n, 0.0), tau(n), none(n), capture(n), odds(n);
  // Which stations i captures over: fixed, so worked out once, not in every iteration.
  std::vector<char> weaker(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      weaker[i * n + j] = j != i && snr_db[i] - snr_db[j] >= params.threshold_db;
  }
  // Damped fixed-point iteration: the map is a contraction for the loads of a Wi-Fi cell, and
  // damping keeps strong and weak stations from oscillating against each other.
  for (int iteration = 0; iteration < 500; ++iteration) {
    for (std::size_t i = 0; i < n; ++i) {
      tau[i] = rho * BackoffTauAtStages(p[i], params.cw_min, stages);
      odds[i] = tau[i] / (1.0 - tau[i]);  // once per station, not once per pair
    }
    double all_quiet = 1.0;
    for (double t : tau)
      all_quiet *= 1.0 - t;
    double change = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      none[i] = all_quiet / (1.0 - tau[i]);  // nobody else transmits in i's slot
      double one_weaker = 0.0;               // exactly one other does, and it is weaker
      // Summed in j's order, as always: the same bits.
      for (std::size_t j = 0; j < n; ++j) {
        if (weaker[i * n + j])
          one_weaker += odds[j];
      }
      capture[i] = kappa * one_weaker * none[i];
      const double next = std::clamp(1.0 - none[i] - capture[i], 0.0, 1.0);
      change = std::max(change, std::abs(next - p[i]));
      p[i] = 0.5 * (p[i] + next);
    }
    if (change < 1e-12)
      break;
  }
  CaptureShares shares;
  shares.access_weight.assign(n, 1.0);
  shares.capture_share.assign(n, 0.0);
  double mean_success = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // Own attempts are not scaled by the activity: the weights compare backlogged stations.
    shares.access_weight[i] = BackoffTauAtStages(p[i], params.cw_min, stages) * (1.0 - p[i]);
    shares.capture_share[i] = p[i] < 1.0 ? capture[i] / (1.0 - p[i]) : 0.0;
    mean_success += shares.access_weight[i] / static_cast<double>(n);
  }
  for (double& w : shares.access_weight)
    w = mean_success > 0 ? w / mean_success : 1.0;
  return shares;
}

}  // namespace rlpos
