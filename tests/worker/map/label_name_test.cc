// A building's label on a map: an imported building's element id is not a name.
#include <gtest/gtest.h>

#include "worker/map/map_painter.h"

namespace rlpos::map {
namespace {

TEST(BuildingLabelName, DropsTheElementIdOfAnImportedBuilding) {
  EXPECT_EQ(BuildingLabelName("Rautatalo (way/34079465)"), "Rautatalo");
  EXPECT_EQ(BuildingLabelName("Erottajan paloasema (relation/167018)"), "Erottajan paloasema");
  EXPECT_EQ(BuildingLabelName("Suomen Pankki (way/12) #2"), "Suomen Pankki #2");
  EXPECT_EQ(BuildingLabelName("Tower (feature/3)"), "Tower");
}

TEST(BuildingLabelName, AnIdAloneIsNoLabel) {
  EXPECT_EQ(BuildingLabelName("way/22338006"), "");
  EXPECT_EQ(BuildingLabelName("relation/1689684"), "");
  EXPECT_EQ(BuildingLabelName("feature/3 #2"), "");
}

TEST(BuildingLabelName, OtherNamesStayAsTheyAre) {
  for (const char* name : {"tower", "lab (north)", "way/north", "way/", "Block #a", "(way/1)",
                           "hall (way/1x)", "way/12 annex"})
    EXPECT_EQ(BuildingLabelName(name), name);
}

}  // namespace
}  // namespace rlpos::map
