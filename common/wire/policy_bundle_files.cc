#include "common/wire/policy_bundle_files.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/hash/sha256.h"
#include "common/wire/identifiers.h"

namespace rlpos {
namespace fs = std::filesystem;

namespace {

std::string ReadWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof())
    throw std::invalid_argument(file.string() + ": cannot be read");
  return text.str();
}

bool HoldsBundle(const std::string& dir, const std::string& sha256) {
  try {
    return ReadPolicyBundle(dir).sha256 == sha256;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

PolicyBundle ReadPolicyBundle(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw std::invalid_argument("policy folder \"" + dir + "\" does not exist");
  std::vector<PolicyFile> files;
  std::uintmax_t total = 0;
  for (const auto& name : PolicyFileNames()) {
    const fs::path file = fs::path(dir) / name;
    if (!fs::exists(file, error))
      continue;
    if (!fs::is_regular_file(file, error))
      throw std::invalid_argument(file.string() + " is not a regular file");
    total += fs::file_size(file, error);
    if (error || total > kMaxPolicyBytes) {
      throw std::invalid_argument("policy folder \"" + dir + "\" holds more than " +
                                  std::to_string(kMaxPolicyBytes) + " bytes of policy files");
    }
    files.push_back({name, ReadWhole(file)});
  }
  if (files.empty()) {
    throw std::invalid_argument("policy folder \"" + dir +
                                "\" holds no policy (neither result.json and policy.pt from "
                                "`rlpos-sim train` nor a TorchScript policy.json and model.pt)");
  }
  try {
    return MakePolicyBundle(std::move(files));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("policy folder \"" + dir + "\": " + e.what());
  }
}

std::string PolicyBundleDir(const std::string& root, const std::string& sha256) {
  return (fs::path(root) / sha256).string();
}

std::string WritePolicyBundle(const PolicyBundle& bundle, const std::string& root) {
  if (!IsSha256Hex(bundle.sha256))
    throw std::runtime_error("a policy bundle without a sha256");
  const std::string dir = PolicyBundleDir(root, bundle.sha256);
  if (HoldsBundle(dir, bundle.sha256))
    return dir;
  std::error_code error;
  fs::create_directories(root, error);
  // Unique per process: two workers sharing a folder never write into one temporary folder.
  const fs::path temp = fs::path(root) / ("." + bundle.sha256 + ".tmp" + std::to_string(getpid()));
  fs::remove_all(temp, error);
  fs::create_directories(temp, error);
  if (error)
    throw std::runtime_error(temp.string() + ": " + error.message());
  for (const auto& f : bundle.files) {
    std::ofstream out(temp / f.name, std::ios::binary);
    out.write(f.data.data(), static_cast<std::streamsize>(f.data.size()));
    out.close();
    if (!out)
      throw std::runtime_error((temp / f.name).string() + ": cannot write");
  }
  fs::remove_all(dir, error);  // a damaged copy
  fs::rename(temp, dir, error);
  if (error) {
    fs::remove_all(temp, error);
    // Another writer may have won the race with the same files.
    if (!HoldsBundle(dir, bundle.sha256))
      throw std::runtime_error(dir + ": cannot store the policy");
  }
  return dir;
}

PolicyBundle ReadStoredPolicyBundle(const std::string& root, const std::string& sha256) {
  if (!IsSha256Hex(sha256))
    throw std::runtime_error("not a policy sha256: \"" + wire::Printable(sha256) + "\"");
  const std::string dir = PolicyBundleDir(root, sha256);
  PolicyBundle bundle;
  try {
    bundle = ReadPolicyBundle(dir);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("stored policy ") + sha256 + ": " + e.what());
  }
  if (bundle.sha256 != sha256)
    throw std::runtime_error("stored policy " + sha256 + " does not match its sha256");
  return bundle;
}

}  // namespace rlpos
