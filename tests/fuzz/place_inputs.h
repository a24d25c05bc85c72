#pragma once
// Inputs for the fuzz of the place importer (place_import_fuzz_test.cc), made from a FuzzInput:
// structural edits of OpenStreetMap XML files (elements deleted, duplicated, moved, taken from
// other files; attributes and tags made odd; rings broken, nodes moved) and of GeoJSON documents
// (positions, rings, features, properties, the bbox); and places drawn at random, as
// OpenStreetMap XML or GeoJSON. The blocks of PBF files and their edits are in pbf_blocks.h.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/footprint.h"
#include "common/scenario_import/place_data.h"
#include "tests/fuzz/fuzz_input.h"

namespace rlpos::testing {

// The venue of the importer's test fixtures (tests/common/scenario_import/data/): 100 m x 100 m
// around 60.0 N, 25.0 E; their data reach 180 m east and west of it, 90 m north and south.
constexpr LonLat kPlaceFixtureCentre{25.0, 60.0};

// Texts numbers trip on: NaN, infinities, overflow of every width, signs, units, separators.
std::string WeirdNumberText(FuzzInput& in);

// A fifth, a heap over-read on a zero byte in a PBF string (a tag's key or value), the importer
// guards against (osm_reader.cc's CheckTagLists), so the fuzz makes such strings.
// Known bugs of libosmium (in 2.19.0, the system's, and still in 2.23.1): undefined behaviour
// (signed overflow) on some bad files, which the RLPOS_SANITIZE build reports. The fuzz keeps
// clear of them unless RLPOS_FUZZ_KNOWN_BUGS is set (KnownOsmiumBugsIncluded), so that it can
// find others; with it set, the sanitizer build reports them:
//  - XML: a coordinate with a positive exponent (lat="1e999"): location.hpp's
//    string_to_location_coordinate multiplies by 10 per unit of the exponent (a build without
//    the sanitizers reads 1e999 as 0);
//  - XML and PBF: a way or relation id beyond +-2^62 that the area assembler makes an area of:
//    area.hpp's object_id_to_area_id, std::abs(id) * 2;
//  - PBF: coordinates and delta-coded values that overflow 64 bits: pbf_decoder.hpp's
//    convert_pbf_lat/lon (c * granularity + offset), delta.hpp's DeltaDecode::update;
bool KnownOsmiumBugsIncluded();
// Whether OpenStreetMap XML text holds a coordinate or an id of the first two kinds.
bool HitsKnownOsmiumXmlBug(const std::string& text);

// An OpenStreetMap XML file as lines: those before the first element (the declaration, <osm>,
// <bounds>), the elements (a node, way or relation with its child lines, or a comment), and
// those from </osm> on.
struct OsmXml {
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> elements;
  std::vector<std::string> tail;

  std::string Text() const;  // the file again
  // The elements whose first line starts with `prefix` ("<node").
  std::vector<std::size_t> Find(const char* prefix) const;
};

OsmXml SplitOsmXml(const std::string& text);
// One structural edit of an OpenStreetMap XML file; `others` are files whose elements it may
// take (the other fixtures).
void EditOsmXml(OsmXml& xml, const std::vector<OsmXml>& others, FuzzInput& in);

// A random place in the fixtures' venue frame (metres): buildings of any shape (rectangles,
// turned ones, polygons that may cross themselves, slivers, ones that share edges on a coarse
// grid), some with holes, tags odd or missing; streets across it.
struct RandomBuilding {
  std::vector<std::vector<Point2>> rings;  // outer first; open
  std::vector<std::pair<std::string, std::string>> tags;
};
struct RandomPlace {
  std::vector<RandomBuilding> buildings;
  std::vector<std::vector<Point2>> streets;
};

RandomPlace MakeRandomPlace(FuzzInput& in);
// The place as OpenStreetMap XML: nodes shared where points coincide, a building with holes
// (and now and then one without) as a multipolygon relation, now and then a way left open.
std::string RandomPlaceAsOsmXml(const RandomPlace& place, FuzzInput& in);
// The place as GeoJSON: polygons (now and then a multipolygon, a ring left open, a height as a
// number), streets as lines.
std::string RandomPlaceAsGeoJson(const RandomPlace& place, FuzzInput& in);

// One structural edit of a GeoJSON document: a position deleted, doubled, moved or made odd;
// a ring opened, turned or cut short; a feature deleted or doubled; a geometry of another type;
// a property or the bbox made odd; coordinates nested deeper or shallower. Numbers JSON cannot
// hold are put in as the strings "@1e999@", "@-1e999@" and "@NaN@".
void EditGeoJson(nlohmann::json& doc, FuzzInput& in);
// The document's text with those strings made numbers (1e999 parses as an infinity, NaN not
// at all).
std::string WithUnwritableNumbers(std::string text);

// `text` in gzip's format (an .osm.gz file).
std::string Gzipped(const std::string& text);

}  // namespace rlpos::testing
