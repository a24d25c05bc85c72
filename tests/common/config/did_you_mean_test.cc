#include "common/config/did_you_mean.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(EditDistance("", ""), 0u);
  EXPECT_EQ(EditDistance("abc", "abc"), 0u);
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(EditDistance("Width", "width"), 0u);  // case-insensitive
}

TEST(ClosestMatch, SuggestsOnlyPlausibleTypos) {
  const std::vector<std::string> keys = {"width", "depth", "height"};
  EXPECT_EQ(ClosestMatch("widht", keys), "width");
  EXPECT_EQ(ClosestMatch("heigth", keys), "height");
  EXPECT_EQ(ClosestMatch("colour", keys), "");
}

}  // namespace
}  // namespace rlpos
