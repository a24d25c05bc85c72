#include "tests/common/golden/golden_file.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace rlpos::golden {
namespace {

namespace fs = std::filesystem;

constexpr const char* kGoldenFolder = "tests/common/golden/data";
// Lines of canonical JSON run to kilobytes: the message shows this much of each around the
// first differing column.
constexpr std::size_t kShownBefore = 60;
constexpr std::size_t kShownWidth = 140;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string Clipped(const std::string& line, std::size_t column) {
  if (line.size() <= kShownWidth)
    return line;
  const std::size_t first = column > kShownBefore ? column - kShownBefore : 0;
  std::string shown = line.substr(first, kShownWidth);
  if (first > 0)
    shown = "..." + shown;
  if (first + kShownWidth < line.size())
    shown += "...";
  return shown;
}

std::string ReadWhole(const std::string& path, bool& found) {
  std::ifstream in(path, std::ios::binary);
  found = static_cast<bool>(in);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string GoldenDir() {
  return std::string(RLPOS_SOURCE_DIR) + "/" + kGoldenFolder;
}

std::string RepositoryPath(const std::string& name) {
  return std::string(kGoldenFolder) + "/" + name;
}

bool UpdatingGolden() {
  const char* update = std::getenv("RLPOS_UPDATE_GOLDEN");
  return update != nullptr && std::string(update) == "1";
}

std::string FirstDifference(const std::string& golden, const std::string& actual) {
  if (golden == actual)
    return "";
  const std::vector<std::string> expected_lines = Lines(golden);
  const std::vector<std::string> actual_lines = Lines(actual);
  const std::size_t common = std::min(expected_lines.size(), actual_lines.size());
  std::size_t line = 0;
  while (line < common && expected_lines[line] == actual_lines[line])
    ++line;
  std::ostringstream out;
  if (line == common && expected_lines.size() == actual_lines.size()) {
    // Same lines: only the final newline differs.
    out << "the same lines, but the golden file "
        << (golden.back() == '\n' ? "ends" : "does not end") << " with a newline and the text now "
        << (actual.back() == '\n' ? "does" : "does not");
    return out.str();
  }
  const std::string none = "(the text ends before this line)";
  const std::string& g = line < expected_lines.size() ? expected_lines[line] : none;
  const std::string& a = line < actual_lines.size() ? actual_lines[line] : none;
  std::size_t column = 0;
  while (column < std::min(g.size(), a.size()) && g[column] == a[column])
    ++column;
  out << "first difference at line " << line + 1 << ", column " << column + 1 << ":\n"
      << "  golden: " << Clipped(g, column) << "\n"
      << "  now:    " << Clipped(a, column);
  return out.str();
}

::testing::AssertionResult MatchesGolden(const std::string& name, const std::string& actual) {
  const std::string path = GoldenDir() + "/" + name;
  if (UpdatingGolden()) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << actual;
    out.close();
    if (!out)
      return ::testing::AssertionFailure() << "cannot write " << RepositoryPath(name);
    return ::testing::AssertionSuccess();
  }
  bool found = false;
  const std::string golden = ReadWhole(path, found);
  if (!found) {
    return ::testing::AssertionFailure()
           << RepositoryPath(name)
           << " is missing; write it with RLPOS_UPDATE_GOLDEN=1 (tests/common/golden/"
              "serialised_golden_test.cc)";
  }
  const std::string difference = FirstDifference(golden, actual);
  if (difference.empty())
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << RepositoryPath(name) << " differs from what the code writes now; " << difference
         << "\nIf the change is meant: RLPOS_UPDATE_GOLDEN=1 build/bin/rlpos_common_golden_tests, "
            "then review git diff "
         << kGoldenFolder;
}

std::set<std::string> GoldenFilesOnDisk() {
  std::set<std::string> names;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(GoldenDir(), ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->is_regular_file())
      names.insert(fs::relative(it->path(), GoldenDir()).generic_string());
  }
  return names;
}

}  // namespace rlpos::golden
