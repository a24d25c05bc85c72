#include "common/wire/artifacts.h"

#include <algorithm>
#include <set>

#include "common/hash/sha256.h"
#include "common/wire/limits.h"

namespace rlpos {

const std::vector<std::string>& TrainArtifactNames() {
  static const std::vector<std::string> names{"policy.pt", "learning_curve.csv", "trajectory.csv",
                                              "result.json", "scenario.json"};
  return names;
}

std::string CheckArtifacts(const std::vector<ArtifactFile>& artifacts) {
  if (artifacts.size() > wire::kMaxArtifacts)
    return "too many artifacts";
  const auto& known = TrainArtifactNames();
  std::set<std::string> seen;
  std::size_t total = 0;
  for (const auto& a : artifacts) {
    if (std::find(known.begin(), known.end(), a.name) == known.end())
      return "unknown artifact name";
    if (!seen.insert(a.name).second)
      return "artifact " + a.name + " twice";
    if (a.data.size() > wire::kMaxArtifactBytes)
      return "artifact " + a.name + " too large";
    total += a.data.size();
    if (total > wire::kMaxArtifactsTotal)
      return "artifacts too large together";
    if (!IsSha256Hex(a.sha256) || Sha256Hex(a.data) != a.sha256)
      return "artifact " + a.name + " does not match its sha256";
  }
  return "";
}

}  // namespace rlpos
