#include "common/process/shipped_data.h"

#include <filesystem>

#include "common/process/executable_path.h"

namespace rlpos {

namespace fs = std::filesystem;

std::string ResolveShipped(const std::string& given, ShippedKind kind) {
  std::error_code error;
  if (given.empty() || given.find('/') != std::string::npos || fs::exists(given, error))
    return given;
  const fs::path share = fs::path(ExecutableDir()).parent_path() / "share" / "rlpos";
  const fs::path folder =
      kind == ShippedKind::kScenario ? share / "campaigns" / "scenarios" : share / "policies";
  for (const fs::path& candidate : {folder / given, folder / (given + ".json")}) {
    if (kind == ShippedKind::kPolicy && candidate.extension() == ".json")
      continue;
    if (fs::exists(candidate, error))
      return candidate.lexically_normal().string();
  }
  return given;
}

}  // namespace rlpos
