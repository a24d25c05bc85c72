#pragma once
// Shared helpers of the results tests: temporary folders, the shipped campaigns, and the JSON
// that rlpos-sim prints for each kind of job.
#include <nlohmann/json.hpp>
#include <string>

#include "campaign/campaign_spec.h"
#include "campaign/expansion.h"

namespace rlpos::testing {

// A fresh folder under the system's temp dir, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::string SourcePath(const std::string& relative);  // inside the repository
void WriteFile(const std::string& file, const std::string& text);

CampaignSpec MiniSpec();                  // campaigns/mini.json
ExpandedCampaign MiniCampaign();          // its jobs
const Job& FindJob(const ExpandedCampaign& campaign, const std::string& key);

// stdout of `rlpos-sim train|position --json` and of `rlpos-sim eval --json`.
nlohmann::json PositionResult(double x, double y, double z);
nlohmann::json EvalResult(std::uint64_t run, double throughput_mbps, double delay_ms);

}  // namespace rlpos::testing
