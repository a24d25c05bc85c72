// Structural edits of GeoJSON documents for the place importer's fuzz (positions, rings,
// features, properties, the bbox), and the numbers JSON cannot hold put back into their text.
#include <algorithm>
#include <utility>

#include "tests/fuzz/place_inputs.h"
#include "tests/fuzz/place_inputs_internal.h"

namespace rlpos::testing {

using nlohmann::json;

std::string WithUnwritableNumbers(std::string text) {
  static const std::pair<const char*, const char*> kPlaceholders[] = {
      {"\"@1e999@\"", "1e999"}, {"\"@-1e999@\"", "-1e999"}, {"\"@NaN@\"", "NaN"}};
  for (const auto& [placeholder, number] : kPlaceholders) {
    for (std::size_t at = text.find(placeholder); at != std::string::npos;
         at = text.find(placeholder, at))
      text.replace(at, std::string(placeholder).size(), number);
  }
  return text;
}

namespace {

json WeirdJsonNumber(FuzzInput& in) {
  // clang-format off
  static const json kValues[] = {
      1e308, -1e308, 180.0, -180.0, 90.0, -90.0, 180.0000001, 90.0000001, 0.0, -0.0, 5e-324, -1,
      9223372036854775807LL, 18446744073709551615ULL, "@1e999@", "@-1e999@", "@NaN@"};
  // clang-format on
  return kValues[in.Below(std::size(kValues))];
}

bool IsPosition(const json& v) {
  return v.is_array() && v.size() >= 2 && v.size() <= 4 &&
         std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); });
}

// The positions and the lines (arrays of positions: rings, line strings) of a document.
struct JsonParts {
  std::vector<json*> positions, lines;
};

void CollectParts(json& v, JsonParts& parts) {
  if (!v.is_array() && !v.is_object())
    return;
  if (IsPosition(v)) {
    parts.positions.push_back(&v);
    return;
  }
  if (v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), IsPosition))
    parts.lines.push_back(&v);
  for (auto& child : v)
    CollectParts(child, parts);
}

// The parts of a document one edit may change, drawn before the edit is.
struct GeoJsonTargets {
  JsonParts parts;
  json* features = nullptr;
  json* feature = nullptr;
  json* position = nullptr;
  json* line = nullptr;
  long at = 0;  // a position's index in `line`
};

// Edits 0 to 8 of EditGeoJson: of a position or of a line (`line` is not null).
void EditPositions(std::size_t edit, GeoJsonTargets& t, FuzzInput& in) {
  json* const line = t.line;
  json* const position = t.position;
  const long at = t.at;
  switch (edit) {
    case 0:  // a position deleted
      line->erase(line->begin() + at);
      break;
    case 1:  // a position drawn twice
      line->insert(line->begin() + static_cast<long>(in.Below(line->size() + 1)),
                   json((*line)[static_cast<std::size_t>(at)]));
      break;
    case 2:  // a position onto another's
      *position = *t.parts.positions[in.Below(t.parts.positions.size())];
      break;
    case 3: {  // a position moved by a hair or a few metres
      static const double kSteps[] = {1e-9, -1e-7, 1e-6, 2e-5, -3e-4};
      json& v = (*position)[in.Below(2)];
      v = v.get<double>() + kSteps[in.Below(5)] * (in.Chance(0.5) ? 1 : Uniform(in, -10, 10));
      break;
    }
    case 4:  // a longitude or latitude made odd
      (*position)[in.Below(2)] = WeirdJsonNumber(in);
      break;
    case 5:  // an altitude, or one number too many
      position->push_back(in.Chance(0.5) ? json(Uniform(in, -10, 100)) : WeirdJsonNumber(in));
      break;
    case 6:  // a ring left open
      line->erase(line->end() - 1);
      break;
    case 7:  // a ring turned the other way
      std::reverse(line->begin(), line->end());
      break;
    default:  // a line cut to 0, 1 or 2 positions
      line->erase(line->begin() + std::min<long>(static_cast<long>(in.Below(3)),
                                                 static_cast<long>(line->size())),
                  line->end());
  }
}

// A feature deleted or given twice.
void DeleteOrDoubleFeature(json* features, json* feature, FuzzInput& in) {
  if (feature == nullptr)
    return;
  if (in.Chance(0.5))
    features->erase(features->begin() + (feature - &(*features)[0]));
  else
    features->push_back(json(*feature));
}

bool HasGeometry(const json* feature) {
  return feature != nullptr && feature->is_object() && feature->contains("geometry") &&
         (*feature)["geometry"].is_object();
}

// A geometry of another type, or none.
void RetypeGeometry(json* feature, FuzzInput& in) {
  if (!HasGeometry(feature))
    return;
  static const char* const kTypes[] = {
      "Polygon", "MultiPolygon", "LineString",         "MultiLineString",
      "Point",   "MultiPoint",   "GeometryCollection", "polygon"};
  json& geometry = (*feature)["geometry"];
  if (in.Chance(0.1))
    geometry = nullptr;
  else
    geometry["type"] = kTypes[in.Below(8)];
}

// A property made odd, or the properties.
void MakePropertyOdd(json* feature, FuzzInput& in) {
  if (feature == nullptr || !feature->is_object())
    return;
  static const char* const kKeys[] = {
      "height",      "building:levels", "min_height",    "building:min_level",
      "roof:height", "building",        "building:part", "highway",
      "name"};
  json& properties = (*feature)["properties"];
  if (in.Chance(0.1)) {
    static const json kOdd[] = {nullptr, json::array(), "x", 5};
    properties = kOdd[in.Below(4)];
    return;
  }
  if (!properties.is_object())
    properties = json::object();
  const char* key = kKeys[in.Below(9)];
  switch (in.Below(4)) {
    case 0:
      properties[key] = WeirdNumberText(in);
      break;
    case 1:
      properties[key] = WeirdJsonNumber(in);
      break;
    case 2:
      properties[key] = in.Chance(0.5) ? json("yes") : json("no");
      break;
    default:
      properties[key] = in.Chance(0.5) ? json(nullptr) : json::object({{"a", 1}});
  }
}

// The bbox: dropped, shrunk off the centre, turned over, or odd.
void EditBbox(json& doc, FuzzInput& in) {
  if (!doc.is_object())
    return;
  switch (in.Below(4)) {
    case 0:
      doc.erase("bbox");
      break;
    case 1:
      doc["bbox"] = {25.0000001, 59.9991922, 25.0016129, 60.0008078};
      break;
    case 2:
      doc["bbox"] = {25.0016129, 60.0008078, 24.9983871, 59.9991922};
      break;
    default:
      if (doc.contains("bbox") && doc["bbox"].is_array() && !doc["bbox"].empty())
        doc["bbox"][in.Below(doc["bbox"].size())] = WeirdJsonNumber(in);
  }
}

// Coordinates nested a level deeper or shallower.
void RenestCoordinates(json* feature, FuzzInput& in) {
  if (!HasGeometry(feature) || !(*feature)["geometry"].contains("coordinates"))
    return;
  json& coordinates = (*feature)["geometry"]["coordinates"];
  if (in.Chance(0.5))
    coordinates = json::array({coordinates});
  else if (coordinates.is_array() && !coordinates.empty())
    coordinates = json(coordinates[0]);
}

}  // namespace

void EditGeoJson(json& doc, FuzzInput& in) {
  GeoJsonTargets t;
  CollectParts(doc, t.parts);
  t.features = doc.is_object() && doc.contains("features") && doc["features"].is_array()
                   ? &doc["features"]
                   : nullptr;
  t.feature =
      t.features && !t.features->empty() ? &(*t.features)[in.Below(t.features->size())] : nullptr;
  t.position =
      t.parts.positions.empty() ? nullptr : t.parts.positions[in.Below(t.parts.positions.size())];
  t.line = t.parts.lines.empty() ? nullptr : t.parts.lines[in.Below(t.parts.lines.size())];
  const std::size_t edit = in.Below(14);
  if (edit <= 8 && t.line == nullptr)
    return;
  t.at = static_cast<long>(t.line ? in.Below(t.line->size()) : 0);
  switch (edit) {
    case 9:
      DeleteOrDoubleFeature(t.features, t.feature, in);
      break;
    case 10:
      RetypeGeometry(t.feature, in);
      break;
    case 11:
      MakePropertyOdd(t.feature, in);
      break;
    case 12:
      EditBbox(doc, in);
      break;
    case 13:
      RenestCoordinates(t.feature, in);
      break;
    default:
      EditPositions(edit, t, in);
  }
}

}  // namespace rlpos::testing
