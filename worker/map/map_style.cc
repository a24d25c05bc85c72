#include "worker/map/map_style.h"

#include <algorithm>
#include <cmath>

namespace rlpos::map {
namespace {

constexpr Rgb kBuildingLow = Rgb::Hex(0xcfd2d6);
constexpr Rgb kBuildingHigh = Rgb::Hex(0x39424e);

double Fraction(double height, double max_height) {
  return max_height > 0 ? std::clamp(height / max_height, 0.0, 1.0) : 1.0;
}

std::uint32_t Channel(double v) {
  return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

std::uint32_t Rgb::ToHex() const {
  return (Channel(r) << 16) | (Channel(g) << 8) | Channel(b);
}

Rgb BuildingColour(double height, double max_height) {
  const double t = Fraction(height, max_height);
  // Snapped to 8-bit channels: what the PNG holds is exactly this colour.
  return Rgb::Hex(Rgb{kBuildingLow.r + t * (kBuildingHigh.r - kBuildingLow.r),
                      kBuildingLow.g + t * (kBuildingHigh.g - kBuildingLow.g),
                      kBuildingLow.b + t * (kBuildingHigh.b - kBuildingLow.b)}
                      .ToHex());
}

bool BuildingTextIsLight(double height, double max_height) {
  return Fraction(height, max_height) > 0.42;
}

Rgb UavColour(int i) {
  static const Rgb colours[] = {Rgb::Hex(0x0072b2), Rgb::Hex(0xe69f00), Rgb::Hex(0xcc79a7),
                                Rgb::Hex(0x56b4e9), Rgb::Hex(0x999933), Rgb::Hex(0x882255),
                                Rgb::Hex(0x44aa99), Rgb::Hex(0x332288)};
  return colours[static_cast<std::size_t>(std::abs(i)) % std::size(colours)];
}

PlacementStyle PlacementStyleOf(int i) {
  static const MarkerShape shapes[] = {
      MarkerShape::kCircle,  MarkerShape::kSquare,       MarkerShape::kTriangleUp,
      MarkerShape::kDiamond, MarkerShape::kTriangleDown, MarkerShape::kPentagon,
      MarkerShape::kPlus,    MarkerShape::kCross,        MarkerShape::kStar};
  static const Rgb colours[] = {Rgb::Hex(0x000000), Rgb::Hex(0xe69f00), Rgb::Hex(0x0072b2),
                                Rgb::Hex(0x009e73), Rgb::Hex(0xcc79a7), Rgb::Hex(0xd55e00),
                                Rgb::Hex(0x56b4e9), Rgb::Hex(0x882255)};
  const std::size_t k = static_cast<std::size_t>(std::abs(i));
  return {shapes[k % std::size(shapes)], colours[k % std::size(colours)]};
}

}  // namespace rlpos::map
