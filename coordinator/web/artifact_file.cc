#include "coordinator/web/artifact_file.h"

#include <filesystem>

#include "common/store/artifact_files.h"
#include "coordinator/web/api_error.h"

namespace rlpos::web {
namespace fs = std::filesystem;

namespace {

// True when `path` is `root` or below it (both canonical).
bool IsInside(const fs::path& path, const fs::path& root) {
  auto p = path.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++p) {
    if (p == path.end() || *p != *r)
      return false;
  }
  return true;
}

}  // namespace

ServedArtifact ResolveArtifact(ResultsReader& store, std::int64_t artifact_id) {
  const auto record = store.Artifact(artifact_id);
  if (!record)
    throw ApiError(404, "no artifact " + std::to_string(artifact_id));
  const fs::path relative(record->path);
  if (relative.empty() || relative.is_absolute())
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": its stored path is unsafe");
  std::error_code error;
  const fs::path root = fs::canonical(ArtifactsDirOf(store.file()), error);
  if (error)
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": no artifacts folder");
  const fs::path file = fs::canonical(root / relative, error);
  if (error || !IsInside(file, root) || file == root)
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": its file is missing");
  if (!fs::is_regular_file(file, error))
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": not a regular file");
  const auto bytes = static_cast<std::int64_t>(fs::file_size(file, error));
  if (error)
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": unreadable");
  if (bytes > kMaxArtifactBytes)
    throw ApiError(413, "artifact " + std::to_string(artifact_id) + " is too large to serve");
  return {file.string(), record->name, bytes};
}

}  // namespace rlpos::web
