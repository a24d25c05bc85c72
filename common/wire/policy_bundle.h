#pragma once
// A policy folder packed to travel: the files a placement needs, under fixed names, with a
// sha256 of their canonical packing. A campaign's rl positioner may name such a folder instead
// of training; the client packs it at submit, the coordinator keeps it by its hash, and the
// worker unpacks it into a folder it names itself. Nothing but the names below ever becomes a
// file, and no path travels. Two formats, told apart as `rlpos-sim position --policy` does:
// - ours (`rlpos-sim train`): policy.pt, result.json, scenario.json;
// - TorchScript (docs/positioners.md "policy folders"): policy.json, model.pt, scenario.json.
#include <cstddef>
#include <string>
#include <vector>

namespace rlpos {

// The names a bundle may hold, in packing order.
const std::vector<std::string>& PolicyFileNames();

// Bounds of one bundle: each file and all of them together (a trained policy is kilobytes; a
// TorchScript module a few megabytes at most).
inline constexpr std::size_t kMaxPolicyBytes = 16 * 1048576;
// Policies one campaign may name.
inline constexpr std::size_t kMaxCampaignPolicies = 4;

struct PolicyFile {
  std::string name;  // one of PolicyFileNames()
  std::string data;
  bool operator==(const PolicyFile& o) const { return name == o.name && data == o.data; }
};

enum class PolicyFormat { kTrained, kTorchScript };
const char* ToString(PolicyFormat format);  // "trained" | "torchscript"

struct PolicyBundle {
  PolicyFormat format = PolicyFormat::kTrained;
  std::vector<PolicyFile> files;  // in PolicyFileNames() order, each once
  std::string sha256;             // PolicyBundleSha256(files)
};

// sha256 of the canonical packing: for each file in PolicyFileNames() order, its name, a NUL,
// its size in decimal, a NUL and its bytes. The same files give the same hash whatever order
// they came in.
std::string PolicyBundleSha256(const std::vector<PolicyFile>& files);

// A bundle from received files: checks them (known names, each once, within the bounds, the
// files of one format complete) and sorts them. Throws std::invalid_argument with one line.
PolicyBundle MakePolicyBundle(std::vector<PolicyFile> files);

// A bundle as received: the files as they came, the sha256 their sender claims, the format their
// names say. Unchecked: CheckPolicyBundle says whether it is one.
PolicyBundle ReceivedPolicyBundle(std::vector<PolicyFile> files, std::string claimed_sha256);

// "" when `bundle` is what MakePolicyBundle makes of its files and its sha256 is theirs; else
// why not (an order's bundle is held to this).
std::string CheckPolicyBundle(const PolicyBundle& bundle);

}  // namespace rlpos
