#include "coordinator/web/artifact_file.h"

#include <filesystem>

#include "common/store/artifact_files.h"
#include "coordinator/web/api_error.h"

namespace rlpos::web {
namespace fs = std::filesystem;

ServedArtifact ResolveArtifact(ResultsReader& store, std::int64_t artifact_id) {
  const auto record = store.Artifact(artifact_id);
  if (!record)
    throw ApiError(404, "no artifact " + std::to_string(artifact_id));
  std::string file;
  try {
    file = ResolveArtifactFile(ArtifactsDirOf(store.file()), record->path);
  } catch (const std::runtime_error& e) {
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": " + e.what());
  }
  std::error_code error;
  const auto bytes = static_cast<std::int64_t>(fs::file_size(file, error));
  if (error)
    throw ApiError(404, "artifact " + std::to_string(artifact_id) + ": unreadable");
  if (bytes > kMaxArtifactBytes)
    throw ApiError(413, "artifact " + std::to_string(artifact_id) + " is too large to serve");
  return {file, record->name, bytes};
}

}  // namespace rlpos::web
