#include "common/scenario_import/osm_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
// libosmium's object builder trips GCC 12's string-overread analysis (a false alarm on its
// strlen of tag texts), reported at the header's lines.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#include <osmium/area/assembler.hpp>
#include <osmium/area/multipolygon_manager.hpp>
#include <osmium/area/problem_reporter.hpp>
#include <osmium/handler.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/any_input.hpp>
#include <osmium/tags/tags_filter.hpp>
#include <osmium/visitor.hpp>
#pragma GCC diagnostic pop
#include <set>
#include <sstream>

#include "common/config/config_error.h"

namespace rlpos {
namespace {

using Index = osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
using LocationHandler = osmium::handler::NodeLocationsForWays<Index>;

// libosmium's PBF reader stores a string-table entry as it is, zero bytes included, and then walks
// a tag list with strlen: a key or value with a zero byte in it makes that walk run past the end
// of the list (a heap over-read in libosmium 2.19 to 2.23, found by tests/fuzz). So every tag
// list is walked here first, within its bounds, before any code of ours or libosmium's reads it:
// its texts must end exactly at its end, in key-value pairs.
void CheckTagLists(const osmium::memory::Buffer& buffer) {
  for (const auto& object : buffer.select<osmium::OSMObject>()) {
    const osmium::TagList& tags = object.tags();
    const auto* text = reinterpret_cast<const char*>(tags.data()) + sizeof(osmium::TagList);
    const auto* end = reinterpret_cast<const char*>(tags.data()) + tags.byte_size();
    std::size_t texts = 0;
    while (text < end) {
      const void* nul = std::memchr(text, '\0', static_cast<std::size_t>(end - text));
      if (nul == nullptr)
        break;
      text = static_cast<const char*>(nul) + 1;
      ++texts;
    }
    if (text != end || texts % 2 != 0) {
      throw ConfigError::AboutFile(std::string(osmium::item_type_to_name(object.type())) + " " +
                                   std::to_string(object.id()) +
                                   ": a tag's key or value holds a zero byte");
    }
  }
}

// osmium::apply(reader, handlers...) with every buffer checked first (CheckTagLists): the same
// items in the same order, and the handlers flushed once, at the end.
template <typename... Handlers>
void ApplyChecked(osmium::io::Reader& reader, Handlers&... handlers) {
  while (osmium::memory::Buffer buffer = reader.read()) {
    CheckTagLists(buffer);
    for (auto& item : buffer)
      osmium::apply_item(item, handlers...);
  }
  osmium::apply_flush(handlers...);
}

BuildingRole RoleOfTags(const osmium::TagList& tags) {
  return RoleOf(tags.get_value_by_key("building"), tags.get_value_by_key("building:part"));
}

bool IsBuilding(const osmium::TagList& tags) {
  return RoleOfTags(tags) != BuildingRole::kNone;
}

// A street a UE can stand on: any highway above ground (not in a tunnel).
bool IsStreet(const osmium::TagList& tags) {
  if (!tags.has_key("highway"))
    return false;
  const char* tunnel = tags.get_value_by_key("tunnel");
  return tunnel == nullptr || std::string(tunnel) == "no";
}

std::string OsmSource(const char* type, osmium::object_id_type id) {
  return std::string(type) + " " + std::to_string(id);
}

LonLat ToLonLat(const osmium::Location& l) {
  return {l.lon(), l.lat()};
}

std::string Position(const osmium::Location& l) {
  char text[64];
  std::snprintf(text, sizeof text, "%.7f,%.7f", l.lat(), l.lon());
  return text;
}

// The first problem the assembler met with each object: why it built no area from it.
class ProblemNotes : public osmium::area::ProblemReporter {
 public:
  std::map<std::pair<int, osmium::object_id_type>, std::string> first;

  void report_intersection(osmium::object_id_type, osmium::Location, osmium::Location,
                           osmium::object_id_type, osmium::Location, osmium::Location,
                           osmium::Location at) override {
    Note("its edges cross at " + Position(at));
  }
  void report_ring_not_closed(const osmium::NodeRef& nr, const osmium::Way*) override {
    Note("a ring does not close (at node " + std::to_string(nr.ref()) + ")");
  }
  void report_duplicate_segment(const osmium::NodeRef& a, const osmium::NodeRef&) override {
    Note("an edge is drawn twice (at node " + std::to_string(a.ref()) + ")");
  }
  void report_overlapping_segment(const osmium::NodeRef& a, const osmium::NodeRef&) override {
    Note("two edges overlap (at node " + std::to_string(a.ref()) + ")");
  }
  void report_touching_ring(osmium::object_id_type node, osmium::Location) override {
    Note("two rings touch at node " + std::to_string(node));
  }

 private:
  void Note(const std::string& text) {
    first.emplace(std::make_pair(static_cast<int>(m_object_type), m_object_id), text);
  }
};

struct GeoBounds {
  bool any = false;
  GeoBox box;
  void Add(const osmium::Location& l) {
    if (!any) {
      box = {l.lon(), l.lat(), l.lon(), l.lat()};
      any = true;
      return;
    }
    box.Extend({l.lon(), l.lat()});
  }
};

PlaceFeature FeatureFromTags(const osmium::TagList& tags, const char* type,
                             osmium::object_id_type id) {
  PlaceFeature f;
  f.source = OsmSource(type, id);
  f.id = std::string(type) + "/" + std::to_string(id);
  f.is_part = RoleOfTags(tags) == BuildingRole::kPart;
  for (const auto& key : PlaceTagKeys()) {
    if (const char* value = tags.get_value_by_key(key.c_str()))
      f.tags[key] = value;
  }
  return f;
}

GeoRing RingOf(const osmium::NodeRefList& nodes) {
  GeoRing ring;
  for (const auto& n : nodes)
    ring.push_back(ToLonLat(n.location()));
  if (ring.size() > 1 && ring.front().lon == ring.back().lon &&
      ring.front().lat == ring.back().lat) {
    ring.pop_back();
  }
  return ring;
}

// Relations: which ways are members of building multipolygons (pass 1).
class MemberWays : public osmium::handler::Handler {
 public:
  std::map<osmium::object_id_type, std::vector<osmium::object_id_type>> relations_of_way;
  // Ways that are an outer ring of a building multipolygon, and the first such relation.
  std::map<osmium::object_id_type, osmium::object_id_type> outer_of;

  void relation(const osmium::Relation& relation) {
    const char* type = relation.tags().get_value_by_key("type");
    if (type == nullptr || std::string(type) != "multipolygon" || !IsBuilding(relation.tags()))
      return;
    for (const auto& member : relation.members()) {
      if (member.type() != osmium::item_type::way)
        continue;
      relations_of_way[member.ref()].push_back(relation.id());
      if (std::string(member.role()) != "inner")
        outer_of.emplace(member.ref(), relation.id());
    }
  }
};

// Nodes, ways and (from the assembler) areas (pass 2).
class PlaceHandler : public osmium::handler::Handler {
 public:
  PlaceHandler(const GeoBox& area, const MemberWays& members, PlaceData& data)
      : area_(area), members_(members), data_(data) {}

  struct RelationProblem {
    bool near = false;
    std::string message;
  };

  GeoBounds extent;
  // Building multipolygons whose member ways lack nodes.
  std::map<osmium::object_id_type, RelationProblem> relation_problems;

  void node(const osmium::Node& node) {
    if (node.location().valid())
      extent.Add(node.location());
  }

  void way(const osmium::Way& way) {
    GeoBounds known;
    int missing = 0;
    for (const auto& n : way.nodes()) {
      if (n.location().valid())
        known.Add(n.location());
      else
        ++missing;
    }
    const bool near = known.any && known.box.Meets(area_);
    const bool building = IsBuilding(way.tags());
    const auto member = members_.relations_of_way.find(way.id());
    if (known.any && (building || member != members_.relations_of_way.end()))
      boxes_[way.id()] = known.box;
    if (member != members_.relations_of_way.end() && missing > 0) {
      for (osmium::object_id_type rel : member->second) {
        auto& problem = relation_problems[rel];
        problem.near = problem.near || near;
        if (problem.message.empty()) {
          problem.message =
              "its way " + std::to_string(way.id()) + " lacks " + NodesMissing(missing, way);
        }
      }
    }
    const bool street = IsStreet(way.tags());
    if ((!building && !street) || !near)
      return;
    if (missing > 0) {
      ++data_.missing_nodes;
      data_.warnings.push_back(
          {OsmSource("way", way.id()), "lacks " + NodesMissing(missing, way) + ": skipped"});
      return;
    }
    if (street) {
      std::vector<LonLat> line;
      for (const auto& n : way.nodes())
        line.push_back(ToLonLat(n.location()));
      data_.streets.push_back(std::move(line));
    }
    if (building && member == members_.relations_of_way.end())
      UnclosedBuilding(way);
  }

  // Whether a way, or a relation through its member ways, comes near the area (true when
  // nothing of it is known: better one warning too many than a silent drop).
  bool Near(osmium::item_type type, osmium::object_id_type id) const {
    if (type == osmium::item_type::way) {
      const auto box = boxes_.find(id);
      return box == boxes_.end() || box->second.Meets(area_);
    }
    bool any = false;
    for (const auto& [way, relations] : members_.relations_of_way) {
      if (std::find(relations.begin(), relations.end(), id) == relations.end())
        continue;
      const auto box = boxes_.find(way);
      if (box == boxes_.end())
        continue;
      if (box->second.Meets(area_))
        return true;
      any = true;
    }
    return !any;
  }

  // Areas the assembler built (or left empty when it could not).
  void area(const osmium::Area& area) {
    const char* type = area.from_way() ? "way" : "relation";
    const osmium::Box envelope = area.envelope();
    if (envelope.valid()) {
      const GeoBox box{envelope.bottom_left().lon(), envelope.bottom_left().lat(),
                       envelope.top_right().lon(), envelope.top_right().lat()};
      if (!box.Meets(area_))
        return;
    }
    if (!IsBuilding(area.tags()))
      return;  // building=no
    if (area.from_way()) {
      // A building way that is also the outline of a building multipolygon: the relation,
      // with its courtyards, is the building (the way's tags are a mapping slip).
      const auto relation = members_.outer_of.find(area.orig_id());
      if (relation != members_.outer_of.end()) {
        data_.warnings.push_back(
            {OsmSource("way", area.orig_id()), "also the outline of relation " +
                                                   std::to_string(relation->second) +
                                                   ": that relation's polygon is the building"});
        return;
      }
    }
    PlaceFeature f = FeatureFromTags(area.tags(), type, area.orig_id());
    for (const auto& outer : area.outer_rings()) {
      GeoPolygon polygon;
      polygon.outer = RingOf(outer);
      for (const auto& inner : area.inner_rings(outer))
        polygon.holes.push_back(RingOf(inner));
      f.polygons.push_back(std::move(polygon));
    }
    if (f.polygons.empty()) {
      const osmium::item_type item =
          area.from_way() ? osmium::item_type::way : osmium::item_type::relation;
      if (!Near(item, area.orig_id()))
        return;
      ++data_.rings_dropped;
      const auto why = notes_->first.find({static_cast<int>(item), area.orig_id()});
      data_.warnings.push_back(
          {f.source, "no valid outline (" +
                         (why != notes_->first.end() ? why->second : std::string("invalid rings")) +
                         "): dropped"});
      return;
    }
    data_.features.push_back(std::move(f));
  }

  void set_notes(const ProblemNotes* notes) { notes_ = notes; }

 private:
  static std::string NodesMissing(int missing, const osmium::Way& way) {
    return std::to_string(missing) + " of its " + std::to_string(way.nodes().size()) +
           " nodes (a cut extract)";
  }

  // A building way the assembler leaves alone: too short, or not closed. Closing it is a
  // repair when it has the points of a polygon.
  void UnclosedBuilding(const osmium::Way& way) {
    const auto& nodes = way.nodes();
    const bool closed = nodes.size() > 1 && nodes.front().location() == nodes.back().location();
    if (closed && nodes.size() > 3)
      return;  // the assembler's
    GeoRing ring;
    for (const auto& n : nodes) {
      const LonLat p = ToLonLat(n.location());
      if (ring.empty() || ring.back().lon != p.lon || ring.back().lat != p.lat)
        ring.push_back(p);
    }
    if (ring.size() > 1 && ring.front().lon == ring.back().lon &&
        ring.front().lat == ring.back().lat) {
      ring.pop_back();
    }
    if (ring.size() < 3) {
      ++data_.rings_dropped;
      data_.warnings.push_back(
          {OsmSource("way", way.id()), "fewer than 3 distinct points: not a building outline"});
      return;
    }
    PlaceFeature f = FeatureFromTags(way.tags(), "way", way.id());
    f.polygons.push_back({ring, {}});
    f.rings_repaired = 1;
    data_.warnings.push_back({f.source, "not closed: closed from its last node to its first"});
    data_.features.push_back(std::move(f));
  }

  GeoBox area_;
  std::map<osmium::object_id_type, GeoBox> boxes_;  // of building ways and member ways
  const MemberWays& members_;
  PlaceData& data_;
  const ProblemNotes* notes_ = nullptr;
};

PlaceData ReadOsm(const std::string& file, const GeoBox& area) {
  PlaceData data;
  const osmium::io::File input{file};
  ProblemNotes notes;
  osmium::area::Assembler::config_type config;
  config.problem_reporter = &notes;
  config.create_empty_areas = true;
  osmium::TagsFilter filter{false};
  filter.add_rule(true, osmium::TagMatcher{"building"});
  filter.add_rule(true, osmium::TagMatcher{"building:part"});
  osmium::area::MultipolygonManager<osmium::area::Assembler> manager{config, filter};
  MemberWays members;
  GeoBounds claimed;  // the area the extract says it covers (its header's boxes)
  {
    osmium::io::Reader relations{input, osmium::osm_entity_bits::relation};
    const osmium::io::Header header = relations.header();
    for (const auto& box : header.boxes()) {
      if (box.valid()) {
        claimed.Add(box.bottom_left());
        claimed.Add(box.top_right());
      }
    }
    ApplyChecked(relations, manager, members);
    relations.close();
    manager.prepare_for_lookup();
  }
  PlaceHandler handler(area, members, data);
  handler.set_notes(&notes);
  Index index;
  LocationHandler locations{index};
  locations.ignore_errors();  // a missing node leaves an invalid location, counted per way
  osmium::io::Reader reader{input, osmium::io::read_meta::no};
  auto areas = manager.handler(
      [&handler](osmium::memory::Buffer&& buffer) { osmium::apply(buffer, handler); });
  ApplyChecked(reader, locations, handler, areas);
  reader.close();
  // Relations that never completed lack member ways altogether.
  auto& problems = handler.relation_problems;
  manager.for_each_incomplete_relation([&](osmium::relations::RelationHandle handle) {
    const osmium::Relation& relation = *handle;
    int missing = 0;
    for (const auto& m : relation.members()) {
      if (m.type() == osmium::item_type::way && !manager.get_member_way(m.ref()))
        ++missing;
    }
    auto& problem = problems[relation.id()];
    problem.near = handler.Near(osmium::item_type::relation, relation.id());
    problem.message = std::to_string(missing) + " of its member ways are missing (a cut extract)";
  });
  for (const auto& [id, problem] : problems) {
    if (!problem.near)
      continue;
    ++data.incomplete_relations;
    data.warnings.push_back({OsmSource("relation", id), problem.message + ": skipped"});
  }
  // The header's claim where there is one (an extract's box reaches past its last node on
  // open ground), else the nodes'; an empty file has neither.
  if (handler.extent.any)
    data.extent = claimed.any ? claimed.box : handler.extent.box;
  return data;
}

}  // namespace

PlaceData ReadOsmFile(const std::string& file, const GeoBox& area) {
  try {
    return ReadOsm(file, area);
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    // libosmium's errors (XML, PBF, compression) say what was wrong in one line.
    std::string what = e.what();
    for (auto& c : what) {
      if (c == '\n')
        c = ' ';
    }
    throw ConfigError::AboutFile("not a readable OpenStreetMap file: " + what);
  }
}

}  // namespace rlpos
