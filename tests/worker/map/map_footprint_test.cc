// Footprint buildings on a map are their exact shapes: from above, the ground shows in an L's
// notch and in a courtyard; from a side, a footprint is its extent between min_height and
// height. Their labels go where the shape is, not the bounding box's centre.
#include <gtest/gtest.h>

#include "common/scenario/building_obstacles.h"
#include "common/scenario/scenario_parser.h"
#include "tests/worker/map/map_image.h"
#include "worker/map/map_render.h"
#include "worker/map/map_shapes.h"
#include "worker/map/map_style.h"

namespace rlpos::map {
namespace {

using rlpos::map::testing::Image;

// The points looked at stay off the grid (every 10 m). ell: the L (10, 10)-(40, 10)-(40, 20)-(20,
// 20)-(20, 40)-(10, 40), 20 m; courtyard: 55-90 x 55-90 less 65-80 x 65-80, 30 m; bridge: 44-52 x
// 60-66 between 8 and 14 m.
MapScene FootprintScene(bool side) {
  MapScene scene;
  scene.scenario = ParseScenario(
      ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/tests/worker/map/footprints.json"));
  scene.placements = {{"baseline", scene.scenario.InitialPlacement()}};
  scene.side_views = side;
  return scene;
}

const BuildingSpec& Named(const Scenario& s, const std::string& name) {
  for (const auto& b : s.buildings) {
    if (b.name == name)
      return b;
  }
  throw std::logic_error("no building " + name);
}

TEST(MapFootprints, TopViewDrawsTheExactShapes) {
  const MapScene scene = FootprintScene(false);
  const Image image(RenderMap(scene, MapFormat::kPng));
  ASSERT_TRUE(image.ok());
  const View& top = LayoutOf(scene).top;
  const std::uint32_t ell = BuildingColour(20, 60).ToHex();
  const std::uint32_t courtyard = BuildingColour(30, 60).ToHex();
  // In the L's bounding box but off the L: ground.
  EXPECT_EQ(image.At(top, {31, 29, 0}), kGround.ToHex());
  EXPECT_EQ(image.At(top, {36, 26, 0}), kGround.ToHex());
  // Inside its walls, in both arms.
  EXPECT_EQ(image.At(top, {15, 35, 0}), ell);
  EXPECT_EQ(image.At(top, {37, 12, 0}), ell);
  // The courtyard is ground; the wings around it are the building.
  EXPECT_EQ(image.At(top, {72.5, 72.5, 0}), kGround.ToHex());
  EXPECT_EQ(image.At(top, {68, 77, 0}), kGround.ToHex());
  EXPECT_EQ(image.At(top, {61, 72.5, 0}), courtyard);
  EXPECT_EQ(image.At(top, {85, 72.5, 0}), courtyard);
  EXPECT_EQ(image.At(top, {72.5, 87, 0}), courtyard);
}

// From the south the courtyard is hidden by its south wing, and the bridge stands on nothing.
TEST(MapFootprints, SideViewsDrawTheSilhouette) {
  const MapScene scene = FootprintScene(true);
  const Image image(RenderMap(scene, MapFormat::kPng));
  ASSERT_TRUE(image.ok());
  const MapLayout layout = LayoutOf(scene);
  ASSERT_TRUE(layout.side);
  EXPECT_EQ(image.At(layout.xz, {72.5, 0, 25}), BuildingColour(30, 60).ToHex());
  EXPECT_EQ(image.At(layout.xz, {33, 0, 15}), BuildingColour(20, 60).ToHex());
  EXPECT_EQ(image.At(layout.xz, {47, 0, 11}), BuildingColour(14, 60).ToHex());
  EXPECT_EQ(image.At(layout.xz, {47, 0, 5}), kGround.ToHex());
  EXPECT_EQ(image.At(layout.xz, {47, 0, 17}), kGround.ToHex());
  // From the east the L's notch is hidden too: its extent spans 10-40 up to 20 m.
  EXPECT_EQ(image.At(layout.yz, {0, 33, 15}), BuildingColour(20, 60).ToHex());
}

// The L's bounding-box centre (25, 25) and its centroid (21, 21) lie in the notch: its label
// goes in an arm, centred across it.
TEST(MapFootprints, LabelPointsLieInsideTheShape) {
  const Scenario s = FootprintScene(false).scenario;
  for (const auto& b : s.buildings) {
    const std::vector<Point2> points = LabelPoints(b);
    ASSERT_FALSE(points.empty()) << b.name;
    for (const Point2& p : points)
      EXPECT_TRUE(GroundShapeHolds(b, p.x, p.y)) << b.name << " (" << p.x << ", " << p.y << ")";
  }
  const Point2 ell = LabelPoints(Named(s, "ell")).front();
  EXPECT_DOUBLE_EQ(ell.y, 15.0);
  EXPECT_GT(ell.x, 20.0);
  const Point2 wing = LabelPoints(Named(s, "courtyard")).front();
  EXPECT_FALSE(wing.x > 65 && wing.x < 80 && wing.y > 65 && wing.y < 80);
  // A box: its centre, as before footprints.
  BuildingSpec box;
  box.xmin = 10, box.xmax = 30, box.ymin = 40, box.ymax = 44;
  const std::vector<Point2> centre = LabelPoints(box);
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_EQ(centre[0].x, 20.0);
  EXPECT_EQ(centre[0].y, 42.0);
}

TEST(MapFootprints, RectangleInsideTheShape) {
  const Footprint courtyard = GroundShape(Named(FootprintScene(false).scenario, "courtyard"));
  EXPECT_TRUE(RectangleInside(courtyard, {56, 56, 89, 64}));   // the south wing
  EXPECT_TRUE(RectangleInside(courtyard, {55, 55, 90, 65}));   // all of it, edges touching
  EXPECT_FALSE(RectangleInside(courtyard, {56, 56, 89, 70}));  // into the courtyard
  EXPECT_FALSE(RectangleInside(courtyard, {60, 60, 85, 85}));  // around it: corners inside
  EXPECT_FALSE(RectangleInside(courtyard, {50, 56, 60, 60}));  // past the outer ring
}

}  // namespace
}  // namespace rlpos::map
