// A named policy's bundle (wire/policy_bundle.h): only the fixed file names, within the bounds,
// one format complete, and the sha256 of its canonical packing; an order carries one only for
// an rl position job, and only the one its policy_sha256 names.
#include "common/wire/policy_bundle.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/hash/sha256.h"
#include "common/wire/job_order.h"
#include "common/wire/policy_bundle_files.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

std::vector<PolicyFile> TrainedFiles() {
  return {{"scenario.json", "{\"name\": \"B\"}"},
          {"result.json", "{\"algorithm\": \"dqn\"}"},
          {"policy.pt", std::string("\0\1weights", 9)}};
}

std::string ErrorOfBundle(std::vector<PolicyFile> files) {
  try {
    MakePolicyBundle(std::move(files));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PolicyBundle, TheHashIsOfTheFilesWhateverTheirOrder) {
  const PolicyBundle bundle = MakePolicyBundle(TrainedFiles());
  EXPECT_EQ(bundle.format, PolicyFormat::kTrained);
  EXPECT_EQ(CheckPolicyBundle(bundle), "");
  std::vector<PolicyFile> reversed = TrainedFiles();
  std::reverse(reversed.begin(), reversed.end());
  EXPECT_EQ(MakePolicyBundle(reversed).sha256, bundle.sha256);
  EXPECT_EQ(MakePolicyBundle(reversed).files, bundle.files);
  std::vector<PolicyFile> retrained = TrainedFiles();
  retrained[2].data += "x";
  EXPECT_NE(MakePolicyBundle(retrained).sha256, bundle.sha256);
  // The canonical packing, as documented: name, NUL, decimal size, NUL, bytes, in
  // PolicyFileNames() order. Its hash is the campaign's and the workers' contract.
  std::string packed;
  for (const auto& f : {TrainedFiles()[0], TrainedFiles()[1], TrainedFiles()[2]}) {
    packed += f.name + std::string(1, '\0') + std::to_string(f.data.size()) + std::string(1, '\0') +
              f.data;
  }
  EXPECT_EQ(bundle.sha256, Sha256Hex(packed));
  const PolicyBundle torchscript =
      MakePolicyBundle({{"model.pt", "zip"}, {"policy.json", "{}"}, {"scenario.json", "{}"}});
  EXPECT_EQ(torchscript.format, PolicyFormat::kTorchScript);
  EXPECT_EQ(torchscript.files.front().name, "scenario.json");
}

TEST(PolicyBundle, BadBundlesAreRefusedInOneLine) {
  std::vector<PolicyFile> files = TrainedFiles();
  files.push_back({"../../etc/passwd", "x"});
  EXPECT_EQ(ErrorOfBundle(files), "a policy file that is none of the known names");
  files = TrainedFiles();
  files.push_back(files[0]);
  EXPECT_EQ(ErrorOfBundle(files), "policy file scenario.json twice");
  files = TrainedFiles();
  files[2].data.assign(kMaxPolicyBytes, 'w');
  EXPECT_EQ(ErrorOfBundle(files), "the policy is larger than 16777216 bytes");
  files = TrainedFiles();
  files.pop_back();
  EXPECT_EQ(ErrorOfBundle(files), "a trained policy needs policy.pt");
  EXPECT_EQ(ErrorOfBundle({}), "a trained policy needs policy.pt (no policy file at all)");
  files = TrainedFiles();
  files.push_back({"model.pt", "zip"});
  EXPECT_EQ(ErrorOfBundle(files), "a torchscript policy needs policy.json");
  files.push_back({"policy.json", "{}"});
  EXPECT_EQ(ErrorOfBundle(files),
            "policy file result.json does not belong to a torchscript policy");
}

TEST(PolicyBundle, AReceivedBundleIsHeldToItsClaimedHash) {
  const PolicyBundle bundle = MakePolicyBundle(TrainedFiles());
  EXPECT_EQ(CheckPolicyBundle(ReceivedPolicyBundle(bundle.files, bundle.sha256)), "");
  EXPECT_EQ(CheckPolicyBundle(ReceivedPolicyBundle(bundle.files, std::string(64, 'a'))),
            "the policy does not match its sha256");
  std::vector<PolicyFile> tampered = bundle.files;
  tampered[2].data = "other weights";
  EXPECT_EQ(CheckPolicyBundle(ReceivedPolicyBundle(tampered, bundle.sha256)),
            "the policy does not match its sha256");
  std::vector<PolicyFile> unordered = bundle.files;
  std::swap(unordered[0], unordered[1]);
  EXPECT_EQ(CheckPolicyBundle(ReceivedPolicyBundle(unordered, bundle.sha256)),
            "policy files out of order or of another format");
  std::vector<PolicyFile> unknown = bundle.files;
  unknown.push_back({"run.sh", "#!/bin/sh"});
  EXPECT_EQ(CheckPolicyBundle(ReceivedPolicyBundle(unknown, bundle.sha256)),
            "a policy file that is none of the known names");
}

TEST(PolicyBundleFiles, AFolderIsPackedAndKeptByItsHash) {
  testing::TempDir dir;
  const std::string folder = dir.File("p1");
  std::filesystem::create_directories(folder);
  for (const auto& f : TrainedFiles())
    testing::WriteFile(folder + "/" + f.name, f.data);
  testing::WriteFile(folder + "/learning_curve.csv", "not packed");
  const PolicyBundle bundle = ReadPolicyBundle(folder);
  EXPECT_EQ(bundle.sha256, MakePolicyBundle(TrainedFiles()).sha256);

  const std::string root = dir.File("kept");
  const std::string kept = WritePolicyBundle(bundle, root);
  EXPECT_EQ(kept, root + "/" + bundle.sha256);
  EXPECT_EQ(ReadStoredPolicyBundle(root, bundle.sha256).files, bundle.files);
  // A damaged copy is not served, and is replaced when the bundle is written again.
  testing::WriteFile(kept + "/policy.pt", "damaged");
  EXPECT_THROW(ReadStoredPolicyBundle(root, bundle.sha256), std::runtime_error);
  WritePolicyBundle(bundle, root);
  EXPECT_EQ(ReadStoredPolicyBundle(root, bundle.sha256).files, bundle.files);
  EXPECT_THROW(ReadStoredPolicyBundle(root, "../" + bundle.sha256), std::runtime_error);
}

TEST(PolicyBundleFiles, FoldersThatHoldNoPolicyAreNamed) {
  testing::TempDir dir;
  const auto error = [](const std::string& folder) {
    try {
      ReadPolicyBundle(folder);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error(dir.File("none")), "policy folder \"" + dir.File("none") + "\" does not exist");
  std::filesystem::create_directories(dir.File("empty"));
  testing::WriteFile(dir.File("empty/learning_curve.csv"), "episode\n");
  EXPECT_NE(error(dir.File("empty")).find("holds no policy"), std::string::npos);
  std::filesystem::create_directories(dir.File("big"));
  std::ofstream(dir.File("big/policy.pt")) << std::string(kMaxPolicyBytes + 1, 'w');
  EXPECT_EQ(error(dir.File("big")), "policy folder \"" + dir.File("big") +
                                        "\" holds more than 16777216 bytes of policy files");
}

// An rl position job of urban3 flying `bundle`.
JobOrder RlPosition(const PolicyBundle& bundle) {
  std::ifstream in(testing::SourcePath("campaigns/scenarios/urban3.json"));
  JobOrder order;
  order.job_id = "c1/position/urban3/rl+p1";
  order.campaign_id = "c1";
  order.timeout_s = 60;
  order.params.kind = JobKind::kPosition;
  order.params.scenario = "urban3";
  order.params.positioner = "rl";
  order.params.policy_sha256 = bundle.sha256;
  order.policy = bundle;
  order.scenario_document.assign(std::istreambuf_iterator<char>(in), {});
  return order;
}

std::string ErrorOfOrder(const JobOrder& order) {
  try {
    CheckJobOrder(order, 3600);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PolicyBundleOrders, OnlyAnRlPositionJobCarriesItsOwnPolicy) {
  const PolicyBundle bundle = MakePolicyBundle(TrainedFiles());
  JobOrder order = RlPosition(bundle);
  EXPECT_EQ(ErrorOfOrder(order), "accepted");
  order.policy->files[2].data = "other weights";
  EXPECT_EQ(ErrorOfOrder(order), "policy: the policy does not match its sha256");
  order = RlPosition(
      MakePolicyBundle({{"model.pt", "zip"}, {"policy.json", "{}"}, {"scenario.json", "{}"}}));
  order.params.policy_sha256 = bundle.sha256;
  EXPECT_EQ(ErrorOfOrder(order), "policy: not the job's policy " + bundle.sha256);
  order = RlPosition(bundle);
  order.policy.reset();
  EXPECT_EQ(ErrorOfOrder(order), "policy: the job's is missing");
  order = RlPosition(bundle);
  order.params.policy_sha256.clear();
  EXPECT_EQ(ErrorOfOrder(order), "policy_sha256: an rl position job needs its policy's sha256");
  order = RlPosition(bundle);
  order.params.positioner = "oracle";
  EXPECT_EQ(ErrorOfOrder(order), "policy_sha256: only an rl position or track job has one");
  order.params.policy_sha256.clear();
  EXPECT_EQ(ErrorOfOrder(order), "policy: only an rl position or track job carries one");
}

}  // namespace
}  // namespace rlpos
