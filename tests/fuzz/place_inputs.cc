// Inputs for the place importer's fuzz: texts numbers trip on, the known libosmium bugs the fuzz
// keeps clear of, structural edits of OpenStreetMap XML files, and gzip. Random places are in
// place_inputs_random.cc, GeoJSON edits in place_inputs_geojson.cc, PBF blocks in pbf_blocks.cc.
#include "tests/fuzz/place_inputs.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "tests/fuzz/place_inputs_internal.h"

namespace rlpos::testing {

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

// Each edit below is one case of EditOsmXml, its random draws in the order they always were (a
// seed gives the same file).

// An element deleted, a node more often than not.
void DeleteElement(OsmXml& xml, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  if (n > 0) {
    const auto nodes = xml.Find("<node");
    const std::size_t i =
        in.Chance(0.6) && !nodes.empty() ? nodes[in.Below(nodes.size())] : in.Below(n);
    elements.erase(elements.begin() + static_cast<long>(i));
  }
}

// An element duplicated (its id twice).
void DuplicateElement(OsmXml& xml, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  if (n > 0)
    elements.insert(elements.begin() + static_cast<long>(in.Below(n + 1)), elements[in.Below(n)]);
}

// An element moved (a way before its nodes, a relation before its ways).
void MoveElement(OsmXml& xml, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  if (n > 1) {
    auto element = elements[in.Below(n)];
    elements.erase(std::find(elements.begin(), elements.end(), element));
    elements.insert(elements.begin() + static_cast<long>(in.Below(n)), std::move(element));
  }
}

// An element of another fixture (its ids clash or dangle).
void InsertOtherElement(OsmXml& xml, const std::vector<OsmXml>& others, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  const OsmXml& other = others[in.Below(others.size())];
  if (!other.elements.empty())
    elements.insert(elements.begin() + static_cast<long>(in.Below(n + 1)),
                    other.elements[in.Below(other.elements.size())]);
}

// A child line (<nd>, <member>, <tag>) deleted, duplicated, or swapped with another.
void EditChildLine(OsmXml& xml, FuzzInput& in) {
  auto& elements = xml.elements;
  const std::size_t n = elements.size();
  if (n == 0)
    return;
  auto& element = elements[in.Below(n)];
  if (element.size() < 3)
    return;
  const std::size_t a = 1 + in.Below(element.size() - 2);
  const std::size_t b = 1 + in.Below(element.size() - 2);
  const std::size_t edit = in.Below(3);
  if (edit == 0)
    element.erase(element.begin() + static_cast<long>(a));
  else if (edit == 1)
    element.insert(element.begin() + static_cast<long>(b), element[a]);
  else
    std::swap(element[a], element[b]);
}

// An attribute value made a weird number (an id, ref, lat, lon, version, v).
void MakeValueWeird(OsmXml& xml, FuzzInput& in) {
  std::string* line = PickLine(xml, {}, in);
  if (line == nullptr)
    return;
  const auto values = AttributeValues(*line, "");
  if (!values.empty()) {
    const auto [begin, end] = values[in.Below(values.size())];
    line->replace(begin, end - begin, WeirdNumberText(in));
  }
}

// A tag's value made odd (and maybe its key).
void MakeTagOdd(OsmXml& xml, FuzzInput& in) {
  std::vector<std::string*> tags;
  for (auto& element : xml.elements) {
    for (auto& line : element) {
      if (StartsWith(Trimmed(line), "<tag"))
        tags.push_back(&line);
    }
  }
  if (tags.empty())
    return;
  std::string& tag = *tags[in.Below(tags.size())];
  static const char* const kKeys[] = {
      "height",      "building:levels", "min_height",    "building:min_level",
      "roof:height", "building",        "building:part", "type",
      "highway",     "tunnel"};
  if (in.Chance(0.3))
    SetAttribute(tag, "k", kKeys[in.Below(sizeof kKeys / sizeof kKeys[0])]);
  static const char* const kValues[] = {"yes",         "no",    "part", "multipolygon", "inner", "",
                                        "residential", "&amp;", "&#0;", "&#x10FFFF;"};
  SetAttribute(
      tag, "v",
      in.Chance(0.6) ? WeirdNumberText(in) : kValues[in.Below(sizeof kValues / sizeof kValues[0])]);
}

// A way's ring broken: open, closed on another node, or through a missing one.
void BreakWayRing(OsmXml& xml, FuzzInput& in) {
  const auto ways = xml.Find("<way");
  if (ways.empty())
    return;
  auto& way = xml.elements[ways[in.Below(ways.size())]];
  std::vector<std::size_t> nds;
  for (std::size_t i = 0; i < way.size(); ++i) {
    if (StartsWith(Trimmed(way[i]), "<nd"))
      nds.push_back(i);
  }
  if (nds.empty())
    return;
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
}

// A node moved.
void MoveNode(OsmXml& xml, FuzzInput& in) {
  auto& elements = xml.elements;
  const auto nodes = xml.Find("<node");
  if (nodes.empty())
    return;
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
}

// The bounds: dropped, shrunk off the venue's centre, or made odd.
void EditBounds(OsmXml& xml, FuzzInput& in) {
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
    return;
  }
}

// A relation's member: its role, type or ref changed.
void EditMember(OsmXml& xml, FuzzInput& in) {
  const auto relations = xml.Find("<relation");
  if (relations.empty())
    return;
  auto& relation = xml.elements[relations[in.Below(relations.size())]];
  std::string& line = relation[in.Below(relation.size())];
  if (!StartsWith(Trimmed(line), "<member"))
    return;
  static const char* const kRoles[] = {"outer", "inner", "", "part", "outline"};
  static const char* const kTypes[] = {"way", "node", "relation", "area"};
  const std::size_t edit = in.Below(3);
  if (edit == 0)
    SetAttribute(line, "role", kRoles[in.Below(5)]);
  else if (edit == 1)
    SetAttribute(line, "type", kTypes[in.Below(4)]);
  else
    SetAttribute(line, "ref", in.Chance(0.5) ? "1" : AttributeValue(relation[0], "id"));
}

// An id or a ref made another element's id.
void ShareId(OsmXml& xml, FuzzInput& in) {
  std::string* line = PickLine(xml, {}, in);
  std::string* other = PickLine(xml, {}, in);
  if (line == nullptr)
    return;
  const std::string id = AttributeValue(*other, "id");
  if (!id.empty())
    SetAttribute(*line, in.Chance(0.5) ? "id" : "ref", id);
}

}  // namespace

void EditOsmXml(OsmXml& xml, const std::vector<OsmXml>& others, FuzzInput& in) {
  switch (in.Below(14)) {
    case 0:
      DeleteElement(xml, in);
      break;
    case 1:
      DuplicateElement(xml, in);
      break;
    case 2:
      MoveElement(xml, in);
      break;
    case 3:
      InsertOtherElement(xml, others, in);
      break;
    case 4:
    case 5:
    case 6:
      EditChildLine(xml, in);
      break;
    case 7:
      MakeValueWeird(xml, in);
      break;
    case 8:
      MakeTagOdd(xml, in);
      break;
    case 9:
      BreakWayRing(xml, in);
      break;
    case 10:
      MoveNode(xml, in);
      break;
    case 11:
      EditBounds(xml, in);
      break;
    case 12:
      EditMember(xml, in);
      break;
    default:
      ShareId(xml, in);
      break;
  }
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
