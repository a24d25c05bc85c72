#include "worker/positioning/track/track_positioner.h"

#include "common/config/config_error.h"
#include "common/scenario/names.h"
#include "worker/positioning/positioners/positioners.h"
#include "worker/positioning/positioners/tracking_oracle.h"

namespace rlpos {
namespace {

// `scenario` with its UEs at `ue_positions` and its UAVs' initial positions at `uavs_now`: what
// the static positioners read (centroid matches clusters to UAVs by distance from there).
Scenario At(Scenario scenario, const std::vector<Vec3>& ue_positions, const Placement& uavs_now) {
  for (std::size_t i = 0; i < ue_positions.size(); ++i)
    scenario.ues[i].position = ue_positions[i];
  for (std::size_t u = 0; u < uavs_now.size(); ++u)
    scenario.uavs[u].initial = uavs_now[u];
  return scenario;
}

Placement AnalyticOracleOnce(const Scenario& scenario) {
  OracleOptions options;
  options.packet_candidates = 0;
  return OracleSearch(scenario, options).front().placement;
}

// Decides once, at the first call (t = 0), then keeps it.
class Held : public TrackPositioner {
 public:
  Held(const Scenario& scenario, Placement (*place)(const Scenario&))
      : scenario_(scenario), place_(place) {}
  Placement Decide(const std::vector<Vec3>& ue_positions, const Placement&) override {
    // The scenario as written (the UAVs' initial positions included): what `position` places.
    if (placement_.empty())
      placement_ = place_(At(scenario_, ue_positions, {}));
    return placement_;
  }

 private:
  Scenario scenario_;
  Placement (*place_)(const Scenario&);
  Placement placement_;
};

class CentroidTrack : public TrackPositioner {
 public:
  explicit CentroidTrack(const Scenario& scenario) : scenario_(scenario) {}
  Placement Decide(const std::vector<Vec3>& ue_positions, const Placement& uavs_now) override {
    return CentroidPlacement(At(scenario_, ue_positions, uavs_now));
  }

 private:
  Scenario scenario_;
};

class OracleTrack : public TrackPositioner {
 public:
  explicit OracleTrack(const Scenario& scenario) : oracle_(scenario) {}
  Placement Decide(const std::vector<Vec3>& ue_positions, const Placement&) override {
    return oracle_.Decide(ue_positions);
  }

 private:
  TrackingOracle oracle_;
};

}  // namespace

std::unique_ptr<TrackPositioner> MakeTrackPositioner(const std::string& name,
                                                     const Scenario& scenario) {
  if (name == "baseline")
    return std::make_unique<Held>(scenario, BaselinePlacement);
  if (name == "centroid")
    return std::make_unique<Held>(scenario, CentroidPlacement);
  if (name == "oracle")
    return std::make_unique<Held>(scenario, AnalyticOracleOnce);
  if (name == "centroid-track")
    return std::make_unique<CentroidTrack>(scenario);
  if (name == "oracle-track")
    return std::make_unique<OracleTrack>(scenario);
  if (name == "rl") {
    throw ConfigError("--positioner",
                      "rl flies a policy, which the RL module loads: rlpos-sim track "
                      "--positioner rl --policy DIR (a policy for any scenario)");
  }
  if (name == "offsets") {
    throw ConfigError("--positioner",
                      "offsets are placed around rl's position, not in track; use " +
                          Alternatives(kPlacingPositioners) + ", or " +
                          Alternatives(kTrackingPositioners));
  }
  throw ConfigError("--positioner", "unknown positioner \"" + name + "\"; expected " +
                                        Alternatives(kTrackPositioners));
}

}  // namespace rlpos
