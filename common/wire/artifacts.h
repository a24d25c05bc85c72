#pragma once
// The files a job sends home with its result: a train job's policy, learning curve and the
// positions it flew, so that a campaign's models live beside its database and an rl eval can be
// re-run elsewhere. Only the names below travel, each within a size bound and with its sha256;
// the coordinator chooses where they are stored (a name never becomes a path on its own).
#include <cstddef>
#include <string>
#include <vector>

namespace rlpos {

struct ArtifactFile {
  std::string name;    // one of TrainArtifactNames()
  std::string sha256;  // of data, 64 lowercase hex digits
  std::string data;
};

// policy.pt (the network), learning_curve.csv (per episode: reward, loss, epsilon, final
// position), trajectory.csv (each step of the greedy evaluation episodes), result.json (what
// `rlpos-sim position --positioner rl --policy DIR` reads) and scenario.json (the scenario it
// trained on, overrides applied).
const std::vector<std::string>& TrainArtifactNames();

// "" when the artifacts are acceptable: known names, each once, each within
// wire::kMaxArtifactBytes and all within wire::kMaxArtifactsTotal, each with its true sha256.
// Else why not.
std::string CheckArtifacts(const std::vector<ArtifactFile>& artifacts);

}  // namespace rlpos
