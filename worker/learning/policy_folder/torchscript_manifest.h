#pragma once
// policy.json: the manifest of a policy folder that holds a TorchScript module trained anywhere
// (PyTorch through the Python binding, say) instead of one of our agents. Format version 1:
//   {"format": "torchscript", "format_version": 1, "action_space": "discrete",
//    "observation_dim": D, "action_count": A, "eval_run": R}
// model.pt's forward takes float32 [B, D] observations, exactly as the binding's env gives them,
// and returns float32 [B, A] logits; the greedy action is the argmax among the allowed actions.
// Continuous action spaces are not part of version 1.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace rlpos::sim {

inline constexpr const char* kTorchScriptManifestFile = "policy.json";
inline constexpr const char* kTorchScriptModelFile = "model.pt";

struct TorchScriptManifest {
  int format_version = 1;
  std::string action_space;  // "discrete"
  int observation_dim = 0;
  int action_count = 0;
  std::uint64_t eval_run = 0;  // RngRun of the greedy flight `position` makes
};

// Validates the manifest document; `file` names it in the error. Every problem is a ConfigError
// on --policy: "<file>: /<key>: <problem>" (unknown key, missing key, wrong type or value,
// unknown format or version, continuous actions).
TorchScriptManifest ParseTorchScriptManifest(const nlohmann::json& manifest,
                                             const std::string& file);

}  // namespace rlpos::sim
