#include "tests/fuzz/place_inputs.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <tuple>

#include "common/scenario_import/local_projection.h"

namespace rlpos::testing {

using nlohmann::json;

namespace {

std::string Format(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

}  // namespace

std::string WeirdNumberText(FuzzInput& in) {
  // clang-format off
  static const char* const kTexts[] = {
      "NaN", "nan", "inf", "-inf", "1e999", "-1e999", "1e308", "-1", "0", "-0", "", " ",
      "18446744073709551616", "9223372036854775807", "-9223372036854775808", "2147483648",
      "4611686018427387905", "4294967296", "1e-320", "90", "-90", "90.0000001", "180", "-180",
      "180.0000001", "214.7483647", "214.7483648", "0x10", "1.5.5", "+5", "6e1", "abc", "1,5",
      "12 ft", "3'", "4'11\"", "10 m", "5;6", ".", "-"};
  // clang-format on
  if (in.Chance(0.02))
    return std::string(40, '9');
  if (in.Chance(0.3))
    return Format("%.17g", in.WeirdDouble());
  return kTexts[in.Below(std::size(kTexts))];
}

bool KnownOsmiumBugsIncluded() {
  return std::getenv("RLPOS_FUZZ_KNOWN_BUGS") != nullptr;
}

bool HitsKnownOsmiumXmlBug(const std::string& text) {
  for (std::size_t eq = text.find('='); eq != std::string::npos; eq = text.find('=', eq + 1)) {
    if (eq + 1 >= text.size() || (text[eq + 1] != '"' && text[eq + 1] != '\''))
      continue;
    const std::size_t end = text.find(text[eq + 1], eq + 2);
    if (end == std::string::npos)
      break;
    const std::string value = text.substr(eq + 2, end - eq - 2);
    std::size_t begin = eq;
    while (begin > 0 && (std::isalnum(static_cast<unsigned char>(text[begin - 1])) ||
                         text[begin - 1] == '_' || text[begin - 1] == ':'))
      --begin;
    const std::string name = text.substr(begin, eq - begin);
    const auto ends_with = [&](const char* suffix) {
      const std::size_t n = std::strlen(suffix);
      return name.size() >= n && name.compare(name.size() - n, n, suffix) == 0;
    };
    if (ends_with("lat") || ends_with("lon")) {
      for (std::size_t k = 0; k + 1 < value.size(); ++k) {
        if ((value[k] == 'e' || value[k] == 'E') && value[k + 1] >= '0' && value[k + 1] <= '9')
          return true;
      }
    } else if (name == "id") {
      errno = 0;
      const long long id = std::strtoll(value.c_str(), nullptr, 10);
      constexpr long long kLimit = 1LL << 62;
      if (errno == 0 && (id > kLimit || id < -kLimit))
        return true;
    }
  }
  return false;
}

namespace {

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos)
      end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::string Trimmed(const std::string& line) {
  const std::size_t begin = line.find_first_not_of(" \t");
  return begin == std::string::npos ? "" : line.substr(begin);
}

bool StartsWith(const std::string& text, const char* prefix) {
  return text.rfind(prefix, 0) == 0;
}

bool StartsElement(const std::string& trimmed) {
  return StartsWith(trimmed, "<node") || StartsWith(trimmed, "<way") ||
         StartsWith(trimmed, "<relation");
}

}  // namespace

std::string OsmXml::Text() const {
  std::string out;
  for (const auto& line : head)
    out += line + "\n";
  for (const auto& element : elements) {
    for (const auto& line : element)
      out += line + "\n";
  }
  for (const auto& line : tail)
    out += line + "\n";
  return out;
}

std::vector<std::size_t> OsmXml::Find(const char* prefix) const {
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (StartsWith(Trimmed(elements[i][0]), prefix))
      found.push_back(i);
  }
  return found;
}

OsmXml SplitOsmXml(const std::string& text) {
  OsmXml xml;
  const std::vector<std::string> lines = SplitLines(text);
  std::size_t i = 0;
  while (i < lines.size() && !StartsElement(Trimmed(lines[i])) &&
         !StartsWith(Trimmed(lines[i]), "</osm"))
    xml.head.push_back(lines[i++]);
  while (i < lines.size() && !StartsWith(Trimmed(lines[i]), "</osm")) {
    const std::string first = Trimmed(lines[i]);
    std::vector<std::string> element{lines[i++]};
    const bool open = StartsElement(first) && first.compare(first.size() - 2, 2, "/>") != 0;
    while (open && i < lines.size()) {
      element.push_back(lines[i++]);
      if (StartsWith(Trimmed(element.back()), "</"))
        break;
    }
    xml.elements.push_back(std::move(element));
  }
  while (i < lines.size())
    xml.tail.push_back(lines[i++]);
  return xml;
}

namespace {

// The [begin, end) of the value of attribute `name` in `line` ("" for any attribute), each.
std::vector<std::pair<std::size_t, std::size_t>> AttributeValues(const std::string& line,
                                                                 const std::string& name) {
  std::vector<std::pair<std::size_t, std::size_t>> values;
  const std::string key = name.empty() ? "=\"" : " " + name + "=\"";
  for (std::size_t at = line.find(key); at != std::string::npos; at = line.find(key, at + 1)) {
    const std::size_t begin = at + key.size();
    const std::size_t end = line.find('"', begin);
    if (end == std::string::npos)
      break;
    values.emplace_back(begin, end);
  }
  return values;
}

std::string AttributeValue(const std::string& line, const std::string& name) {
  const auto values = AttributeValues(line, name);
  return values.empty() ? "" : line.substr(values[0].first, values[0].second - values[0].first);
}

void SetAttribute(std::string& line, const std::string& name, const std::string& value) {
  const auto values = AttributeValues(line, name);
  if (!values.empty())
    line.replace(values[0].first, values[0].second - values[0].first, value);
}

// A random line of a random element among `which` (all elements when empty), or null.
std::string* PickLine(OsmXml& xml, const std::vector<std::size_t>& which, FuzzInput& in) {
  if (xml.elements.empty())
    return nullptr;
  auto& element = which.empty() ? xml.elements[in.Below(xml.elements.size())]
                                : xml.elements[which[in.Below(which.size())]];
  return &element[in.Below(element.size())];
}

// A node's coordinate moved: onto another node's, by a hair, by a few metres, or anywhere in
// the venue.
std::string MovedCoordinate(const std::string& value, const std::string& other, FuzzInput& in) {
  static const double kSteps[] = {1e-7, -1e-7, 1e-6, 2e-5, -3e-4, 1e-9};
  switch (in.Below(4)) {
    case 0:
      return other;
    case 1:
      return Format("%.7f", std::strtod(value.c_str(), nullptr) + kSteps[in.Below(6)]);
    case 2:
      return Format(in.Chance(0.5) ? "%.9f" : "%.7f",
                    std::strtod(value.c_str(), nullptr) +
                        (static_cast<double>(in.Below(2001)) - 1000) * 1e-6);
    default:
      return Format("%.7f", std::strtod(value.c_str(), nullptr) +
                                (static_cast<double>(in.Below(2001)) - 1000) * 1e-7);
  }
}

}  // namespace

void EditOsmXml(OsmXml& xml, const std::vector<OsmXml>& others, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  switch (in.Below(14)) {
    case 0:  // delete an element, a node more often than not
      if (n > 0) {
        const auto nodes = xml.Find("<node");
        const std::size_t i =
            in.Chance(0.6) && !nodes.empty() ? nodes[in.Below(nodes.size())] : in.Below(n);
        elements.erase(elements.begin() + static_cast<long>(i));
      }
      break;
    case 1:  // duplicate an element (its id twice)
      if (n > 0)
        elements.insert(elements.begin() + static_cast<long>(in.Below(n + 1)),
                        elements[in.Below(n)]);
      break;
    case 2:  // move an element (a way before its nodes, a relation before its ways)
      if (n > 1) {
        auto element = elements[in.Below(n)];
        elements.erase(std::find(elements.begin(), elements.end(), element));
        elements.insert(elements.begin() + static_cast<long>(in.Below(n)), std::move(element));
      }
      break;
    case 3: {  // an element of another fixture (its ids clash or dangle)
      const OsmXml& other = others[in.Below(others.size())];
      if (!other.elements.empty())
        elements.insert(elements.begin() + static_cast<long>(in.Below(n + 1)),
                        other.elements[in.Below(other.elements.size())]);
      break;
    }
    case 4:    // delete a child line (<nd>, <member>, <tag>)
    case 5:    // duplicate one
    case 6: {  // swap two
      if (n == 0)
        break;
      auto& element = elements[in.Below(n)];
      if (element.size() < 3)
        break;
      const std::size_t a = 1 + in.Below(element.size() - 2);
      const std::size_t b = 1 + in.Below(element.size() - 2);
      const std::size_t edit = in.Below(3);
      if (edit == 0)
        element.erase(element.begin() + static_cast<long>(a));
      else if (edit == 1)
        element.insert(element.begin() + static_cast<long>(b), element[a]);
      else
        std::swap(element[a], element[b]);
      break;
    }
    case 7: {  // an attribute value made a weird number (an id, ref, lat, lon, version, v)
      std::string* line = PickLine(xml, {}, in);
      if (line == nullptr)
        break;
      const auto values = AttributeValues(*line, "");
      if (!values.empty()) {
        const auto [begin, end] = values[in.Below(values.size())];
        line->replace(begin, end - begin, WeirdNumberText(in));
      }
      break;
    }
    case 8: {  // a tag's value made odd
      std::vector<std::string*> tags;
      for (auto& element : elements) {
        for (auto& line : element) {
          if (StartsWith(Trimmed(line), "<tag"))
            tags.push_back(&line);
        }
      }
      if (tags.empty())
        break;
      std::string& tag = *tags[in.Below(tags.size())];
      static const char* const kKeys[] = {
          "height",      "building:levels", "min_height",    "building:min_level",
          "roof:height", "building",        "building:part", "type",
          "highway",     "tunnel"};
      if (in.Chance(0.3))
        SetAttribute(tag, "k", kKeys[in.Below(sizeof kKeys / sizeof kKeys[0])]);
      static const char* const kValues[] = {"yes",   "no",        "part",        "multipolygon",
                                            "inner", "",          "residential", "&amp;",
                                            "&#0;",  "&#x10FFFF;"};
      SetAttribute(tag, "v",
                   in.Chance(0.6) ? WeirdNumberText(in)
                                  : kValues[in.Below(sizeof kValues / sizeof kValues[0])]);
      break;
    }
    case 9: {  // a way's ring broken: open, closed on another node, or through a missing one
      const auto ways = xml.Find("<way");
      if (ways.empty())
        break;
      auto& way = elements[ways[in.Below(ways.size())]];
      std::vector<std::size_t> nds;
      for (std::size_t i = 0; i < way.size(); ++i) {
        if (StartsWith(Trimmed(way[i]), "<nd"))
          nds.push_back(i);
      }
      if (nds.empty())
        break;
      const std::size_t edit = in.Below(3);
      if (edit == 0) {
        way.erase(way.begin() + static_cast<long>(nds.back()));
      } else if (edit == 1) {
        SetAttribute(way[nds.back()], "ref", AttributeValue(way[nds[in.Below(nds.size())]], "ref"));
      } else {
        std::string nd = way[nds[0]];
        SetAttribute(nd, "ref", std::to_string(1 + in.Below(99999)));
        way.insert(way.begin() + static_cast<long>(nds[in.Below(nds.size())]), nd);
      }
      break;
    }
    case 10: {  // a node moved
      const auto nodes = xml.Find("<node");
      if (nodes.empty())
        break;
      std::string& node = elements[nodes[in.Below(nodes.size())]][0];
      const std::string& other = elements[nodes[in.Below(nodes.size())]][0];
      const char* axis = in.Chance(0.5) ? "lat" : "lon";
      const std::string moved =
          MovedCoordinate(AttributeValue(node, axis), AttributeValue(other, axis), in);
      SetAttribute(node, axis, moved);
      if (in.Chance(0.3)) {  // both axes onto the other node's
        SetAttribute(node, "lat", AttributeValue(other, "lat"));
        SetAttribute(node, "lon", AttributeValue(other, "lon"));
      }
      break;
    }
    case 11: {  // the bounds: dropped, shrunk off the venue's centre, or made odd
      for (std::size_t i = 0; i < xml.head.size(); ++i) {
        std::string& line = xml.head[i];
        if (!StartsWith(Trimmed(line), "<bounds"))
          continue;
        const std::size_t edit = in.Below(3);
        if (edit == 0) {
          xml.head.erase(xml.head.begin() + static_cast<long>(i));
        } else if (edit == 1) {
          SetAttribute(line, in.Chance(0.5) ? "maxlat" : "minlon",
                       in.Chance(0.5) ? "60.0000000" : "24.9999000");
        } else {
          static const char* const kNames[] = {"minlat", "minlon", "maxlat", "maxlon"};
          SetAttribute(line, kNames[in.Below(4)], WeirdNumberText(in));
        }
        break;
      }
      break;
    }
    case 12: {  // a relation's member: its role, type or ref changed
      const auto relations = xml.Find("<relation");
      if (relations.empty())
        break;
      auto& relation = elements[relations[in.Below(relations.size())]];
      std::string& line = relation[in.Below(relation.size())];
      if (!StartsWith(Trimmed(line), "<member"))
        break;
      static const char* const kRoles[] = {"outer", "inner", "", "part", "outline"};
      static const char* const kTypes[] = {"way", "node", "relation", "area"};
      const std::size_t edit = in.Below(3);
      if (edit == 0)
        SetAttribute(line, "role", kRoles[in.Below(5)]);
      else if (edit == 1)
        SetAttribute(line, "type", kTypes[in.Below(4)]);
      else
        SetAttribute(line, "ref", in.Chance(0.5) ? "1" : AttributeValue(relation[0], "id"));
      break;
    }
    default: {  // an id or a ref made another element's id
      std::string* line = PickLine(xml, {}, in);
      std::string* other = PickLine(xml, {}, in);
      if (line == nullptr)
        break;
      const std::string id = AttributeValue(*other, "id");
      if (!id.empty())
        SetAttribute(*line, in.Chance(0.5) ? "id" : "ref", id);
      break;
    }
  }
}

namespace {

// Uniform in [lo, hi].
double Uniform(FuzzInput& in, double lo, double hi) {
  constexpr std::size_t kSteps = std::size_t{1} << 30;
  return lo + (hi - lo) * static_cast<double>(in.Below(kSteps + 1)) / static_cast<double>(kSteps);
}

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

std::string XmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\n':
        out += "&#10;";
        break;
      case '\t':
        out += "&#9;";
        break;
      default:
        out += c;
    }
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

}  // namespace

void EditGeoJson(json& doc, FuzzInput& in) {
  JsonParts parts;
  CollectParts(doc, parts);
  json* features = doc.is_object() && doc.contains("features") && doc["features"].is_array()
                       ? &doc["features"]
                       : nullptr;
  json* feature =
      features && !features->empty() ? &(*features)[in.Below(features->size())] : nullptr;
  json* position =
      parts.positions.empty() ? nullptr : parts.positions[in.Below(parts.positions.size())];
  json* line = parts.lines.empty() ? nullptr : parts.lines[in.Below(parts.lines.size())];
  const std::size_t edit = in.Below(14);
  if (edit <= 8 && line == nullptr)
    return;
  const auto at = static_cast<long>(line ? in.Below(line->size()) : 0);
  switch (edit) {
    case 0:  // a position deleted
      line->erase(line->begin() + at);
      break;
    case 1:  // a position drawn twice
      line->insert(line->begin() + static_cast<long>(in.Below(line->size() + 1)),
                   json((*line)[static_cast<std::size_t>(at)]));
      break;
    case 2:  // a position onto another's
      *position = *parts.positions[in.Below(parts.positions.size())];
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
    case 8:  // a line cut to 0, 1 or 2 positions
      line->erase(line->begin() + std::min<long>(static_cast<long>(in.Below(3)),
                                                 static_cast<long>(line->size())),
                  line->end());
      break;
    case 9:  // a feature deleted or given twice
      if (feature == nullptr)
        break;
      if (in.Chance(0.5))
        features->erase(features->begin() + (feature - &(*features)[0]));
      else
        features->push_back(json(*feature));
      break;
    case 10: {  // a geometry of another type, or none
      if (feature == nullptr || !feature->is_object() || !feature->contains("geometry") ||
          !(*feature)["geometry"].is_object())
        break;
      static const char* const kTypes[] = {
          "Polygon", "MultiPolygon", "LineString",         "MultiLineString",
          "Point",   "MultiPoint",   "GeometryCollection", "polygon"};
      json& geometry = (*feature)["geometry"];
      if (in.Chance(0.1))
        geometry = nullptr;
      else
        geometry["type"] = kTypes[in.Below(8)];
      break;
    }
    case 11: {  // a property made odd, or the properties
      if (feature == nullptr || !feature->is_object())
        break;
      static const char* const kKeys[] = {
          "height",      "building:levels", "min_height",    "building:min_level",
          "roof:height", "building",        "building:part", "highway",
          "name"};
      json& properties = (*feature)["properties"];
      if (in.Chance(0.1)) {
        static const json kOdd[] = {nullptr, json::array(), "x", 5};
        properties = kOdd[in.Below(4)];
        break;
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
      break;
    }
    case 12: {  // the bbox: dropped, shrunk off the centre, turned over, or odd
      if (!doc.is_object())
        break;
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
      break;
    }
    default: {  // coordinates nested a level deeper or shallower
      if (feature == nullptr || !feature->is_object() || !feature->contains("geometry") ||
          !(*feature)["geometry"].is_object() || !(*feature)["geometry"].contains("coordinates"))
        break;
      json& coordinates = (*feature)["geometry"]["coordinates"];
      if (in.Chance(0.5))
        coordinates = json::array({coordinates});
      else if (coordinates.is_array() && !coordinates.empty())
        coordinates = json(coordinates[0]);
    }
  }
}

namespace {

bool ReadVarint(const std::string& s, std::size_t& at, std::uint64_t& value) {
  value = 0;
  for (int shift = 0; shift < 64 && at < s.size(); shift += 7) {
    const auto byte = static_cast<unsigned char>(s[at++]);
    value |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
    if ((byte & 0x80) == 0)
      return true;
  }
  return false;
}

void PutVarint(std::string& out, std::uint64_t v) {
  for (; v >= 0x80; v >>= 7)
    out += static_cast<char>((v & 0x7f) | 0x80);
  out += static_cast<char>(v);
}

void PutBytesField(std::string& out, std::uint64_t number, const std::string& bytes) {
  PutVarint(out, (number << 3) | 2);
  PutVarint(out, bytes.size());
  out += bytes;
}

// What a length-delimited field `number` of a `type` message holds.
std::pair<ProtoField::Kind, PbfMessage> PbfSchema(PbfMessage type, std::uint64_t number) {
  using K = ProtoField::Kind;
  using M = PbfMessage;
  switch (type) {
    case M::kPrimitiveBlock:
      if (number == 1)
        return {K::kMessage, M::kStringTable};
      if (number == 2)
        return {K::kMessage, M::kGroup};
      break;
    case M::kGroup:
      if (number >= 1 && number <= 4) {
        static const M kTypes[] = {M::kNode, M::kDense, M::kWay, M::kRelation};
        return {K::kMessage, kTypes[number - 1]};
      }
      break;
    case M::kDense:
      if (number == 5)
        return {K::kMessage, M::kDenseInfo};
      if (number == 1 || number >= 8)
        return {K::kPacked, M::kOther};
      break;
    case M::kDenseInfo:
      return {K::kPacked, M::kOther};
    case M::kNode:
    case M::kWay:
    case M::kRelation:
      if (number == 4)
        return {K::kMessage, M::kInfo};
      if (number == 2 || number == 3 || number >= 8)
        return {K::kPacked, M::kOther};
      break;
    default:  // the header's bbox is edited as bytes
      break;
  }
  return {K::kBytes, M::kOther};
}

}  // namespace

bool ParseProto(const std::string& data, PbfMessage type, std::vector<ProtoField>& fields) {
  std::size_t at = 0;
  while (at < data.size()) {
    ProtoField f;
    std::uint64_t key = 0;
    if (!ReadVarint(data, at, key))
      return false;
    f.number = key >> 3;
    if ((key & 7) == 0) {
      if (!ReadVarint(data, at, f.value))
        return false;
    } else if ((key & 7) == 2) {
      std::uint64_t size = 0;
      if (!ReadVarint(data, at, size) || size > data.size() - at)
        return false;
      const std::string bytes = data.substr(at, size);
      at += size;
      std::tie(f.kind, f.type) = PbfSchema(type, f.number);
      if (f.kind == ProtoField::Kind::kMessage) {
        if (!ParseProto(bytes, f.type, f.fields))
          return false;
      } else if (f.kind == ProtoField::Kind::kPacked) {
        for (std::size_t p = 0; p < bytes.size();) {
          std::uint64_t v = 0;
          if (!ReadVarint(bytes, p, v))
            return false;
          f.values.push_back(v);
        }
      } else {
        f.bytes = bytes;
      }
    } else {
      return false;
    }
    fields.push_back(std::move(f));
  }
  return true;
}

std::string SerializeProto(const std::vector<ProtoField>& fields) {
  std::string out;
  for (const auto& f : fields) {
    if (f.kind == ProtoField::Kind::kVarint) {
      PutVarint(out, f.number << 3);
      PutVarint(out, f.value);
      continue;
    }
    std::string bytes = f.bytes;
    if (f.kind == ProtoField::Kind::kMessage) {
      bytes = SerializeProto(f.fields);
    } else if (f.kind == ProtoField::Kind::kPacked) {
      for (const std::uint64_t v : f.values)
        PutVarint(bytes, v);
    }
    PutBytesField(out, f.number, bytes);
  }
  return out;
}

namespace {

// The parts of a parsed block an edit may change.
struct ProtoParts {
  std::vector<ProtoField*> varints, packed, strings, submessages;
  std::vector<std::vector<ProtoField>*> messages;
};

void CollectProto(std::vector<ProtoField>& fields, ProtoParts& parts) {
  parts.messages.push_back(&fields);
  for (auto& f : fields) {
    if (f.kind == ProtoField::Kind::kVarint) {
      parts.varints.push_back(&f);
    } else if (f.kind == ProtoField::Kind::kPacked && !f.values.empty()) {
      parts.packed.push_back(&f);
    } else if (f.kind == ProtoField::Kind::kBytes) {
      parts.strings.push_back(&f);
    } else if (f.kind == ProtoField::Kind::kMessage) {
      parts.submessages.push_back(&f);
      CollectProto(f.fields, parts);
    }
  }
}

// A varint made odd: a limit of some width, a bit flipped, nudged (a zigzag coordinate delta by
// a unit of granularity), or scaled.
std::uint64_t WeirdVarint(std::uint64_t v, FuzzInput& in) {
  static const std::uint64_t kSmall[] = {0, 1, 2, 3, 0x7f, 0x80, 0x7fffffff, 0x80000000};
  constexpr std::uint64_t kAll = ~std::uint64_t{0};
  static const std::uint64_t kLarge[] = {0xffffffff,   0x100000000, kAll >> 1,
                                         ~(kAll >> 1), kAll - 1,    kAll};
  std::uint64_t odd = 0;
  switch (in.Below(4)) {
    case 0:
      odd = in.Chance(0.5) ? kSmall[in.Below(std::size(kSmall))]
                           : kLarge[in.Below(std::size(kLarge))];
      break;
    case 1:
      odd = v ^ (std::uint64_t{1} << in.Below(64));
      break;
    case 2:
      odd = v + in.Below(5) - 2;
      break;
    default:
      odd = v * (1 + in.Below(1000));
  }
  // Clear of libosmium's overflows (place_inputs.h): below 2^30, a coordinate times the
  // granularity, a sum of deltas or an id stays far from 2^62.
  return KnownOsmiumBugsIncluded() ? odd : odd & ((std::uint64_t{1} << 30) - 1);
}

}  // namespace

void EditProto(std::vector<ProtoField>& block, FuzzInput& in) {
  ProtoParts parts;
  CollectProto(block, parts);
  const std::size_t edit = in.Below(11);
  if (edit < 3 && !parts.varints.empty()) {
    ProtoField& f = *parts.varints[in.Below(parts.varints.size())];
    f.value = WeirdVarint(f.value, in);
  } else if (edit < 7 && !parts.packed.empty()) {
    auto& values = parts.packed[in.Below(parts.packed.size())]->values;
    const auto at = static_cast<long>(in.Below(values.size()));
    switch (in.Below(4)) {
      case 0:
        values.erase(values.begin() + at);
        break;
      case 1:
        values.insert(values.begin() + at, values[static_cast<std::size_t>(at)]);
        break;
      case 2:
        values.resize(in.Below(values.size()));
        break;
      default:
        values[static_cast<std::size_t>(at)] =
            WeirdVarint(values[static_cast<std::size_t>(at)], in);
    }
  } else if (edit < 9 && !parts.strings.empty()) {
    static const char* const kStrings[] = {"building",
                                           "building:part",
                                           "highway",
                                           "type",
                                           "multipolygon",
                                           "outer",
                                           "inner",
                                           "yes",
                                           "no",
                                           "height",
                                           "building:levels",
                                           "min_height",
                                           "tunnel",
                                           "",
                                           "1e999",
                                           "NaN",
                                           "-5"};
    ProtoField& field = *parts.strings[in.Below(parts.strings.size())];
    std::string& text = field.bytes;
    switch (in.Below(3)) {
      case 0:
        text = kStrings[in.Below(std::size(kStrings))];
        break;
      case 1:
        text = parts.strings[in.Below(parts.strings.size())]->bytes;
        break;
      default:
        text = in.Mutate(text);
    }
  } else if (edit == 10) {
    std::vector<ProtoField*> damageable;
    for (ProtoField* f : parts.submessages) {
      if (KnownOsmiumBugsIncluded() || f->type == PbfMessage::kStringTable)
        damageable.push_back(f);
    }
    if (damageable.empty())
      return;
    ProtoField& f = *damageable[in.Below(damageable.size())];
    std::string damaged = in.Mutate(SerializeProto(f.fields));
    f.bytes = std::move(damaged);
    f.fields.clear();
    f.kind = ProtoField::Kind::kBytes;
  } else {
    auto& fields = *parts.messages[in.Below(parts.messages.size())];
    if (fields.empty())
      return;
    const auto a = static_cast<long>(in.Below(fields.size()));
    const auto b = static_cast<long>(in.Below(fields.size()));
    switch (in.Below(3)) {
      case 0:
        fields.erase(fields.begin() + a);
        break;
      case 1:
        fields.insert(fields.begin() + b, ProtoField(fields[static_cast<std::size_t>(a)]));
        break;
      default:
        std::swap(fields[static_cast<std::size_t>(a)], fields[static_cast<std::size_t>(b)]);
    }
  }
}

std::vector<PbfBlock> ReadPbfBlocks(const std::string& file) {
  std::vector<PbfBlock> blocks;
  std::size_t at = 0;
  while (at + 4 <= file.size()) {
    std::size_t header_size = 0;
    for (int k = 0; k < 4; ++k)
      header_size = (header_size << 8) | static_cast<unsigned char>(file[at++]);
    PbfBlock block;
    std::size_t blob_size = 0;
    std::vector<ProtoField> header, blob;
    if (!ParseProto(file.substr(at, header_size), PbfMessage::kOther, header))
      return {};
    for (const auto& f : header) {
      if (f.number == 1)
        block.type = f.bytes;
      else if (f.number == 3)
        blob_size = f.value;
    }
    at += header_size;
    if (!ParseProto(file.substr(at, blob_size), PbfMessage::kOther, blob))
      return {};
    at += blob_size;
    std::string zlib_data;
    uLongf raw_size = 0;
    for (const auto& f : blob) {
      if (f.number == 1)
        block.data = f.bytes;
      else if (f.number == 2)
        raw_size = static_cast<uLongf>(f.value);
      else if (f.number == 3)
        zlib_data = f.bytes;
    }
    if (!zlib_data.empty()) {
      block.data.resize(raw_size);
      if (uncompress(reinterpret_cast<Bytef*>(block.data.data()), &raw_size,
                     reinterpret_cast<const Bytef*>(zlib_data.data()),
                     static_cast<uLong>(zlib_data.size())) != Z_OK)
        return {};
      block.data.resize(raw_size);
    }
    blocks.push_back(std::move(block));
  }
  return blocks;
}

std::string PbfFile(const std::vector<PbfBlock>& blocks) {
  std::string out;
  for (const auto& b : blocks) {
    std::string blob, header;
    PutBytesField(blob, 1, b.data);
    PutVarint(blob, 2 << 3);
    PutVarint(blob, b.data.size());
    PutBytesField(header, 1, b.type);
    PutVarint(header, 3 << 3);
    PutVarint(header, blob.size());
    for (int shift = 24; shift >= 0; shift -= 8)
      out += static_cast<char>((header.size() >> shift) & 0xff);
    out += header + blob;
  }
  return out;
}

std::string Gzipped(const std::string& text) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    return text;
  std::string out(deflateBound(&z, static_cast<uLong>(text.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

}  // namespace rlpos::testing
