#pragma once
// The colours and markers of a map, in one place: the drawing uses them, and the tests look for
// them in the pixels. Colours are the Okabe-Ito set (told apart by colour-blind readers too);
// buildings are a grey ramp, darker when taller.
#include <cstdint>
#include <string>

namespace rlpos::map {

struct Rgb {
  double r = 0, g = 0, b = 0;  // 0..1
  // From 0xRRGGBB.
  static constexpr Rgb Hex(std::uint32_t hex) {
    return {((hex >> 16) & 0xff) / 255.0, ((hex >> 8) & 0xff) / 255.0, (hex & 0xff) / 255.0};
  }
  // The 8-bit channel values, as a PNG stores them.
  std::uint32_t ToHex() const;
};

constexpr Rgb kBackground = Rgb::Hex(0xffffff);
constexpr Rgb kGround = Rgb::Hex(0xfbfaf5);  // the venue's floor
constexpr Rgb kGrid = Rgb::Hex(0xe4e2da);
constexpr Rgb kInk = Rgb::Hex(0x202020);        // text, axes, outlines
constexpr Rgb kZone = Rgb::Hex(0x7a5195);       // the UAVs' zone, dashed
constexpr Rgb kLos = Rgb::Hex(0x009e73);        // a UE in line of sight of its UAV
constexpr Rgb kNlos = Rgb::Hex(0xd55e00);       // a UE behind a building
constexpr Rgb kUeNeutral = Rgb::Hex(0x8c8c8c);  // UEs on a map of several placements
constexpr Rgb kFlight = Rgb::Hex(0x6a3d9a);     // the rl flight path
constexpr Rgb kUePath = Rgb::Hex(0x4f8fbf);     // the paths moving UEs walk

// A building of `height` in a venue `max_height` high: light grey (low) to dark slate (tall).
Rgb BuildingColour(double height, double max_height);
// Whether text on that building is drawn white (dark fill) rather than black.
bool BuildingTextIsLight(double height, double max_height);

// The colour of UAV `i` on a map of several UAVs (and of the UEs it serves).
Rgb UavColour(int i);

enum class MarkerShape {
  kCircle,
  kSquare,
  kTriangleUp,
  kDiamond,
  kTriangleDown,
  kPentagon,
  kPlus,
  kCross,
  kStar
};

// The marker of the i-th placement on a map of several: no two of the first 9 share a shape,
// no two of the first 8 a colour.
struct PlacementStyle {
  MarkerShape shape = MarkerShape::kCircle;
  Rgb colour;
};
PlacementStyle PlacementStyleOf(int i);

// The one font of every map (Debian's fonts-dejavu-core), so that maps are the same bytes on
// every machine that has it.
constexpr const char* kFontFamily = "DejaVu Sans";

}  // namespace rlpos::map
