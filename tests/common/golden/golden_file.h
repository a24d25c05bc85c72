#pragma once
// A golden file under tests/common/golden/data/ compared with what the code writes now, or
// written anew when RLPOS_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <set>
#include <string>

namespace rlpos::golden {

// The folder of the golden files, in the source tree.
std::string GoldenDir();
// The golden file's path as the repository names it ("tests/common/golden/data/<name>").
std::string RepositoryPath(const std::string& name);

// True when RLPOS_UPDATE_GOLDEN=1: golden files are written, not compared.
bool UpdatingGolden();

// `actual` against the golden file `name` (relative to GoldenDir()). A failure names the file
// and shows its first differing line, golden and now; when updating, writes the file instead.
::testing::AssertionResult MatchesGolden(const std::string& name, const std::string& actual);

// The first line where `golden` and `actual` differ, both shown, long lines clipped around the
// first differing column; "" when they are equal.
std::string FirstDifference(const std::string& golden, const std::string& actual);

// Every golden file under GoldenDir(), by name relative to it.
std::set<std::string> GoldenFilesOnDisk();

}  // namespace rlpos::golden
