// A map shows what the scenario holds: rendered to PNG and read back, a building's colour is
// seen inside each footprint and nowhere else, a UE known to be in LoS (or not) has that colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>

#include "common/config/config_error.h"
#include "common/scenario/building_obstacles.h"
#include "tests/worker/map/map_image.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/map/map_links.h"
#include "worker/map/map_render.h"
#include "worker/map/map_style.h"
#include "worker/map/trajectory_csv.h"

namespace rlpos::map {
namespace {

namespace fs = std::filesystem;

const std::string kScenarios = std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios";

using rlpos::map::testing::Image;

MapScene BaselineScene(const std::string& file, bool side = false) {
  MapScene scene;
  scene.scenario = LoadScenario(file, {});
  scene.placements = {{"baseline", scene.scenario.InitialPlacement()}};
  scene.side_views = side;
  AddLinks(scene);
  return scene;
}

std::vector<std::string> ShippedScenarios() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(kScenarios)) {
    if (entry.path().extension() == ".json")
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// How far (m) (x, y) lies from the nearest edge of any building's ground shape.
double DistanceToAnEdge(const Scenario& s, double x, double y) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& b : s.buildings) {
    const Footprint shape = GroundShape(b);
    std::vector<const Ring*> rings{&shape.outer};
    for (const Ring& hole : shape.holes)
      rings.push_back(&hole);
    for (const Ring* ring : rings) {
      for (std::size_t k = 0; k < ring->size(); ++k) {
        const Point2& a = (*ring)[k];
        const Point2& c = (*ring)[(k + 1) % ring->size()];
        const double dx = c.x - a.x, dy = c.y - a.y, length2 = dx * dx + dy * dy;
        const double t =
            length2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
        nearest = std::min(nearest, std::hypot(x - a.x - t * dx, y - a.y - t * dy));
      }
    }
  }
  return nearest;
}

// The building the top view shows at (x, y): of those whose shape holds it, the one drawn last
// (the tallest; of equal heights, the later); -1 for none.
int TopBuildingAt(const Scenario& s, double x, double y) {
  int top = -1;
  for (std::size_t i = 0; i < s.buildings.size(); ++i) {
    if (GroundShapeHolds(s.buildings[i], x, y) &&
        (top < 0 || s.buildings[i].height >= s.buildings[static_cast<std::size_t>(top)].height))
      top = static_cast<int>(i);
  }
  return top;
}

// Clear of every building's outline (0.8 pt of ink) by 2 points, and by 1 m at least.
double EdgeMargin(const View& view) {
  return std::max(1.0, 2.0 / view.scale);
}

// Where each building shows (its shape less what taller ones cover, away from edges; a 7 x 7
// grid over its bounding box), the ground never does; and most such points over the scenario
// show the building's own colour, the rest being under a label, a link or a marker (a real
// place's small buildings are crowded with the labels that do not fit in them).
void ExpectBuildingsWhereTheScenarioPutsThem(const MapScene& scene, const Image& image,
                                             const View& view) {
  const Scenario& s = scene.scenario;
  int seen = 0, shown = 0;
  for (std::size_t i = 0; i < s.buildings.size(); ++i) {
    const BuildingSpec& b = s.buildings[i];
    const std::uint32_t colour = BuildingColour(b.height, s.venue.height).ToHex();
    for (int u = 1; u <= 7; ++u) {
      for (int v = 1; v <= 7; ++v) {
        const Vec3 p{b.xmin + (b.xmax - b.xmin) * u / 8.0, b.ymin + (b.ymax - b.ymin) * v / 8.0, 0};
        if (TopBuildingAt(s, p.x, p.y) != static_cast<int>(i) ||
            DistanceToAnEdge(s, p.x, p.y) < EdgeMargin(view))
          continue;
        ++shown;
        const std::uint32_t pixel = image.At(view, p);
        seen += pixel == colour ? 1 : 0;
        EXPECT_TRUE(pixel != kGround.ToHex() && pixel != kGrid.ToHex())
            << s.name << ": the ground shows in building " << b.name << " at (" << p.x << ", "
            << p.y << ")";
      }
    }
  }
  EXPECT_TRUE(shown == 0 || 2 * seen > shown)
      << s.name << ": the buildings show their colours at " << seen << " of " << shown << " points";
}

// Every 2 m over the venue, off the buildings' shapes and away from their edges (an L's notch,
// a courtyard): no building colour.
void ExpectNoBuildingElsewhere(const MapScene& scene, const Image& image, const View& view) {
  const Scenario& s = scene.scenario;
  std::vector<std::uint32_t> colours;
  for (const auto& b : s.buildings)
    colours.push_back(BuildingColour(b.height, s.venue.height).ToHex());
  int checked = 0;
  for (double x = 1; x < s.venue.width; x += 2) {
    for (double y = 1; y < s.venue.depth; y += 2) {
      if (TopBuildingAt(s, x, y) >= 0 || DistanceToAnEdge(s, x, y) < EdgeMargin(view))
        continue;
      const std::uint32_t pixel = image.At(view, {x, y, 0});
      ++checked;
      EXPECT_EQ(std::count(colours.begin(), colours.end(), pixel), 0)
          << s.name << ": a building's colour at (" << x << ", " << y << ")";
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(Map, EveryShippedScenarioShowsItsBuildings) {
  const auto files = ShippedScenarios();
  ASSERT_GE(files.size(), 5u);
  for (const auto& file : files) {
    const MapScene scene = BaselineScene(file);
    const Image image(RenderMap(scene, MapFormat::kPng));
    ASSERT_TRUE(image.ok()) << file;
    const MapLayout layout = LayoutOf(scene);
    EXPECT_EQ(image.width(), static_cast<int>(std::ceil(layout.width * kPngPixelsPerPoint)));
    ExpectBuildingsWhereTheScenarioPutsThem(scene, image, layout.top);
    ExpectNoBuildingElsewhere(scene, image, layout.top);
  }
}

// Scenario C at its baseline, the UAV 25 m over the tower (45-55 x 45-55, 20 m): ue3 at (5, 15)
// sees it over the tower's roof (the line crosses x = 45 at 22.4 m); ue0 at (85, 25) does not,
// the east hall (72-80 x 30-70, 15 m) is in the way (the line enters it at 6.2 m).
TEST(Map, UeMarkersHaveTheirLinksColour) {
  const MapScene scene = BaselineScene(kScenarios + "/c.json");
  const Image image(RenderMap(scene, MapFormat::kPng));
  ASSERT_TRUE(image.ok());
  const View& top = LayoutOf(scene).top;
  const auto colour_of = [&](const std::string& name) {
    for (const auto& ue : scene.scenario.ues) {
      if (ue.name == name)
        return image.At(top.CanvasX(ue.position), top.CanvasY(ue.position));
    }
    ADD_FAILURE() << "no UE " << name;
    return 0u;
  };
  EXPECT_EQ(colour_of("ue3"), kLos.ToHex());
  EXPECT_EQ(colour_of("ue0"), kNlos.ToHex());
  EXPECT_EQ(colour_of("ue2"), kNlos.ToHex());
}

// With several UAVs a UE has its serving UAV's colour.
TEST(Map, SeveralUavsColourTheUesByServingUav) {
  const MapScene scene = BaselineScene(kScenarios + "/campus2.json");
  const Image image(RenderMap(scene, MapFormat::kPng));
  const View& top = LayoutOf(scene).top;
  ASSERT_EQ(scene.links.size(), scene.scenario.ues.size());
  for (std::size_t i = 0; i < scene.links.size(); ++i) {
    const Vec3& p = scene.scenario.ues[i].position;
    EXPECT_EQ(image.At(top.CanvasX(p), top.CanvasY(p)),
              UavColour(scene.links[i].serving_uav).ToHex())
        << scene.scenario.ues[i].name;
  }
}

// Seen from the south, the south block (y 18-26, 25 m) stands before the tower (y 45-55, 20 m);
// seen from the east, the east hall (x 72-80, 15 m) before the tower.
TEST(Map, ElevationViewsDrawTheNearestBuildingInFront) {
  const MapScene scene = BaselineScene(kScenarios + "/c.json", true);
  const Image image(RenderMap(scene, MapFormat::kPng));
  const MapLayout layout = LayoutOf(scene);
  ASSERT_TRUE(layout.side);
  EXPECT_EQ(image.height(), static_cast<int>(std::ceil(layout.height * kPngPixelsPerPoint)));
  const Vec3 p{50, 50, 12};
  EXPECT_EQ(image.At(layout.xz.CanvasX(p), layout.xz.CanvasY(p)), BuildingColour(25, 60).ToHex());
  EXPECT_EQ(image.At(layout.yz.CanvasX(p), layout.yz.CanvasY(p)), BuildingColour(15, 60).ToHex());
  const Vec3 sky{52, 50, 45};  // off the grid lines
  EXPECT_EQ(image.At(layout.xz.CanvasX(sky), layout.xz.CanvasY(sky)), kGround.ToHex());
}

// A moving UE's path is a blue line on the open ground (north of C's north block, y 70-78).
TEST(Map, UePathsAreDrawn) {
  MapScene scene = BaselineScene(kScenarios + "/c.json");
  const View& top = LayoutOf(scene).top;
  const Vec3 on_path{23, 87, 1.5};
  const auto pixel = [&] {
    const Image image(RenderMap(scene, MapFormat::kPng));
    return image.At(top.CanvasX(on_path), top.CanvasY(on_path));
  };
  EXPECT_EQ(pixel(), kGround.ToHex());
  scene.ue_paths = {{{5, 87, 1.5}, {40, 87, 1.5}}, {}, {}, {}};
  const std::uint32_t drawn = pixel();
  const int red = static_cast<int>(drawn >> 16), blue = static_cast<int>(drawn & 0xff);
  EXPECT_GT(blue - red, 40) << std::hex << drawn;
}

TEST(Map, SvgIsTheSameBytesEachTime) {
  MapScene scene = BaselineScene(kScenarios + "/urban3.json", true);
  const std::string first = RenderMap(scene, MapFormat::kSvg);
  EXPECT_EQ(first.rfind("<?xml", 0), 0u);
  EXPECT_NE(first.find("<svg"), std::string::npos);
  // Cairo numbers its surfaces process-wide; the SVG must not show it.
  EXPECT_TRUE(RenderMap(scene, MapFormat::kSvg) == first);
  EXPECT_TRUE(RenderMap(scene, MapFormat::kPng) == RenderMap(scene, MapFormat::kPng));
}

TEST(Map, FormatFromTheExtension) {
  EXPECT_EQ(MapFormatOf("maps/c.PNG", "--out"), MapFormat::kPng);
  EXPECT_EQ(MapFormatOf("c.svg", "--out"), MapFormat::kSvg);
  for (const char* bad : {"c.jpg", "c", "png", "dir.svg/c"}) {
    EXPECT_THROW(MapFormatOf(bad, "--out"), ConfigError) << bad;
  }
}

class TrajectoryCsv : public ::testing::Test {
 protected:
  void SetUp() override { scenario_ = LoadScenario(kScenarios + "/c.json", {}); }
  std::string Write(const std::string& text) {
    const std::string file = ::testing::TempDir() + "/trajectory.csv";
    std::ofstream(file) << text;
    return file;
  }
  std::string ErrorOf(const std::string& text) {
    try {
      ReadTrajectoryCsv(Write(text), scenario_, "--trajectory");
    } catch (const ConfigError& e) {
      return e.describe();
    }
    return "no error";
  }
  Scenario scenario_;
};

TEST_F(TrajectoryCsv, ReadsTheLastEpisodeFromTheStart) {
  const std::string header = "episode,step,uav,action,x,y,z,n_los,throughput_mbps,reward\n";
  const Flight f = ReadTrajectoryCsv(Write(header + "11,1,0,up,50,50,30,1,10,0.1\n"
                                                    "12,1,0,right,55,50,25,1,10,0.1\n"
                                                    "12,2,0,right,60,50,25,2,20,0.2\n"),
                                     scenario_, "--trajectory");
  EXPECT_EQ(f.episode, 12);
  ASSERT_EQ(f.paths.size(), 1u);
  ASSERT_EQ(f.paths[0].points.size(), 3u);  // the baseline, then the two moves
  EXPECT_EQ(f.paths[0].points[0].x, 50);
  EXPECT_EQ(f.paths[0].points[2].x, 60);
}

TEST_F(TrajectoryCsv, BadFilesAreNamedErrors) {
  EXPECT_NE(ErrorOf("episode,step,x,y,z\n1,1,5,5,5\n").find("no column \"uav\""),
            std::string::npos);
  EXPECT_NE(
      ErrorOf("episode,uav,x,y,z\n1,0,5,oops,5\n").find("line 2: a cell that is not a number"),
      std::string::npos);
  EXPECT_NE(ErrorOf("episode,uav,x,y,z\n1,3,5,5,5\n").find("UAV 3 is not one of the 1"),
            std::string::npos);
  EXPECT_NE(ErrorOf("episode,uav,x,y,z\n").find("no steps"), std::string::npos);
  try {
    ReadTrajectoryCsv("/nonexistent/trajectory.csv", scenario_, "--trajectory");
    ADD_FAILURE();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(), "--trajectory: /nonexistent/trajectory.csv: cannot open file");
  }
}

}  // namespace
}  // namespace rlpos::map
