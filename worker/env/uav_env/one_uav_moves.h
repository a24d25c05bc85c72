#pragma once
// AnalyticEvaluator::Score of many placements that differ in one UAV's position only (a coverage
// map's points, with several UAVs), the same numbers for less work: what the other UAVs give is
// worked out once. Each UE's best other UAV is fixed, so a point only decides whether the moving
// UAV takes it; and a channel none of whose UEs it takes keeps the share it has without it.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/phy/airtime_model.h"
#include "worker/env/gym/env.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {

// What one point of a coverage map remembers from map to map while its links stay the same (the
// UEs standing still): the share of the moving UAV's channel for each set of UEs it took there.
// Looked up by the set's bits instead of by every link's (ChannelShareMemo): most of a map's
// lookups with several UAVs.
struct PointShares {
  static constexpr std::size_t kMaxSets = 8;  // then the oldest is replaced
  std::vector<std::pair<std::uint64_t, double>> by_taken;
  std::size_t next = 0;
};

class OneUavMoves {
 public:
  // `links[u]` = model.LinksAt(u, placement[u]) for every u but `active` (whose entry is
  // ignored); they and `model` must outlive this.
  OneUavMoves(AnalyticEvaluator& model, const Placement& placement, std::size_t active,
              const std::vector<const std::vector<UeLink>*>& links);
  // Into `info` (every field Score sets, its vectors reused): model.Score of the placement with
  // UAV `active` at `position`, its links `active_links` (model.LinksAt(active, position)).
  // `remembered`: what this position remembers, for the same active_links every time.
  void ScoreInto(const Vec3& position, const std::vector<UeLink>& active_links, StepInfo& info,
                 PointShares* remembered = nullptr);

 private:
  // One channel's share while the moving UAV takes none of its UEs, worked out when first asked.
  struct Share {
    bool known = false;
    double mbps = 0.0;
  };
  // Channel k's (of channel_order_) share with the UEs `serving` gives it: 0.0 for none.
  double ShareOf(std::size_t k, const std::vector<int>& serving,
                 const std::vector<UeLink>& active_links);
  double KeptShare(std::size_t k, const std::vector<int>& serving,
                   const std::vector<UeLink>& active_links);
  // Channel k's share after it lost the UEs of lost_[k]: remembered in this map, or worked out.
  double ShareAfterLoss(std::size_t k, const std::vector<int>& serving,
                        const std::vector<UeLink>& active_links);
  // The moving UAV's channel's share with the UEs of `taken`: from `remembered`, or worked out
  // (0.0 when it takes none).
  double RememberedShare(std::uint64_t taken, const std::vector<int>& serving,
                         const std::vector<UeLink>& active_links, PointShares& remembered);
  const std::vector<UeLink>& LinksOf(int uav, const std::vector<UeLink>& active_links) const;

  AnalyticEvaluator& model_;
  Placement placement_;
  std::size_t active_;
  std::vector<const std::vector<UeLink>*> links_;
  bool generic_ = false;                   // one UAV, or an SNR that is not a number: Score itself
  std::vector<int> others_serving_;        // per UE: its UAV were `active` not there
  std::vector<int> channel_order_;         // the channels in the order Score sums their shares
  std::vector<std::size_t> order_of_uav_;  // per UAV: its channel's entry in channel_order_
  std::vector<Share> kept_shares_;         // per entry of channel_order_
  // Per entry of channel_order_, for the current point: the UEs the moving UAV takes from it, as
  // bits (with more than 64 UEs, only whether it takes any).
  std::vector<std::uint64_t> lost_;
  // Per entry of channel_order_: its share for each set of UEs taken from it, in this map (the
  // others' links fixed, so the set alone makes its UEs and links).
  std::vector<std::vector<std::pair<std::uint64_t, double>>> shares_after_loss_;
  bool channel_of_its_own_ = false;  // no other UAV on the moving UAV's channel
  std::vector<AirtimeLink> domain_;  // scratch
};

}  // namespace rlpos
