#include "worker/env/uav_env/one_uav_moves.h"

#include <algorithm>
#include <cmath>

namespace rlpos {
namespace {

bool AnyNan(const std::vector<UeLink>& links) {
  return std::any_of(links.begin(), links.end(),
                     [](const UeLink& link) { return std::isnan(link.snr_db); });
}

// Score itself, for what the shortcut does not cover.
void ScoreWhole(AnalyticEvaluator& model, const Placement& placement, std::size_t active,
                const std::vector<UeLink>& active_links,
                std::vector<const std::vector<UeLink>*>& links, StepInfo& info) {
  links[active] = &active_links;
  info = model.Score(placement, links);
}

}  // namespace

OneUavMoves::OneUavMoves(AnalyticEvaluator& model, const Placement& placement, std::size_t active,
                         const std::vector<const std::vector<UeLink>*>& links)
    : model_(model), placement_(placement), active_(active), links_(links) {
  const Scenario& scenario = model.GetScenario();
  const std::size_t n_uavs = placement.size();
  generic_ = n_uavs == 1;
  for (std::size_t u = 0; u < n_uavs && !generic_; ++u)
    generic_ = u != active && AnyNan(*links[u]);
  if (generic_)
    return;
  // AssociateUes picks the lowest index of the best SNR: the best of the others is fixed here.
  others_serving_.assign(scenario.ues.size(), 0);
  for (std::size_t i = 0; i < scenario.ues.size(); ++i) {
    if (!scenario.ues[i].uav.empty()) {
      others_serving_[i] = scenario.UavIndex(scenario.ues[i].uav);
      continue;
    }
    int best = -1;
    for (std::size_t u = 0; u < n_uavs; ++u) {
      if (u != active &&
          (best < 0 || (*links[u])[i].snr_db > (*links[static_cast<std::size_t>(best)])[i].snr_db))
        best = static_cast<int>(u);
    }
    others_serving_[i] = best;
  }
  for (const int channel : model.UavChannels()) {
    if (std::find(channel_order_.begin(), channel_order_.end(), channel) == channel_order_.end())
      channel_order_.push_back(channel);
  }
  const std::vector<int>& channels = model.UavChannels();
  for (const int channel : channels)
    order_of_uav_.push_back(static_cast<std::size_t>(
        std::find(channel_order_.begin(), channel_order_.end(), channel) - channel_order_.begin()));
  channel_of_its_own_ = std::count(channels.begin(), channels.end(), channels[active]) == 1;
  kept_shares_.assign(channel_order_.size(), Share{});
  lost_.assign(channel_order_.size(), 0);
  shares_after_loss_.assign(channel_order_.size(), {});
}

const std::vector<UeLink>& OneUavMoves::LinksOf(int uav,
                                                const std::vector<UeLink>& active_links) const {
  return static_cast<std::size_t>(uav) == active_ ? active_links
                                                  : *links_[static_cast<std::size_t>(uav)];
}

void OneUavMoves::ScoreInto(const Vec3& position, const std::vector<UeLink>& active_links,
                            StepInfo& info, PointShares* remembered) {
  placement_[active_] = position;
  if (generic_)
    return ScoreWhole(model_, placement_, active_, active_links, links_, info);
  const Scenario& scenario = model_.GetScenario();
  const int active = static_cast<int>(active_);
  const std::size_t n_ues = scenario.ues.size();
  info.positions = placement_;
  info.serving.resize(n_ues);
  info.active_uav = 0;
  info.n_los = 0;
  info.los.clear();
  info.throughput_mbps = 0.0;
  info.demands_met = 0;
  info.snr_db.clear();
  info.coverage.clear();
  info.lookahead.clear();
  std::fill(lost_.begin(), lost_.end(), 0);
  // The UEs the moving UAV serves, as bits: with its channel its own and its links fixed, they
  // alone make its channel's share.
  if (!channel_of_its_own_ || n_ues > 64)
    remembered = nullptr;
  std::uint64_t taken = 0;
  for (std::size_t i = 0; i < n_ues; ++i) {
    const int other = others_serving_[i];
    int serving = other;
    if (scenario.ues[i].uav.empty()) {
      const double mine = active_links[i].snr_db;
      if (std::isnan(mine))  // the best of the others no longer decides alone
        return ScoreWhole(model_, placement_, active_, active_links, links_, info);
      const double theirs = (*links_[static_cast<std::size_t>(other)])[i].snr_db;
      if (mine > theirs || (mine == theirs && active < other))
        serving = active;
    }
    if (serving == active && other != active)
      lost_[order_of_uav_[static_cast<std::size_t>(other)]] |=
          n_ues <= 64 ? std::uint64_t{1} << i : 1;
    info.serving[i] = serving;
    if (serving == active)
      taken |= std::uint64_t{1} << i;
    const UeLink& link = LinksOf(serving, active_links)[i];
    info.n_los += link.los ? 1 : 0;
    info.los.push_back(link.los ? 1 : 0);
    info.snr_db.push_back(link.snr_db);
    info.demands_met += link.demand_met ? 1 : 0;
  }
  // Score's sum, channel by channel in the same order (a channel without UEs adds 0.0, which
  // leaves the sum's bits as Score's skipping it does: the sum starts at +0.0).
  const std::size_t active_k = order_of_uav_[active_];
  for (std::size_t k = 0; k < channel_order_.size(); ++k) {
    if (k != active_k && lost_[k] == 0)
      info.throughput_mbps += KeptShare(k, info.serving, active_links);
    else if (k != active_k && n_ues <= 64)
      info.throughput_mbps += ShareAfterLoss(k, info.serving, active_links);
    else if (k == active_k && remembered)
      info.throughput_mbps += RememberedShare(taken, info.serving, active_links, *remembered);
    else
      info.throughput_mbps += ShareOf(k, info.serving, active_links);
  }
}

double OneUavMoves::ShareOf(std::size_t k, const std::vector<int>& serving,
                            const std::vector<UeLink>& active_links) {
  domain_.clear();
  for (std::size_t i = 0; i < serving.size(); ++i) {
    const auto uav = static_cast<std::size_t>(serving[i]);
    if (order_of_uav_[uav] == k)
      domain_.push_back(model_.AirtimeOf(i, LinksOf(serving[i], active_links)[i]));
  }
  return domain_.empty() ? 0.0 : model_.ChannelThroughput(domain_);
}

double OneUavMoves::RememberedShare(std::uint64_t taken, const std::vector<int>& serving,
                                    const std::vector<UeLink>& active_links,
                                    PointShares& remembered) {
  for (const auto& [set, mbps] : remembered.by_taken) {
    if (set == taken)
      return mbps;
  }
  const double mbps = ShareOf(order_of_uav_[active_], serving, active_links);
  if (remembered.by_taken.size() < PointShares::kMaxSets) {
    remembered.by_taken.emplace_back(taken, mbps);
  } else {
    remembered.by_taken[remembered.next] = {taken, mbps};
    remembered.next = (remembered.next + 1) % PointShares::kMaxSets;
  }
  return mbps;
}

double OneUavMoves::ShareAfterLoss(std::size_t k, const std::vector<int>& serving,
                                   const std::vector<UeLink>& active_links) {
  constexpr std::size_t kMaxSets = 256;  // per channel and map
  std::vector<std::pair<std::uint64_t, double>>& known = shares_after_loss_[k];
  for (const auto& [set, mbps] : known) {
    if (set == lost_[k])
      return mbps;
  }
  const double mbps = ShareOf(k, serving, active_links);
  if (known.size() < kMaxSets)
    known.emplace_back(lost_[k], mbps);
  return mbps;
}

double OneUavMoves::KeptShare(std::size_t k, const std::vector<int>& serving,
                              const std::vector<UeLink>& active_links) {
  // Its UEs are those it has without the moving UAV, with the same links.
  Share& share = kept_shares_[k];
  if (!share.known)
    share = {true, ShareOf(k, serving, active_links)};
  return share.mbps;
}

}  // namespace rlpos
