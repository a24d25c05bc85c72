#include "common/scenario_import/place_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common/config/config_error.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/generated_json.h"
#include "common/scenario_generator/portable_random.h"
#include "common/scenario_generator/uav_baseline.h"
#include "common/scenario_generator/ue_placement.h"
#include "common/scenario_import/footprint_overlaps.h"
#include "common/scenario_import/geojson_reader.h"
#include "common/scenario_import/osm_reader.h"
#include "common/scenario_import/street_ues.h"

namespace rlpos {
namespace {

// Draws of the UEs before giving up (the generator's count).
constexpr int kUeAttempts = 100;
// m: features this far outside the venue are still read (a building the edge cuts).
constexpr double kReadMargin = 20.0;
// The venue's height limit: the generator's, or the tallest building and this much air.
constexpr double kMinVenueHeight = 60.0;
constexpr double kAirAboveTallest = 10.0;
constexpr double kAboveRoof = 5.0;  // as the generator's baseline

std::string Degrees(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

std::string Plural(int n, const std::string& one) {
  return std::to_string(n) + " " + one + (n == 1 ? "" : "s");
}

// The lon/lat box of the venue's rectangle grown by `margin`.
GeoBox VenueArea(const LocalProjection& projection, const VenueSize& size, double margin) {
  GeoBox box{180, 90, -180, -90};
  const double hx = size.width / 2 + margin, hy = size.depth / 2 + margin;
  for (double fx : {-1.0, 0.0, 1.0}) {
    for (double fy : {-1.0, 0.0, 1.0}) {
      box.Extend(projection.Inverse({fx * hx, fy * hy}));
    }
  }
  return box;
}

std::string BoxText(const GeoBox& b) {
  return "lat " + Degrees(b.min_lat) + " to " + Degrees(b.max_lat) + ", lon " + Degrees(b.min_lon) +
         " to " + Degrees(b.max_lon);
}

PlaceData ReadPlace(const PlaceImportOptions& o, PlaceFormat format, const GeoBox& area) {
  std::error_code error;
  if (!std::filesystem::exists(o.file, error))
    throw ConfigError::AboutFile("cannot open: No such file or directory");
  if (std::filesystem::is_directory(o.file, error))
    throw ConfigError::AboutFile("is a folder, not a map file");
  return format == PlaceFormat::kOsm ? ReadOsmFile(o.file, area) : ReadGeoJsonFile(o.file, area);
}

// The data must hold the venue's centre; a venue reaching past it is warned about.
void CheckExtent(const PlaceData& data, const PlaceImportOptions& o, const PlaceVenue& venue,
                 const LocalProjection& projection, std::vector<ImportWarning>& warnings) {
  const std::string option = o.bbox ? "--bbox" : "--center";
  if (!data.extent) {
    throw ConfigError::AboutFile("no data: the file holds no points (an empty extract)");
  }
  if (!data.extent->Contains(venue.center)) {
    throw ConfigError(option, "the venue's centre " + Degrees(venue.center.lat) + "," +
                                  Degrees(venue.center.lon) + " is outside the data (" +
                                  BoxText(*data.extent) + ")");
  }
  // A metre past the data is rounding, not a venue off the map.
  const GeoBox area = VenueArea(projection, venue.size, -1.0);
  const GeoBox& e = *data.extent;
  if (area.min_lon < e.min_lon || area.min_lat < e.min_lat || area.max_lon > e.max_lon ||
      area.max_lat > e.max_lat) {
    warnings.push_back({option, "the venue reaches beyond the data (" + BoxText(e) +
                                    "): the map knows no buildings or streets there"});
  }
}

// A box per footprint, for the generator's baseline (its centre building, its roof).
std::vector<BuildingSpec> BaselineBoxes(const std::vector<PlaceBuilding>& buildings) {
  std::vector<BuildingSpec> boxes;
  for (const auto& b : buildings) {
    const Bounds2 r = BoundsOf(b.footprint.outer);
    BuildingSpec spec;
    spec.name = b.name;
    spec.xmin = r.xmin;
    spec.xmax = r.xmax;
    spec.ymin = r.ymin;
    spec.ymax = r.ymax;
    spec.height = b.height.height;
    boxes.push_back(spec);
  }
  return boxes;
}

constexpr double kUavSpreadM = 5.0;

// The generator's baseline over the box of the central building; a UAV over a taller footprint
// than that (the box is not the footprint) rises above it.
std::vector<UavSpec> PlaceUavs(const Venue& venue, const std::vector<PlaceBuilding>& buildings,
                               int count) {
  std::vector<UavSpec> uavs = BaselineUavs(venue, BaselineBoxes(buildings), count);
  // Over a small central building the roof's even steps can fall under the checks' 1 m between
  // UAVs: then they stand 5 m apart along x around the roof's middle, inside the venue.
  bool crowded = false;
  for (std::size_t u = 1; u < uavs.size(); ++u)
    crowded = crowded || std::abs(uavs[u].initial.x - uavs[u - 1].initial.x) +
                                 std::abs(uavs[u].initial.y - uavs[u - 1].initial.y) <
                             kUavSpreadM;
  if (crowded) {
    const double middle = std::clamp(uavs.front().initial.x, kUavSpreadM * count / 2.0,
                                     venue.width - kUavSpreadM * count / 2.0);
    for (std::size_t u = 0; u < uavs.size(); ++u) {
      const double offset = kUavSpreadM * (static_cast<double>(u) - (count - 1) / 2.0);
      uavs[u].initial.x = std::round(2.0 * (middle + offset)) / 2.0;  // to the half metre
      uavs[u].initial.y = uavs.front().initial.y;
    }
  }
  for (auto& uav : uavs) {
    for (const auto& b : buildings) {
      if (Contains(b.footprint, {uav.initial.x, uav.initial.y}))
        uav.initial.z = std::max(uav.initial.z, b.height.height + kAboveRoof);
    }
  }
  return uavs;
}

PlaceSummary Summarise(const std::vector<PlaceBuilding>& buildings) {
  PlaceSummary s;
  s.buildings = static_cast<int>(buildings.size());
  for (const auto& b : buildings) {
    s.parts += b.is_part ? 1 : 0;
    s.above_ground += b.height.min_height > 0 ? 1 : 0;
    s.from_height += b.height.source == HeightSource::kHeight ? 1 : 0;
    s.from_levels += b.height.source == HeightSource::kLevels ? 1 : 0;
    s.from_default += b.height.source == HeightSource::kDefault ? 1 : 0;
  }
  return s;
}

// The scenario's checks on the document; an error names the map's element where it can.
void Validate(const nlohmann::json& document, const std::vector<PlaceBuilding>& buildings) {
  try {
    ParseScenario(document);
  } catch (const ConfigError& e) {
    const std::string prefix = "/buildings/";
    if (e.path().rfind(prefix, 0) == 0) {
      const std::size_t i = std::strtoul(e.path().c_str() + prefix.size(), nullptr, 10);
      if (i < buildings.size()) {
        throw ConfigError(buildings[i].source,
                          e.problem() + " (as the scenario's " + e.path() + ")");
      }
    }
    throw;
  }
}

// The scenario: the venue and its buildings, its UEs (drawn on the ground with the generator's
// demands) and UAVs, the generator's radio and loss model, a description that credits the data
// and says how to make it again.
Scenario PlaceScenario(const PlaceImportOptions& o, PlaceFormat format, const PlaceVenue& venue,
                       const std::vector<PlaceBuilding>& buildings, const UeGround& ground) {
  Scenario s;
  s.venue.width = venue.size.width;
  s.venue.depth = venue.size.depth;
  double tallest = 0;
  for (const auto& b : buildings)
    tallest = std::max(tallest, b.height.height);
  s.venue.height = std::max(kMinVenueHeight, std::ceil(tallest) + kAirAboveTallest);
  s.wifi.width_mhz = GeneratedChannelWidthMhz(o.uavs);
  s.wifi.channel = GeneratedUavChannels(o.uavs).front();
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  const int ue_count = ResolvedUeCount(o);
  PortableRandom random(o.seed);
  std::optional<UeSpots> spots;
  for (int attempt = 0; attempt < kUeAttempts && !spots; ++attempt)
    spots = DrawUeSpots(ground, ue_count, o.ue_groups, random);
  if (!spots) {
    throw ConfigError("--ues", "found no outdoor spot for " + Plural(ue_count, "UE") +
                                   (o.ue_groups > 0 ? " in " + Plural(o.ue_groups, "group") : "") +
                                   " in " + std::to_string(kUeAttempts) +
                                   " draws: the venue has too little open ground");
  }
  for (std::size_t i = 0; i < spots->positions.size(); ++i) {
    s.ues.emplace_back();
    s.ues.back().name = "ue" + std::to_string(i);
    s.ues.back().position = spots->positions[i];
  }
  // The generator's demand mix and budget: 20 UEs at MCS 0 per UAV.
  DrawDemands(s.ues, kDemandBudgetUes * McsDataRateMbps(phy, 0) * o.uavs, phy, random);
  for (const auto& b : buildings)
    s.buildings.push_back(PlaceBuildingSpec(b));
  s.uavs = PlaceUavs(s.venue, buildings, o.uavs);
  s.uavs_listed = o.uavs > 1;
  s.propagation = GeneratedPropagation(!buildings.empty());
  s.name = o.name.empty() ? PlaceFormatName(format) + "-" + PlaceFileStem(o.file) : o.name;
  const std::string source = format == PlaceFormat::kOsm
                                 ? "OpenStreetMap data ((c) OpenStreetMap contributors, ODbL 1.0)"
                                 : "GeoJSON data";
  s.description =
      "Imported from " + source + ", " + std::filesystem::path(o.file).filename().string() + ": " +
      Degrees(venue.size.width) + " x " + Degrees(venue.size.depth) + " m around " +
      Degrees(venue.center.lat) + "," + Degrees(venue.center.lon) + "; " +
      Plural(static_cast<int>(buildings.size()), "building") + "; " + spots->summary + "; " +
      Plural(o.uavs, "UAV") + ", baseline " + BaselineSummary(s.venue, BaselineBoxes(buildings)) +
      ". Reproduce: " + PlaceCommandLine(o) + ".";
  return s;
}

}  // namespace

std::string PlaceCommandLine(const PlaceImportOptions& o) {
  const PlaceFormat format = o.format ? *o.format : PlaceFormatOfFile(o.file);
  std::string line = "rlpos-sim import --from " + PlaceFormatName(format) + " " +
                     std::filesystem::path(o.file).filename().string();
  if (o.bbox) {
    line += " --bbox " + Degrees(o.bbox->min_lon) + "," + Degrees(o.bbox->min_lat) + "," +
            Degrees(o.bbox->max_lon) + "," + Degrees(o.bbox->max_lat);
  } else if (o.center && o.size) {
    line += " --center " + Degrees(o.center->lat) + "," + Degrees(o.center->lon) + " --size " +
            Degrees(o.size->width) + "x" + Degrees(o.size->depth);
  }
  line += " --ues " + std::to_string(ResolvedUeCount(o));
  if (o.ue_groups > 0)
    line += " --ue-groups " + std::to_string(o.ue_groups);
  line += " --uavs " + std::to_string(o.uavs) + " --seed " + std::to_string(o.seed);
  const HeightRules defaults;
  if (o.heights.level_height != defaults.level_height)
    line += " --level-height " + Degrees(o.heights.level_height);
  if (o.heights.default_height != defaults.default_height)
    line += " --default-height " + Degrees(o.heights.default_height);
  if (!o.name.empty())
    line += " --name " + o.name;
  return line;
}

std::string PlaceSummaryLine(const PlaceSummary& s) {
  std::string line = Degrees(s.width) + " x " + Degrees(s.depth) + " m: ";
  if (s.buildings == 0) {
    line += "no buildings";
  } else {
    line += Plural(s.buildings, "building") + " (height " + std::to_string(s.from_height) +
            ", levels " + std::to_string(s.from_levels) + ", default " +
            std::to_string(s.from_default) + "; " + Plural(s.parts, "part") + ", " +
            std::to_string(s.above_ground) + " above the ground)";
  }
  line += "; clipped " + std::to_string(s.clipped) + ", outlines replaced " +
          std::to_string(s.outlines_replaced) + "; rings repaired " +
          std::to_string(s.rings_repaired) + ", dropped " + std::to_string(s.rings_dropped) +
          "; overlaps trimmed " + std::to_string(s.overlaps_trimmed) + ", stacked " +
          std::to_string(s.overlaps_stacked) + ", dropped " + std::to_string(s.overlaps_dropped) +
          "; bad heights " + std::to_string(s.bad_heights) + "; skipped ways " +
          std::to_string(s.ways_skipped) + ", relations " + std::to_string(s.relations_skipped) +
          "; " + Plural(s.ues, "UE") + (s.ues_on_streets ? " along the streets" : " outdoors");
  if (s.ue_groups > 0)
    line += " in " + Plural(s.ue_groups, "group");
  return line + "; " + Plural(s.uavs, "UAV");
}

PlaceImportResult ImportPlace(const PlaceImportOptions& o) {
  const PlaceFormat file_format = PlaceFormatOfFile(o.file);
  if (o.format && *o.format != file_format) {
    throw ConfigError("--from",
                      "\"" + PlaceFormatName(*o.format) + "\" does not read " +
                          (file_format == PlaceFormat::kOsm ? "an OpenStreetMap" : "a GeoJSON") +
                          " file (by its extension)");
  }
  const PlaceVenue venue = ResolvePlaceVenue(o);
  const LocalProjection projection(venue.center);
  const VenueFrame frame{venue.size.width, venue.size.depth};
  PlaceImportResult result;
  PlaceData data = ReadPlace(o, file_format, VenueArea(projection, venue.size, kReadMargin));
  CheckExtent(data, o, venue, projection, result.warnings);
  result.warnings.insert(result.warnings.end(), data.warnings.begin(), data.warnings.end());

  FootprintCounts counts;
  std::vector<PlaceBuilding> buildings =
      BuildFootprints(data, projection, frame, o.heights, counts, result.warnings);
  OverlapCounts overlaps;
  ResolveOverlaps(buildings, o.heights.level_height, overlaps, result.warnings);
  UeGround ground;
  ground.venue = frame;
  for (const auto& b : buildings)
    ground.footprints.push_back(b.footprint);
  ground.streets = StreetSegments(data.streets, projection, frame);

  const Scenario s = PlaceScenario(o, file_format, venue, buildings, ground);
  result.json_text = GeneratedJsonText(s);
  result.document = nlohmann::json::parse(result.json_text);
  Validate(result.document, buildings);

  PlaceSummary& sum = result.summary;
  sum = Summarise(buildings);
  sum.width = venue.size.width;
  sum.depth = venue.size.depth;
  sum.clipped = counts.clipped;
  sum.outlines_replaced = counts.outlines_replaced;
  sum.rings_repaired = counts.rings_repaired;
  sum.rings_dropped = counts.rings_dropped + data.rings_dropped;
  sum.overlaps_trimmed = overlaps.trimmed;
  sum.overlaps_stacked = overlaps.stacked;
  sum.overlaps_dropped = overlaps.dropped;
  sum.bad_heights = counts.bad_heights;
  sum.ways_skipped = data.missing_nodes;
  sum.relations_skipped = data.incomplete_relations;
  sum.street_segments = static_cast<int>(ground.streets.size());
  sum.ues = static_cast<int>(s.ues.size());
  sum.ue_groups = o.ue_groups;
  sum.ues_on_streets = !ground.streets.empty();
  sum.uavs = o.uavs;
  return result;
}

}  // namespace rlpos
