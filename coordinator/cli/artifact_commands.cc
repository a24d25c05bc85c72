// artifacts ID [--out DIR]: list a campaign's (or a job's) artifacts, or export them. Reads the
// database read-only and the files beside it; an export is checked against each file's sha256
// and appears whole or not at all.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "common/files/atomic_file.h"
#include "common/hash/sha256.h"
#include "common/store/artifact_files.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"
#include "coordinator/cli/campaign_commands.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;

std::string ReadWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read artifact " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int ListOrExportArtifacts(const std::string& db, const std::string& id,
                          const std::string& out_dir) {
  StoreOptions options;
  options.read_only = true;
  StoreDb opened(db, options);
  ResultsReader store(opened);
  const std::vector<ArtifactRecord> artifacts = store.Artifacts(id);
  if (artifacts.empty()) {
    if (!store.GetJob(id))
      store.Progress(id);  // throws StoreError naming an unknown campaign
    // Listing nothing is an answer; exporting nothing is a failure the caller must see.
    if (out_dir.empty()) {
      std::cerr << "no artifacts for " << id << "\n";
      return kExitOk;
    }
    std::cerr << "rlpos-campaign: error: " << id << ": no artifacts to export to " << out_dir
              << "\n";
    return kExitFailure;
  }
  const fs::path root = ArtifactsDirOf(db);
  if (out_dir.empty()) {
    std::cout << std::left << std::setw(40) << "job" << std::setw(20) << "name" << std::right
              << std::setw(10) << "bytes"
              << "  sha256\n";
    for (const auto& a : artifacts) {
      std::cout << std::left << std::setw(40) << a.job_key << std::setw(20) << a.name << std::right
                << std::setw(10) << a.bytes << "  " << a.sha256.substr(0, 16)
                << (a.cached_from ? "  (cached)" : "") << "\n";
    }
    return kExitOk;
  }
  if (fs::exists(out_dir))
    throw std::invalid_argument("--out: " + out_dir + " already exists; choose another folder");
  // Built under a temporary sibling, renamed when complete: nothing half-exported.
  const fs::path partial = fs::path(out_dir).string() + ".partial";
  std::error_code error;
  fs::remove_all(partial, error);
  try {
    for (const auto& a : artifacts) {
      const std::string data = ReadWhole(root / a.path);
      if (Sha256Hex(data) != a.sha256) {
        throw std::runtime_error("artifact " + (root / a.path).string() +
                                 " does not match the sha256 the database holds");
      }
      const fs::path target = partial / a.job_key / a.name;
      fs::create_directories(target.parent_path());
      WriteFileAtomically(target.string(), data);
    }
    fs::rename(partial, out_dir);
  } catch (...) {
    fs::remove_all(partial, error);
    throw;
  }
  std::cerr << "exported " << artifacts.size() << " artifact(s) to " << out_dir << "\n";
  return kExitOk;
}

}  // namespace rlpos
