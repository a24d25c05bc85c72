#pragma once
// An artifact's file, found by its id in the database: the stored path, relative to the
// artifacts folder beside the database, must resolve (symbolic links followed) to a regular file
// inside that folder. Nothing a request writes ever becomes part of a path.
#include <cstdint>
#include <string>

#include "common/store/results_reader.h"

namespace rlpos::web {

constexpr std::int64_t kMaxArtifactBytes = 256ll << 20;

struct ServedArtifact {
  std::string file;  // absolute, inside the artifacts folder
  std::string name;  // the artifact's name, for the download
  std::int64_t bytes = 0;
};

// Throws ApiError 404 (no such artifact, or its file is missing or outside the folder) or 413
// (larger than kMaxArtifactBytes).
ServedArtifact ResolveArtifact(ResultsReader& store, std::int64_t artifact_id);

}  // namespace rlpos::web
