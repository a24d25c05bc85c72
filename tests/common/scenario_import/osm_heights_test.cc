// Heights as OpenStreetMap writes them, and the order of their sources.
#include "common/scenario_import/osm_heights.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

PlaceFeature FeatureWith(std::map<std::string, std::string> tags) {
  PlaceFeature f;
  f.source = "way 1";
  f.tags = std::move(tags);
  return f;
}

TEST(OsmHeights, LengthsWithAndWithoutUnits) {
  EXPECT_DOUBLE_EQ(*ParseOsmLength("12"), 12);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("12 m"), 12);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("12.5m"), 12.5);
  EXPECT_DOUBLE_EQ(*ParseOsmLength(" 7 metres"), 7);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("40 ft"), 40 * 0.3048);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("40'"), 40 * 0.3048);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("40 feet"), 40 * 0.3048);
  EXPECT_DOUBLE_EQ(*ParseOsmLength("40'6\""), 40 * 0.3048 + 6 * 0.0254);
  EXPECT_DOUBLE_EQ(*ParseOsmLength(".5"), 0.5);
}

TEST(OsmHeights, TextThatIsNotALength) {
  for (const char* text : {"tall", "12;15", "12,5", "-3", "", "12 yards", "1e3", "40'6", "nan"})
    EXPECT_FALSE(ParseOsmLength(text)) << text;
  EXPECT_FALSE(ParseOsmLevels("5 floors"));
  EXPECT_DOUBLE_EQ(*ParseOsmLevels("2.5"), 2.5);
}

TEST(OsmHeights, HeightThenLevelsThenDefault) {
  std::vector<ImportWarning> warnings;
  const HeightRules rules;
  ResolvedHeight h =
      ResolveHeight(FeatureWith({{"height", "18.03"}, {"building:levels", "5"}}), rules, warnings);
  EXPECT_EQ(h.source, HeightSource::kHeight);
  EXPECT_DOUBLE_EQ(h.height, 18.03);
  EXPECT_EQ(h.floors, 5);  // the levels count the floors even where height sets the top
  h = ResolveHeight(FeatureWith({{"building:levels", "7"}}), rules, warnings);
  EXPECT_EQ(h.source, HeightSource::kLevels);
  EXPECT_DOUBLE_EQ(h.height, 21);
  h = ResolveHeight(FeatureWith({}), rules, warnings);
  EXPECT_EQ(h.source, HeightSource::kDefault);
  EXPECT_DOUBLE_EQ(h.height, 10);
  EXPECT_EQ(h.floors, 3);
  EXPECT_TRUE(warnings.empty());
  h = ResolveHeight(FeatureWith({}), HeightRules{4.0, 25.0}, warnings);
  EXPECT_DOUBLE_EQ(h.height, 25);
  EXPECT_EQ(h.floors, 6);
}

TEST(OsmHeights, PartsStartAboveTheGround) {
  std::vector<ImportWarning> warnings;
  ResolvedHeight h =
      ResolveHeight(FeatureWith({{"building:levels", "8"}, {"building:min_level", "2"}}),
                    HeightRules{}, warnings);
  EXPECT_DOUBLE_EQ(h.min_height, 6);
  EXPECT_DOUBLE_EQ(h.height, 24);
  EXPECT_EQ(h.floors, 6);
  h = ResolveHeight(FeatureWith({{"height", "40 m"}, {"min_height", "37"}}), HeightRules{},
                    warnings);
  EXPECT_DOUBLE_EQ(h.min_height, 37);
  EXPECT_EQ(h.floors, 1);
  EXPECT_TRUE(warnings.empty());
}

TEST(OsmHeights, BadValuesFallBackWithAWarning) {
  std::vector<ImportWarning> warnings;
  ResolvedHeight h = ResolveHeight(FeatureWith({{"height", "tall"}, {"building:levels", "4"}}),
                                   HeightRules{}, warnings);
  EXPECT_EQ(h.source, HeightSource::kLevels);
  EXPECT_DOUBLE_EQ(h.height, 12);
  EXPECT_EQ(h.bad_values, 1);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].path, "way 1");
  EXPECT_EQ(warnings[0].message,
            "height \"tall\" is not a height in metres or feet: building:levels is used");
  warnings.clear();
  h = ResolveHeight(FeatureWith({{"height", "0"}, {"building:levels", "none"}}), HeightRules{},
                    warnings);
  EXPECT_EQ(h.source, HeightSource::kDefault);
  EXPECT_EQ(h.bad_values, 2);
  warnings.clear();
  h = ResolveHeight(FeatureWith({{"height", "9"}, {"min_height", "12"}}), HeightRules{}, warnings);
  EXPECT_DOUBLE_EQ(h.min_height, 0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message,
            "its bottom (12 m) is not below its top (9 m): it stands on the ground");
}

}  // namespace
}  // namespace rlpos
