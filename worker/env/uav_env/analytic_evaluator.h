#pragma once
// The "analytic" fidelity: the state at a UAV position without packets. LoS from the building
// geometry and SNR from the scenario's loss models (worker/env/analytic: the packet-level
// channel's numbers); the MCS per UE from ns-3's own rate thresholds; throughput from the
// airtime-share model. With several UAVs each UE associates with its UAV at the placement
// evaluated (environment/association.h), and the UEs of UAVs on one channel share that
// channel's airtime (their BSSs contend). Owns all it uses: any number may live in one process,
// and each may be used by one thread at a time.
#include <memory>
#include <string>

#include "common/phy/airtime_model.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/uav_env/channel_share_memo.h"
#include "worker/env/uav_env/placement_memo.h"
#include "worker/env/uav_env/shared_placement_memo.h"

namespace rlpos {

class AnalyticChannel;

// One UE's link to a UAV at some position, with what the airtime model needs of it.
struct UeLink {
  bool los = false;
  double snr_db = 0.0;
  double phy_rate_mbps = 0.0;  // 0: below the lowest MCS
  double mpdu_success = 1.0;
  bool demand_met = false;
};

class AnalyticEvaluator {
 public:
  // With `shared_memo` (of this scenario, shared with other evaluators), Evaluate remembers its
  // states there; without it, in its own PlacementMemo.
  explicit AnalyticEvaluator(const Scenario& scenario,
                             std::shared_ptr<SharedPlacementMemo> shared_memo = nullptr);
  ~AnalyticEvaluator();
  // Placements already evaluated come from a bounded memo (placement_memo.h): the same numbers.
  StepInfo Evaluate(const Placement& placement);
  // The same into `info` (every field set), reusing its vectors: no allocation on a memo hit.
  void EvaluateInto(const Placement& placement, StepInfo& info);
  // Every UE's link to UAV `uav` were it at `position` (the other UAVs do not matter).
  std::vector<UeLink> LinksAt(std::size_t uav, const Vec3& position);
  // UE `ue`'s link alone (LinksAt(uav, position)[ue]).
  UeLink LinkAt(std::size_t uav, std::size_t ue, const Vec3& position);
  // The UEs where they are at some time t of a run (one per UE, in the scenario's order; the
  // scenario's positions until this is called): every later evaluation is of that moment.
  // Forgets the placements memorised before. Throws std::logic_error with a shared memo (the
  // other evaluators sharing it keep their UEs) and std::invalid_argument for another count.
  void SetUePositions(const std::vector<Vec3>& positions);
  const std::vector<Vec3>& UePositions() const;
  // The state at `placement` from links already known: `links[u]` = LinksAt(u, placement[u]).
  // What a search that moves one UAV at a time evaluates without recomputing the others.
  StepInfo Score(const Placement& placement, const std::vector<const std::vector<UeLink>*>& links);
  // Score's parts, for those that score many placements in one go (one_uav_moves.h):
  // UE `ue`'s entry in the airtime model when `link` serves it;
  AirtimeLink AirtimeOf(std::size_t ue, const UeLink& link) const;
  // the airtime model's aggregate throughput of one channel's UEs (remembered by their inputs).
  double ChannelThroughput(const std::vector<AirtimeLink>& domain);
  const std::vector<int>& UavChannels() const;
  const Scenario& GetScenario() const { return scenario_; }

 private:
  Scenario scenario_;
  PhyProfile phy_;  // the scenario's Wi-Fi, as the MCS table reads it
  CaptureCost capture_;
  std::unique_ptr<AnalyticChannel> channel_;
  std::unique_ptr<PlacementMemo> own_memo_;           // no shared memo given
  std::shared_ptr<SharedPlacementMemo> shared_memo_;  // or this one
  ChannelShareMemo channel_shares_;                   // several UAVs: each channel's share
};

// The env's reward (the scenario's env.reward) at `placement` by the analytic model: what the
// agent and the oracle score a placement with. Builds its own evaluator.
double AnalyticReward(const Scenario& scenario, const Placement& placement);

// What a packet-level eval records as its reward: AnalyticReward, or NaN (null in the eval's
// JSON) where the analytic model refuses the scenario's loss model (one that reads ns-3's
// building list, draws random numbers or asks a condition model of its own), which packet level
// runs: the eval keeps its packet metrics. `why` gets the refusal ("" when scored).
double PacketEvalReward(const Scenario& scenario, const Placement& placement, std::string& why);

}  // namespace rlpos
