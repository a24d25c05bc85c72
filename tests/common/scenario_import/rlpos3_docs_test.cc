// docs/rlpos3-import.md's table names every field of the test config, so a field the import
// learns to read (or to warn about) cannot go undocumented.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "tests/common/scenario_import/rlpos3_config.h"

namespace rlpos {
namespace {

// Every key of `v`, below objects the docs name as a whole (their keys are RLpos-3's own).
void CollectKeys(const nlohmann::json& v, std::set<std::string>& keys) {
  if (v.is_array()) {
    for (const auto& item : v)
      CollectKeys(item, keys);
    return;
  }
  if (!v.is_object())
    return;
  for (auto it = v.begin(); it != v.end(); ++it) {
    keys.insert(it.key());
    if (it.key() != "StartScript" && it.key() != "logLevels")
      CollectKeys(it.value(), keys);
  }
}

TEST(Rlpos3Docs, TableNamesEveryFieldOfTheTestConfig) {
  std::ifstream in(std::string(RLPOS_SOURCE_DIR) + "/docs/rlpos3-import.md");
  ASSERT_TRUE(in) << "docs/rlpos3-import.md";
  std::stringstream page;
  page << in.rdbuf();
  std::set<std::string> keys;
  CollectKeys(FullRlpos3Config(), keys);
  keys.erase("experiment");  // the test's unknown key: "any other key"
  for (const std::string& key : keys) {
    // `key`, `Parent.key`, `key.Child` or `key[]`.
    const std::regex named("[`.]" + key + "[`.\\[]");
    EXPECT_TRUE(std::regex_search(page.str(), named)) << key << " is not in the docs' table";
  }
}

}  // namespace
}  // namespace rlpos
