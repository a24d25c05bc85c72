#include "common/scenario_import/osm_heights.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rlpos {
namespace {

constexpr double kFoot = 0.3048;
constexpr double kInch = 0.0254;

// The number at text[pos] (digits with at most one decimal point, as OpenStreetMap writes
// them; no sign, exponent or comma), moving pos past it.
std::optional<double> TakeNumber(const std::string& text, std::size_t& pos) {
  const std::size_t start = pos;
  bool digits = false, point = false;
  while (pos < text.size()) {
    const char c = text[pos];
    if (c >= '0' && c <= '9') {
      digits = true;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
    ++pos;
  }
  if (!digits)
    return std::nullopt;
  // Digits and one point only: the C library reads them the same in every locale's stead.
  double value = 0, scale = 1;
  bool after_point = false;
  for (std::size_t i = start; i < pos; ++i) {
    if (text[i] == '.') {
      after_point = true;
      continue;
    }
    if (after_point) {
      scale /= 10;
      value += (text[i] - '0') * scale;
    } else {
      value = value * 10 + (text[i] - '0');
    }
  }
  return value;
}

void SkipSpaces(const std::string& text, std::size_t& pos) {
  while (pos < text.size() && text[pos] == ' ')
    ++pos;
}

double Centimetres(double metres) {
  return std::round(metres * 100) / 100;
}

std::string Quoted(const std::string& text) {
  return "\"" + text + "\"";
}

std::string Metres(double v) {
  std::ostringstream out;
  out << v << " m";
  return out.str();
}

const std::string* Tag(const PlaceFeature& f, const std::string& key) {
  const auto it = f.tags.find(key);
  return it == f.tags.end() ? nullptr : &it->second;
}

}  // namespace

std::optional<double> ParseOsmLength(const std::string& text) {
  std::size_t pos = 0;
  SkipSpaces(text, pos);
  const auto number = TakeNumber(text, pos);
  if (!number)
    return std::nullopt;
  SkipSpaces(text, pos);
  const std::string unit = text.substr(pos);
  double metres = -1;
  if (unit.empty() || unit == "m" || unit == "meter" || unit == "meters" || unit == "metre" ||
      unit == "metres") {
    metres = *number;
  } else if (unit == "ft" || unit == "feet" || unit == "'") {
    metres = *number * kFoot;
  } else if (unit[0] == '\'') {  // feet and inches: 40'6"
    std::size_t at = 1;
    SkipSpaces(unit, at);
    const auto inches = TakeNumber(unit, at);
    if (!inches || unit.substr(at) != "\"")
      return std::nullopt;
    metres = *number * kFoot + *inches * kInch;
  }
  if (metres < 0)
    return std::nullopt;
  return metres;
}

std::optional<double> ParseOsmLevels(const std::string& text) {
  std::size_t pos = 0;
  SkipSpaces(text, pos);
  const auto number = TakeNumber(text, pos);
  SkipSpaces(text, pos);
  if (!number || pos != text.size())
    return std::nullopt;
  return number;
}

ResolvedHeight ResolveHeight(const PlaceFeature& f, const HeightRules& rules,
                             std::vector<ImportWarning>& warnings) {
  ResolvedHeight r;
  auto warn = [&](const std::string& message) {
    warnings.push_back({f.source, message});
    ++r.bad_values;
  };
  // Each source is read only when the ones before it gave nothing, so a bad value is warned
  // about only when it would have counted. -1: no usable count.
  auto levels_of = [&](const char* key) {
    const std::string* text = Tag(f, key);
    const double v = text ? ParseOsmLevels(*text).value_or(-1) : -1;
    return v > kMaxLevels ? -1 : v;
  };
  const double levels = levels_of("building:levels");
  const double min_levels = levels_of("building:min_level");
  // The bottom: min_height, else building:min_level levels up, else the ground.
  bool have_bottom = false;
  if (const std::string* text = Tag(f, "min_height")) {
    const auto m = ParseOsmLength(*text);
    if (m && *m <= kMaxBuildingHeight) {
      r.min_height = *m;
      have_bottom = true;
    } else {
      warn("min_height " + Quoted(*text) + " is not a height in metres or feet: " +
           (min_levels >= 0 ? "building:min_level is used" : "the building stands on the ground"));
    }
  }
  if (!have_bottom) {
    if (const std::string* text = Tag(f, "building:min_level")) {
      if (min_levels >= 0) {
        r.min_height = min_levels * rules.level_height;
      } else {
        warn("building:min_level " + Quoted(*text) +
             " is not a number of levels: the building stands on the ground");
      }
    }
  }
  // The top: height, else the levels and the roof on them, else the default.
  bool have_top = false;
  if (const std::string* text = Tag(f, "height")) {
    const auto h = ParseOsmLength(*text);
    if (h && *h > 0 && *h <= kMaxBuildingHeight) {
      r.height = *h;
      r.source = HeightSource::kHeight;
      have_top = true;
    } else {
      warn("height " + Quoted(*text) + " is not a height in metres or feet: " +
           (levels > 0 ? "building:levels is used" : "the default is used"));
    }
  }
  double roof = 0;
  if (const std::string* text = have_top ? nullptr : Tag(f, "roof:height")) {
    const auto h = ParseOsmLength(*text);
    if (h && *h <= kMaxBuildingHeight)
      roof = *h;
    else
      warn("roof:height " + Quoted(*text) + " is not a height in metres or feet: no roof added");
  }
  if (!have_top) {
    if (const std::string* text = Tag(f, "building:levels")) {
      if (levels > 0) {
        r.height = levels * rules.level_height + roof;
        r.source = HeightSource::kLevels;
        have_top = true;
      } else {
        warn("building:levels " + Quoted(*text) + " is not a number of levels from 1 to 200: " +
             "the default height " + Metres(rules.default_height) + " is used");
      }
    }
  }
  if (!have_top) {
    // A part that starts at or above the default height (a dome on a drum): its roof, or one
    // level, above its bottom.
    r.height = rules.default_height;
    if (r.height <= r.min_height)
      r.height = r.min_height + (roof > 0 ? roof : rules.level_height);
    r.source = HeightSource::kDefault;
  }
  r.height = Centimetres(r.height);
  r.min_height = Centimetres(r.min_height);
  if (r.min_height >= r.height) {
    warn("its bottom (" + Metres(r.min_height) + ") is not below its top (" + Metres(r.height) +
         "): it stands on the ground");
    r.min_height = 0;
  }
  // Floors: the levels it spans when the tags count them, else its height in levels.
  double floors = 0;
  if (levels > 0 && r.source != HeightSource::kDefault)
    floors = std::round(levels - (r.min_height > 0 && min_levels > 0 ? min_levels : 0.0));
  if (floors < 1)
    floors = std::floor((r.height - r.min_height) / rules.level_height);
  r.floors = static_cast<int>(std::clamp(floors, 1.0, kMaxLevels));
  return r;
}

}  // namespace rlpos
