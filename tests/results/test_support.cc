#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace rlpos::testing {

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "rlpos-results-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (!mkdtemp(buffer.data())) throw std::runtime_error("mkdtemp failed");
  path_ = buffer.data();
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::add, ignored);
  std::filesystem::remove_all(path_, ignored);
}

std::string SourcePath(const std::string& relative) {
  return std::string(RLPOS_SOURCE_DIR) + "/" + relative;
}

void WriteFile(const std::string& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file);
}

CampaignSpec MiniSpec() { return ReadCampaignFile(SourcePath("campaigns/mini.json")); }

ExpandedCampaign MiniCampaign() { return ExpandCampaign(MiniSpec()); }

const Job& FindJob(const ExpandedCampaign& campaign, const std::string& key) {
  for (const auto& job : campaign.jobs) {
    if (job.key == key) return job;
  }
  throw std::out_of_range("no job " + key);
}

nlohmann::json PositionResult(double x, double y, double z) {
  return {{"position", {x, y, z}}, {"n_los", 4}, {"reward", 0.9}};
}

nlohmann::json EvalResult(std::uint64_t run, double throughput_mbps, double delay_ms) {
  return {{"position", {50.0, 35.0, 10.0}},
          {"window_s", {0.5, 2.0}},
          {"run", run},
          {"aggregate_throughput_mbps", throughput_mbps},
          {"mean_delay_ms", delay_ms},
          {"loss_ratio", 0.01},
          {"n_los", 4},
          {"n_ues", 4},
          {"demands_met", 3},
          {"min_snr_db", 12.5},
          {"ues", nlohmann::json::array()},
          {"scenario", "B"}};
}

}  // namespace rlpos::testing
