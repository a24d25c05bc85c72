#pragma once
// The flight in a trajectory.csv that `rlpos-sim train` writes (columns episode, step, uav,
// action, x, y, z, n_los, throughput_mbps, reward; one row per step of its greedy evaluation
// episodes, the position being where the moving UAV went).
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/map/map_scene.h"

namespace rlpos::map {

struct Flight {
  int episode = 0;                // the evaluation episode drawn: the file's last
  std::vector<FlightPath> paths;  // per UAV, from its start in the scenario through each move
};

// Reads the last episode of `file`. Throws ConfigError naming `what`, the file and its line: a
// missing file or column, a cell that is not a number, a UAV the scenario does not have.
Flight ReadTrajectoryCsv(const std::string& file, const Scenario& scenario,
                         const std::string& what);

}  // namespace rlpos::map
