// Places drawn at random for the place importer's fuzz (buildings of any shape, some with holes,
// their tags odd or missing; streets), written as OpenStreetMap XML or GeoJSON.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>

#include "common/scenario_import/local_projection.h"
#include "tests/fuzz/place_inputs.h"
#include "tests/fuzz/place_inputs_internal.h"

namespace rlpos::testing {

using nlohmann::json;

namespace {

Point2 Snapped(Point2 p, double grid) {
  if (grid > 0) {
    p.x = std::round(p.x / grid) * grid;
    p.y = std::round(p.y / grid) * grid;
  }
  return p;
}

// A ring around `c`: a rectangle, a turned one, a star-shaped polygon, points anywhere (that
// may cross), or a degenerate one (points on a line, a sliver).
std::vector<Point2> RandomRing(const Point2& c, double reach, double grid, FuzzInput& in) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<Point2> ring;
  switch (in.Below(5)) {
    case 0: {
      const double w = Uniform(in, 0.01, reach), h = Uniform(in, 0.01, reach);
      ring = {{c.x, c.y}, {c.x + w, c.y}, {c.x + w, c.y + h}, {c.x, c.y + h}};
      break;
    }
    case 1: {
      const double w = Uniform(in, 0.01, reach), h = Uniform(in, 0.01, reach);
      const double a = Uniform(in, 0, 2 * kPi), ca = std::cos(a), sa = std::sin(a);
      const double us[] = {0, w, w, 0}, vs[] = {0, 0, h, h};
      for (int k = 0; k < 4; ++k)
        ring.push_back({c.x + us[k] * ca - vs[k] * sa, c.y + us[k] * sa + vs[k] * ca});
      break;
    }
    case 2: {
      std::vector<double> angles(3 + in.Below(10));
      for (double& a : angles)
        a = Uniform(in, 0, 2 * kPi);
      std::sort(angles.begin(), angles.end());
      for (const double a : angles) {
        const double r = Uniform(in, 0.05, reach);
        ring.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
      }
      break;
    }
    case 3:
      for (std::size_t k = 3 + in.Below(6); k > 0; --k)
        ring.push_back({c.x + Uniform(in, -reach, reach), c.y + Uniform(in, -reach, reach)});
      break;
    default: {
      const double dx = Uniform(in, -reach, reach), dy = Uniform(in, -reach, reach);
      const double width = in.Chance(0.5) ? 0.0 : Uniform(in, 0, 0.02);
      for (std::size_t k = 3 + in.Below(4); k > 0; --k) {
        const double t = Uniform(in, 0, 1);
        ring.push_back({c.x + t * dx - width * dy, c.y + t * dy + width * dx});
      }
    }
  }
  for (Point2& p : ring)
    p = Snapped(p, grid);
  return ring;
}

// A plausible length ("12.5") or an odd text.
std::string RandomLength(FuzzInput& in, double max) {
  return in.Chance(0.7) ? Format("%.1f", Uniform(in, 0, max)) : WeirdNumberText(in);
}

std::vector<std::pair<std::string, std::string>> RandomTags(FuzzInput& in) {
  static const char* const kNames[] = {"Tower",        "",       "a \"quoted\" <name> & more",
                                       "two\nlines",   "a\ttab", "\xe6\x97\xa5\xe6\x9c\xac",
                                       "/buildings/3", "\\"};
  static const char* const kBuilding[] = {"yes", "yes", "yes", "house", "no", "", "roof"};
  std::vector<std::pair<std::string, std::string>> tags;
  if (in.Chance(0.9))
    tags.emplace_back("building", kBuilding[in.Below(7)]);
  if (in.Chance(0.2))
    tags.emplace_back("building:part", in.Chance(0.9) ? "yes" : "no");
  if (in.Chance(0.5))
    tags.emplace_back("height", RandomLength(in, 120));
  if (in.Chance(0.3))
    tags.emplace_back("building:levels",
                      in.Chance(0.7) ? std::to_string(in.Below(40)) : WeirdNumberText(in));
  if (in.Chance(0.15))
    tags.emplace_back("min_height", RandomLength(in, 60));
  if (in.Chance(0.1))
    tags.emplace_back("building:min_level",
                      in.Chance(0.7) ? std::to_string(in.Below(20)) : WeirdNumberText(in));
  if (in.Chance(0.1))
    tags.emplace_back("roof:height", RandomLength(in, 20));
  if (in.Chance(0.3))
    tags.emplace_back("name", in.Chance(0.1) ? std::string(300, 'x') : kNames[in.Below(8)]);
  return tags;
}

}  // namespace

RandomPlace MakeRandomPlace(FuzzInput& in) {
  static const double kGrids[] = {0, 0, 0, 10, 1, 0.01};
  const double grid = kGrids[in.Below(6)];
  RandomPlace place;
  for (std::size_t n = 1 + in.Below(12); n > 0; --n) {
    RandomBuilding b;
    const Point2 c = Snapped({Uniform(in, -70, 70), Uniform(in, -70, 70)}, grid);
    b.rings.push_back(RandomRing(c, 40, grid, in));
    for (std::size_t h = in.Chance(0.2) ? 1 + in.Below(2) : 0; h > 0; --h)
      b.rings.push_back(
          RandomRing({c.x + Uniform(in, 0, 20), c.y + Uniform(in, 0, 20)}, 10, grid, in));
    b.tags = RandomTags(in);
    place.buildings.push_back(std::move(b));
  }
  for (std::size_t n = in.Below(4); n > 0; --n) {
    std::vector<Point2> street;
    for (std::size_t k = 2 + in.Below(4); k > 0; --k)
      street.push_back(Snapped({Uniform(in, -100, 100), Uniform(in, -100, 100)}, grid));
    place.streets.push_back(std::move(street));
  }
  return place;
}

namespace {

// A tag's text as an XML attribute value: markup escaped, and newlines and tabs as character
// references (attribute-value normalisation would read them back as spaces).
std::string XmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const char* reference = c == '&'    ? "&amp;"
                            : c == '<'  ? "&lt;"
                            : c == '>'  ? "&gt;"
                            : c == '"'  ? "&quot;"
                            : c == '\n' ? "&#10;"
                            : c == '\t' ? "&#9;"
                                        : nullptr;
    if (reference)
      out += reference;
    else
      out += c;
  }
  return out;
}

constexpr const char* kFixtureBounds =
    "  <bounds minlat=\"59.9991922\" minlon=\"24.9983871\" maxlat=\"60.0008078\" "
    "maxlon=\"25.0016129\"/>\n";

}  // namespace

std::string RandomPlaceAsOsmXml(const RandomPlace& place, FuzzInput& in) {
  const LocalProjection projection(kPlaceFixtureCentre);
  std::map<std::pair<long long, long long>, long> node_ids;
  std::string nodes, ways, relations;
  long next_way = 1, next_relation = 1;
  auto node = [&](const Point2& p) {
    const LonLat g = projection.Inverse(p);
    const auto key = std::make_pair(std::llround(g.lon * 1e7), std::llround(g.lat * 1e7));
    const auto found = node_ids.find(key);
    if (found != node_ids.end())
      return found->second;
    const long id = static_cast<long>(node_ids.size()) + 1;
    node_ids.emplace(key, id);
    nodes += "  <node id=\"" + std::to_string(id) + "\" lat=\"" + Format("%.7f", g.lat) +
             "\" lon=\"" + Format("%.7f", g.lon) + "\"/>\n";
    return id;
  };
  auto tag_lines = [](const std::vector<std::pair<std::string, std::string>>& tags) {
    std::string out;
    for (const auto& [k, v] : tags)
      out += "    <tag k=\"" + XmlEscaped(k) + "\" v=\"" + XmlEscaped(v) + "\"/>\n";
    return out;
  };
  auto way = [&](const std::vector<Point2>& points, bool closed,
                 const std::vector<std::pair<std::string, std::string>>& tags) {
    const long id = next_way++;
    ways += "  <way id=\"" + std::to_string(id) + "\">\n";
    for (const Point2& p : points)
      ways += "    <nd ref=\"" + std::to_string(node(p)) + "\"/>\n";
    if (closed && !points.empty())
      ways += "    <nd ref=\"" + std::to_string(node(points.front())) + "\"/>\n";
    ways += tag_lines(tags) + "  </way>\n";
    return id;
  };
  for (const auto& b : place.buildings) {
    const bool closed = !in.Chance(0.05);
    if (b.rings.size() == 1 && !in.Chance(0.1)) {
      way(b.rings[0], closed, b.tags);
      continue;
    }
    std::string members;
    for (std::size_t r = 0; r < b.rings.size(); ++r) {
      const bool tagged = r == 0 && in.Chance(0.1);  // the outline tagged too (a mapping slip)
      const long id = way(b.rings[r], closed, tagged ? b.tags : decltype(b.tags){});
      members += "    <member type=\"way\" ref=\"" + std::to_string(id) + "\" role=\"" +
                 (r == 0 ? "outer" : "inner") + "\"/>\n";
    }
    relations += "  <relation id=\"" + std::to_string(next_relation++) + "\">\n" + members +
                 "    <tag k=\"type\" v=\"multipolygon\"/>\n" + tag_lines(b.tags) +
                 "  </relation>\n";
  }
  for (const auto& street : place.streets) {
    std::vector<std::pair<std::string, std::string>> tags{{"highway", "residential"}};
    if (in.Chance(0.1))
      tags.emplace_back("tunnel", "yes");
    way(street, false, tags);
  }
  return std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n") +
         "<osm version=\"0.6\" generator=\"fuzz\">\n" + (in.Chance(0.9) ? kFixtureBounds : "") +
         nodes + ways + relations + "</osm>\n";
}

std::string RandomPlaceAsGeoJson(const RandomPlace& place, FuzzInput& in) {
  const LocalProjection projection(kPlaceFixtureCentre);
  auto line = [&](const std::vector<Point2>& points, bool closed) {
    json positions = json::array();
    for (const Point2& p : points) {
      const LonLat g = projection.Inverse(p);
      positions.push_back({g.lon, g.lat});
    }
    if (closed && !points.empty())
      positions.push_back(positions.front());
    return positions;
  };
  json features = json::array();
  for (const auto& b : place.buildings) {
    json polygon = json::array();
    for (const auto& ring : b.rings)
      polygon.push_back(line(ring, !in.Chance(0.05)));
    json properties = json::object();
    for (const auto& [k, v] : b.tags) {
      char* end = nullptr;
      const double number = std::strtod(v.c_str(), &end);
      if (in.Chance(0.3) && !v.empty() && *end == '\0' && std::isfinite(number))
        properties[k] = number;
      else
        properties[k] = v;
    }
    const bool multi = in.Chance(0.1);
    features.push_back({{"type", "Feature"},
                        {"properties", properties},
                        {"geometry",
                         {{"type", multi ? "MultiPolygon" : "Polygon"},
                          {"coordinates", multi ? json::array({polygon}) : polygon}}}});
  }
  for (const auto& street : place.streets) {
    features.push_back(
        {{"type", "Feature"},
         {"properties", {{"highway", "residential"}}},
         {"geometry", {{"type", "LineString"}, {"coordinates", line(street, false)}}}});
  }
  json doc = {{"type", "FeatureCollection"}, {"features", features}};
  if (in.Chance(0.8))
    doc["bbox"] = {24.9983871, 59.9991922, 25.0016129, 60.0008078};
  return doc.dump();
}

}  // namespace rlpos::testing
