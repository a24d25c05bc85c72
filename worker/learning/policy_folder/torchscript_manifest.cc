#include "worker/learning/policy_folder/torchscript_manifest.h"

#include <algorithm>
#include <array>
#include <limits>

#include "common/config/config_error.h"

namespace rlpos::sim {
namespace {

constexpr std::array<const char*, 6> kKeys = {"format",          "format_version", "action_space",
                                              "observation_dim", "action_count",   "eval_run"};

[[noreturn]] void Refuse(const std::string& file, const std::string& key,
                         const std::string& problem) {
  throw ConfigError("--policy", file + ": /" + key + ": " + problem);
}

const nlohmann::json& Required(const nlohmann::json& manifest, const char* key,
                               const std::string& file) {
  const auto it = manifest.find(key);
  if (it == manifest.end())
    Refuse(file, key, "missing");
  return *it;
}

std::uint64_t Positive(const nlohmann::json& manifest, const char* key, const std::string& file,
                       std::uint64_t max) {
  const nlohmann::json& v = Required(manifest, key, file);
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() == 0 || v.get<std::uint64_t>() > max)
    Refuse(file, key, "expected an integer in [1, " + std::to_string(max) + "], got " + v.dump());
  return v.get<std::uint64_t>();
}

}  // namespace

TorchScriptManifest ParseTorchScriptManifest(const nlohmann::json& manifest,
                                             const std::string& file) {
  if (!manifest.is_object())
    throw ConfigError("--policy", file + ": expected a JSON object");
  for (const auto& item : manifest.items()) {
    if (std::find(kKeys.begin(), kKeys.end(), item.key()) == kKeys.end())
      Refuse(file, item.key(), "unknown key (format_version 1 has no such key)");
  }
  const nlohmann::json& format = Required(manifest, "format", file);
  if (format != "torchscript")
    Refuse(file, "format", "unknown format " + format.dump() + "; expected \"torchscript\"");
  const nlohmann::json& version = Required(manifest, "format_version", file);
  if (version != 1)
    Refuse(file, "format_version", "unknown version " + version.dump() + "; this build reads 1");
  TorchScriptManifest m;
  const nlohmann::json& actions = Required(manifest, "action_space", file);
  if (actions == "continuous") {
    Refuse(file, "action_space",
           "continuous actions are not supported (format_version 1: discrete only)");
  }
  if (actions != "discrete")
    Refuse(file, "action_space", "expected \"discrete\", got " + actions.dump());
  m.action_space = "discrete";
  constexpr std::uint64_t kMaxDim = 1 << 20;
  m.observation_dim = static_cast<int>(Positive(manifest, "observation_dim", file, kMaxDim));
  m.action_count = static_cast<int>(Positive(manifest, "action_count", file, kMaxDim));
  m.eval_run = Positive(manifest, "eval_run", file, std::numeric_limits<std::int64_t>::max());
  return m;
}

}  // namespace rlpos::sim
