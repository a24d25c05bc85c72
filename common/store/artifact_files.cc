#include "common/store/artifact_files.h"

#include <filesystem>
#include <stdexcept>

#include "common/files/atomic_file.h"
#include "common/wire/identifiers.h"
#include "common/wire/limits.h"

namespace rlpos {

namespace fs = std::filesystem;

std::string ArtifactsDirOf(const std::string& db_file) {
  fs::path dir(db_file);
  if (dir.extension() == ".artifacts")
    return db_file + ".artifacts";
  return dir.replace_extension(".artifacts").string();
}

std::string PoliciesDirOf(const std::string& db_file) {
  return (std::filesystem::path(ArtifactsDirOf(db_file)) / "policies").string();
}

std::string ArtifactRelativePath(const std::string& job_id, const std::string& name) {
  if (!wire::IsSafePath(job_id, wire::kMaxIdLength))
    throw std::invalid_argument("job id " + wire::Printable(job_id) + " is not a safe path");
  if (!wire::IsSafeName(name, wire::kMaxNameLength))
    throw std::invalid_argument("artifact name " + wire::Printable(name) + " is not a safe name");
  return job_id + "/" + name;
}

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

std::string ResolveArtifactFile(const std::string& root, const std::string& relative) {
  const fs::path stored(relative);
  if (stored.empty() || stored.is_absolute())
    throw std::runtime_error("its stored path is unsafe");
  std::error_code error;
  const fs::path folder = fs::canonical(root, error);
  if (error)
    throw std::runtime_error("no artifacts folder");
  const fs::path file = fs::canonical(folder / stored, error);
  if (error || !IsInside(file, folder) || file == folder)
    throw std::runtime_error("its file is missing");
  if (!fs::is_regular_file(file, error))
    throw std::runtime_error("not a regular file");
  return file.string();
}

void WriteArtifactFile(const std::string& root, const std::string& relative,
                       const std::string& data) {
  const fs::path file = fs::path(root) / relative;
  std::error_code error;
  fs::create_directories(file.parent_path(), error);
  if (error)
    throw std::runtime_error("cannot create " + file.parent_path().string() + ": " +
                             error.message());
  WriteFileAtomically(file.string(), data);
}

}  // namespace rlpos
