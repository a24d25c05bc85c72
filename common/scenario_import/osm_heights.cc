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

namespace {

// One feature's height being resolved: its level counts (-1: no usable count), read once, and
// the warnings each tag that falls back adds, counted against the result.
struct HeightResolution {
  const PlaceFeature& feature;
  const HeightRules& rules;
  std::vector<ImportWarning>& warnings;
  ResolvedHeight result;
  double levels = -1;
  double min_levels = -1;

  void Warn(const std::string& message) {
    warnings.push_back({feature.source, message});
    ++result.bad_values;
  }
};

double LevelsTag(const PlaceFeature& f, const char* key) {
  const std::string* text = Tag(f, key);
  const double v = text ? ParseOsmLevels(*text).value_or(-1) : -1;
  return v > kMaxLevels ? -1 : v;
}

// Each source is read only when the ones before it gave nothing, so a bad value is warned
// about only when it would have counted.

// The bottom: min_height, else building:min_level levels up, else the ground.
void ResolveBottom(HeightResolution& h) {
  ResolvedHeight& r = h.result;
  if (const std::string* text = Tag(h.feature, "min_height")) {
    const auto m = ParseOsmLength(*text);
    if (m && *m <= kMaxBuildingHeight) {
      r.min_height = *m;
      return;
    }
    h.Warn(
        "min_height " + Quoted(*text) + " is not a height in metres or feet: " +
        (h.min_levels >= 0 ? "building:min_level is used" : "the building stands on the ground"));
  }
  if (const std::string* text = Tag(h.feature, "building:min_level")) {
    if (h.min_levels >= 0) {
      r.min_height = h.min_levels * h.rules.level_height;
    } else {
      h.Warn("building:min_level " + Quoted(*text) +
             " is not a number of levels: the building stands on the ground");
    }
  }
}

// The top from the height tag; false when it has none usable.
bool ResolveTopFromHeight(HeightResolution& h) {
  const std::string* text = Tag(h.feature, "height");
  if (!text)
    return false;
  const auto m = ParseOsmLength(*text);
  if (m && *m > 0 && *m <= kMaxBuildingHeight) {
    h.result.height = *m;
    h.result.source = HeightSource::kHeight;
    return true;
  }
  h.Warn("height " + Quoted(*text) + " is not a height in metres or feet: " +
         (h.levels > 0 ? "building:levels is used" : "the default is used"));
  return false;
}

// The roof:height added on the levels; 0 without a usable one.
double RoofHeight(HeightResolution& h) {
  const std::string* text = Tag(h.feature, "roof:height");
  if (!text)
    return 0;
  const auto m = ParseOsmLength(*text);
  if (m && *m <= kMaxBuildingHeight)
    return *m;
  h.Warn("roof:height " + Quoted(*text) + " is not a height in metres or feet: no roof added");
  return 0;
}

// The top from building:levels and the roof on them; false when it has none usable.
bool ResolveTopFromLevels(HeightResolution& h, double roof) {
  const std::string* text = Tag(h.feature, "building:levels");
  if (!text)
    return false;
  if (h.levels > 0) {
    h.result.height = h.levels * h.rules.level_height + roof;
    h.result.source = HeightSource::kLevels;
    return true;
  }
  h.Warn("building:levels " + Quoted(*text) + " is not a number of levels from 1 to 200: " +
         "the default height " + Metres(h.rules.default_height) + " is used");
  return false;
}

// The top: height, else the levels and the roof on them, else the default.
void ResolveTop(HeightResolution& h) {
  if (ResolveTopFromHeight(h))
    return;
  const double roof = RoofHeight(h);
  if (ResolveTopFromLevels(h, roof))
    return;
  // A part that starts at or above the default height (a dome on a drum): its roof, or one
  // level, above its bottom.
  ResolvedHeight& r = h.result;
  r.height = h.rules.default_height;
  if (r.height <= r.min_height)
    r.height = r.min_height + (roof > 0 ? roof : h.rules.level_height);
  r.source = HeightSource::kDefault;
}

// Rounds both ends to the centimetre and puts a bottom that is not below the top on the ground.
void SettleEnds(HeightResolution& h) {
  ResolvedHeight& r = h.result;
  r.height = Centimetres(r.height);
  r.min_height = Centimetres(r.min_height);
  if (r.min_height >= r.height) {
    h.Warn("its bottom (" + Metres(r.min_height) + ") is not below its top (" + Metres(r.height) +
           "): it stands on the ground");
    r.min_height = 0;
  }
}

// Floors: the levels it spans when the tags count them, else its height in levels.
int CountFloors(const HeightResolution& h) {
  const ResolvedHeight& r = h.result;
  double floors = 0;
  if (h.levels > 0 && r.source != HeightSource::kDefault)
    floors = std::round(h.levels - (r.min_height > 0 && h.min_levels > 0 ? h.min_levels : 0.0));
  if (floors < 1)
    floors = std::floor((r.height - r.min_height) / h.rules.level_height);
  return static_cast<int>(std::clamp(floors, 1.0, kMaxLevels));
}

}  // namespace

ResolvedHeight ResolveHeight(const PlaceFeature& f, const HeightRules& rules,
                             std::vector<ImportWarning>& warnings) {
  HeightResolution h{
      f, rules, warnings, {}, LevelsTag(f, "building:levels"), LevelsTag(f, "building:min_level")};
  ResolveBottom(h);
  ResolveTop(h);
  SettleEnds(h);
  h.result.floors = CountFloors(h);
  return h.result;
}

}  // namespace rlpos
