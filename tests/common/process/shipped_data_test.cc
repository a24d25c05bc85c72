#include "common/process/shipped_data.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/process/executable_path.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;

// The test program lives in build/bin, beside build/share/rlpos and its links to the checkout.
fs::path Share() {
  return fs::path(ExecutableDir()).parent_path() / "share" / "rlpos";
}

TEST(ResolveShipped, NamesTheShippedScenarioWithOrWithoutJson) {
  const fs::path b = (Share() / "campaigns" / "scenarios" / "b.json").lexically_normal();
  ASSERT_TRUE(fs::exists(b)) << b;
  EXPECT_EQ(ResolveShipped("b", ShippedKind::kScenario), b.string());
  EXPECT_EQ(ResolveShipped("b.json", ShippedKind::kScenario), b.string());
}

TEST(ResolveShipped, NamesTheShippedPolicyFolder) {
  const fs::path policy = (Share() / "policies" / "generalist-1uav").lexically_normal();
  ASSERT_TRUE(fs::is_directory(policy)) << policy;
  EXPECT_EQ(ResolveShipped("generalist-1uav", ShippedKind::kPolicy), policy.string());
  // A policy is a folder: no ".json" is tried.
  EXPECT_EQ(ResolveShipped("b", ShippedKind::kPolicy), "b");
}

TEST(ResolveShipped, LeavesPathsEmptyAndUnknownNamesAsGiven) {
  EXPECT_EQ(ResolveShipped("", ShippedKind::kScenario), "");
  EXPECT_EQ(ResolveShipped("./b.json", ShippedKind::kScenario), "./b.json");
  EXPECT_EQ(ResolveShipped("scenarios/b.json", ShippedKind::kScenario), "scenarios/b.json");
  EXPECT_EQ(ResolveShipped("no-such-scenario", ShippedKind::kScenario), "no-such-scenario");
}

TEST(ResolveShipped, AFileOfThatNameHereWins) {
  const fs::path here = fs::temp_directory_path() / ("rlpos-shipped-" + std::to_string(::getpid()));
  fs::create_directories(here);
  const fs::path before = fs::current_path();
  fs::current_path(here);
  { std::ofstream("b") << "{}"; }
  const std::string resolved = ResolveShipped("b", ShippedKind::kScenario);
  fs::current_path(before);
  fs::remove_all(here);
  EXPECT_EQ(resolved, "b");
}

}  // namespace
}  // namespace rlpos
