#include "common/wire/policy_bundle.h"

#include <algorithm>
#include <stdexcept>

#include "common/hash/sha256.h"
#include "common/wire/limits.h"

namespace rlpos {
namespace {

const std::vector<std::string> kTrainedFiles{"policy.pt", "result.json", "scenario.json"};
const std::vector<std::string> kTorchScriptFiles{"policy.json", "model.pt", "scenario.json"};

std::size_t Rank(const std::string& name) {
  const auto& names = PolicyFileNames();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

bool Holds(const std::vector<PolicyFile>& files, const std::string& name) {
  return std::any_of(files.begin(), files.end(),
                     [&](const PolicyFile& f) { return f.name == name; });
}

}  // namespace

static_assert(kMaxPolicyBytes == wire::kMaxPolicyFileBytes &&
              kMaxCampaignPolicies == wire::kMaxPolicyFolders);

const std::vector<std::string>& PolicyFileNames() {
  static const std::vector<std::string> names{"scenario.json", "result.json", "policy.pt",
                                              "policy.json", "model.pt"};
  return names;
}

const char* ToString(PolicyFormat format) {
  return format == PolicyFormat::kTorchScript ? "torchscript" : "trained";
}

std::string PolicyBundleSha256(const std::vector<PolicyFile>& files) {
  std::vector<const PolicyFile*> sorted;
  for (const auto& f : files)
    sorted.push_back(&f);
  std::stable_sort(sorted.begin(), sorted.end(), [](const PolicyFile* a, const PolicyFile* b) {
    return Rank(a->name) < Rank(b->name);
  });
  std::string packed;
  for (const PolicyFile* f : sorted) {
    packed += f->name;
    packed += '\0';
    packed += std::to_string(f->data.size());
    packed += '\0';
    packed += f->data;
  }
  return Sha256Hex(packed);
}

PolicyBundle MakePolicyBundle(std::vector<PolicyFile> files) {
  const auto bad = [](const std::string& problem) { throw std::invalid_argument(problem); };
  std::size_t total = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const PolicyFile& f = files[i];
    if (Rank(f.name) == PolicyFileNames().size())
      bad("a policy file that is none of the known names");
    for (std::size_t j = 0; j < i; ++j) {
      if (files[j].name == f.name)
        bad("policy file " + f.name + " twice");
    }
    total += f.data.size();
    if (f.data.size() > kMaxPolicyBytes || total > kMaxPolicyBytes) {
      bad("the policy is larger than " + std::to_string(kMaxPolicyBytes) + " bytes");
    }
  }
  PolicyBundle bundle;
  // As ReadPolicyFolder decides: either TorchScript file makes a TorchScript folder.
  const bool torchscript = Holds(files, "policy.json") || Holds(files, "model.pt");
  bundle.format = torchscript ? PolicyFormat::kTorchScript : PolicyFormat::kTrained;
  const auto& needed = torchscript ? kTorchScriptFiles : kTrainedFiles;
  for (const auto& name : needed) {
    if (!Holds(files, name)) {
      bad(std::string("a ") + ToString(bundle.format) + " policy needs " + name +
          (files.empty() ? " (no policy file at all)" : ""));
    }
  }
  for (const auto& f : files) {
    if (std::find(needed.begin(), needed.end(), f.name) == needed.end())
      bad("policy file " + f.name + " does not belong to a " + ToString(bundle.format) + " policy");
  }
  std::sort(files.begin(), files.end(),
            [](const PolicyFile& a, const PolicyFile& b) { return Rank(a.name) < Rank(b.name); });
  bundle.sha256 = PolicyBundleSha256(files);
  bundle.files = std::move(files);
  return bundle;
}

PolicyBundle ReceivedPolicyBundle(std::vector<PolicyFile> files, std::string claimed_sha256) {
  PolicyBundle bundle;
  bundle.format = Holds(files, "policy.json") || Holds(files, "model.pt")
                      ? PolicyFormat::kTorchScript
                      : PolicyFormat::kTrained;
  bundle.files = std::move(files);
  bundle.sha256 = std::move(claimed_sha256);
  return bundle;
}

std::string CheckPolicyBundle(const PolicyBundle& bundle) {
  try {
    const PolicyBundle made = MakePolicyBundle(bundle.files);
    if (made.files != bundle.files || made.format != bundle.format)
      return "policy files out of order or of another format";
    if (!IsSha256Hex(bundle.sha256) || made.sha256 != bundle.sha256)
      return "the policy does not match its sha256";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace rlpos
