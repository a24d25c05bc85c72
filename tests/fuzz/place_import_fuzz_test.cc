// Fuzz of the place importer (ImportPlace, common/scenario_import/place_import.h): OpenStreetMap
// XML, OpenStreetMap PBF and GeoJSON files made from valid ones, from a fixed seed. The test
// fixtures (tests/common/scenario_import/data/) and the shipped extract (data/osm/) are mutated:
// bytes flipped, ranges cut, duplicated and spliced; elements deleted, duplicated, moved and
// taken from other files; numbers made huge, NaN or negative; rings broken and nodes moved onto
// each other; the extract's blocks unpacked, edited and dropped. Places drawn at random
// (buildings of any shape, their tags odd or missing, inside and across the venue) reach the
// geometry behind the readers. Each input is written to a temporary file and imported with a
// small venue inside the data; it must be refused with a ConfigError of one line, or imported
// into a scenario that agrees with its summary (the same bytes when imported twice). Anything
// else fails: another exception (the input is then kept in the temporary folder under the name
// the failure gives), a crash or an ASan or UBSan report in the RLPOS_SANITIZE build, or an
// import that runs for over a minute (a hang: the program aborts, naming the input's file).
// Inputs that would hit the known bugs of libosmium (place_inputs.h: undefined behaviour the
// sanitizers report) are counted as skipped, or made so as not to hit them; RLPOS_FUZZ_KNOWN_BUGS=1
// imports them too. RLPOS_FUZZ_VERBOSE=1 prints the refusals by their reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario_import/place_import.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/pbf_blocks.h"
#include "tests/fuzz/place_inputs.h"

namespace rlpos {
namespace place_fuzz {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rlpos::testing;  // FuzzInput and the input makers (place_inputs.h, pbf_blocks.h)

// Inputs per test: some 13 s in all in a RelWithDebInfo build (an import takes a millisecond or
// two, one of the 148 KB extract some 8 ms), some 85 s with the sanitizers (libosmium starts
// threads for each file it reads, which ASan makes slow).
constexpr int kOsmXmlInputs = 2500;
constexpr int kGeoJsonInputs = 3000;
constexpr int kRandomPlaceInputs = 1600;  // half OSM XML, half GeoJSON
constexpr int kPbfInputs = 500;
constexpr std::uint64_t kPlaceSeed = 20261201;
// An import that runs this long is a hang.
constexpr auto kHangLimit = std::chrono::seconds(60);
// One accepted input in this many is imported twice, to compare the bytes.
constexpr int kTwiceEvery = 25;

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string FixtureFile(const std::string& name) {
  return std::string(RLPOS_SOURCE_DIR) + "/tests/common/scenario_import/data/" + name;
}

// Senate Square in the shipped extract (data/osm/README.md), made smaller.
constexpr LonLat kExtractCentre{24.9505, 60.1697};

// A per-process folder for the inputs, removed at the end.
class FuzzFolder {
 public:
  FuzzFolder()
      : path_(fs::temp_directory_path() / ("rlpos-place-fuzz-" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~FuzzFolder() {
    std::error_code error;
    fs::remove_all(path_, error);
  }
  FuzzFolder(const FuzzFolder&) = delete;
  FuzzFolder& operator=(const FuzzFolder&) = delete;

  std::string Write(const std::string& name, const std::string& bytes) const {
    const std::string file = (path_ / name).string();
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file;
  }

  // A copy of the input that outlives the folder, with a note beside it (<copy>.txt: the
  // command that imports it, and `what_happened`): the copy's path.
  static std::string Keep(const PlaceImportOptions& options, const std::string& what, int input,
                          const std::string& what_happened) {
    const fs::path kept = fs::temp_directory_path() /
                          ("rlpos-place-fuzz-failure-" + what + "-" + std::to_string(input) + "-" +
                           fs::path(options.file).filename().string());
    std::error_code error;
    fs::copy_file(options.file, kept, fs::copy_options::overwrite_existing, error);
    if (error)
      return "(not kept: " + error.message() + ")";
    PlaceImportOptions again = options;
    again.file = kept.string();
    std::ofstream(kept.string() + ".txt")
        << "cd " << kept.parent_path().string() << " && " << PlaceCommandLine(again) << "\n"
        << what_happened << "\n";
    return kept.string();
  }

 private:
  fs::path path_;
};

// Aborts the program when one import runs longer than kHangLimit, naming the input: a hang would
// otherwise show only as CTest's timeout, without the input.
class Watchdog {
 public:
  Watchdog() : thread_([this] { Watch(); }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void Begin(const std::string& what, int input, const std::string& file) {
    std::lock_guard<std::mutex> lock(mutex_);
    label_ = what + " input " + std::to_string(input) + " (" + file + ")";
    started_ = std::chrono::steady_clock::now();
    running_ = true;
  }
  void End() {
    std::lock_guard<std::mutex> lock(mutex_);
    running_ = false;
  }

 private:
  void Watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_) {
      wake_.wait_for(lock, std::chrono::seconds(1));
      if (running_ && std::chrono::steady_clock::now() - started_ > kHangLimit) {
        std::fprintf(stderr, "PlaceImportFuzz: %s has run for over %lld s: a hang\n",
                     label_.c_str(), static_cast<long long>(kHangLimit.count()));
        std::abort();
      }
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false, running_ = false;
  std::string label_;
  std::chrono::steady_clock::time_point started_;
  std::thread thread_;  // last: it starts once the rest is made
};

// Counts both outcomes and fails on a third. RLPOS_FUZZ_VERBOSE=1 also counts the refusals by
// their reason (the message with its numbers as #), keeping the first input of each: to see how
// deep the fuzz gets, and to have an input for each refusal.
struct PlaceOutcomes {
  struct Reason {
    long count = 0;
    std::string first;  // the kept input
  };
  long accepted = 0, refused = 0;
  long skipped = 0;  // not imported: they hit a known libosmium bug (place_inputs.h)
  std::map<std::string, Reason> reasons;

  void Refused(const std::string& message, const PlaceImportOptions& options, const char* what,
               int input) {
    ++refused;
    if (std::getenv("RLPOS_FUZZ_VERBOSE") == nullptr)
      return;
    std::string key;
    for (const char c : message.substr(0, 70))
      key += (c >= '0' && c <= '9') ? '#' : c;
    Reason& reason = reasons[key];
    if (reason.count++ == 0)
      reason.first = FuzzFolder::Keep(options, what, input, message);
  }
  void ExpectBoth(const char* what, int inputs) const {
    std::printf("%s: %ld accepted, %ld refused, %ld skipped (known libosmium bugs)\n", what,
                accepted, refused, skipped);
    std::vector<std::pair<long, std::string>> counts;
    for (const auto& [key, reason] : reasons)
      counts.emplace_back(reason.count, key + "  (" + reason.first + ")");
    std::sort(counts.rbegin(), counts.rend());
    for (const auto& [count, line] : counts)
      std::printf("  %6ld  %s\n", count, line.c_str());
    EXPECT_GT(accepted, 0) << what << ": no input was imported; the fuzz never got deep";
    EXPECT_GT(refused, 0) << what << ": no input was refused; the fuzz never mutated";
    EXPECT_EQ(accepted + refused + skipped, inputs) << what;
  }
};

// What an imported scenario must agree with: its summary and the options.
void CheckImported(const PlaceImportResult& r, const PlaceImportOptions& o,
                   const std::string& where) {
  const json& d = r.document;
  ASSERT_TRUE(d.is_object()) << where;
  ASSERT_TRUE(d.contains("buildings") && d.at("buildings").is_array()) << where;
  ASSERT_TRUE(d.contains("ues") && d.at("ues").is_array()) << where;
  EXPECT_EQ(d.at("buildings").size(), static_cast<std::size_t>(r.summary.buildings)) << where;
  EXPECT_EQ(d.at("ues").size(), static_cast<std::size_t>(r.summary.ues)) << where;
  EXPECT_EQ(r.summary.ues, ResolvedUeCount(o)) << where;
  EXPECT_EQ(r.summary.uavs, o.uavs) << where;
  EXPECT_TRUE(std::isfinite(r.summary.width) && r.summary.width >= kMinPlaceVenueSide &&
              r.summary.width <= kMaxPlaceVenueSide)
      << where;
  EXPECT_EQ(json::parse(r.json_text), d) << where;
  for (const auto& w : r.warnings)
    EXPECT_FALSE(w.path.empty() || w.message.empty()) << where << ": " << w.message;
}

// Imports `bytes` as the file `name` of `folder` with `options` and counts the outcome: imported
// (its checks run) or refused with a ConfigError of one line. Another exception fails the test,
// naming the input and keeping it.
void Import(const std::string& bytes, const std::string& name, PlaceImportOptions options,
            const char* what, int input, const FuzzFolder& folder, Watchdog& watchdog,
            PlaceOutcomes& outcomes) {
  options.file = folder.Write(name, bytes);
  const std::string where = std::string(what) + " input " + std::to_string(input);
  watchdog.Begin(what, input, options.file);
  try {
    const PlaceImportResult r = ImportPlace(options);
    CheckImported(r, options, where);
    if (input % kTwiceEvery == 0) {
      EXPECT_EQ(ImportPlace(options).json_text, r.json_text) << where << ": not the same bytes";
    }
    ++outcomes.accepted;
  } catch (const ConfigError& e) {
    const std::string line = e.describe();
    EXPECT_FALSE(line.empty()) << where;
    EXPECT_EQ(line.find('\n'), std::string::npos)
        << where << ": not one line: " << line << "; kept as "
        << FuzzFolder::Keep(options, what, input, line);
    outcomes.Refused(line, options, what, input);
  } catch (const std::exception& e) {
    ADD_FAILURE() << where << ": unexpected exception: " << e.what() << "; kept as "
                  << FuzzFolder::Keep(options, what, input, e.what());
    outcomes.Refused(std::string("unexpected: ") + e.what(), options, what, input);
  } catch (...) {
    ADD_FAILURE() << where << ": unexpected exception of no std type; kept as "
                  << FuzzFolder::Keep(options, what, input, "an exception of no std type");
    outcomes.Refused("unexpected", options, what, input);
  }
  watchdog.End();
}

// The fixtures' options (FixtureOptions of the importer's tests), now and then another valid
// venue, UE and UAV count, seed or height rule.
PlaceImportOptions VenueOptions(const LonLat& centre, double side, FuzzInput& in) {
  PlaceImportOptions o;
  o.center = centre;
  o.size = VenueSize{side, side};
  o.ues = 4;
  o.seed = 1;
  if (!in.Chance(0.2))
    return o;
  static const double kSides[] = {10, 25.5, 60, 100, 150};
  o.size = VenueSize{kSides[in.Below(5)], kSides[in.Below(5)]};
  if (in.Chance(0.2)) {
    // The same venue as a box (--bbox): some 110 m x 110 m.
    o.bbox =
        GeoBox{centre.lon - 0.001, centre.lat - 0.0005, centre.lon + 0.001, centre.lat + 0.0005};
    o.center.reset();
    o.size.reset();
  }
  static const int kUes[] = {1, 4, 20, 50};
  o.ues = kUes[in.Below(4)];
  o.ue_groups = in.Chance(0.3) ? static_cast<int>(in.Below(static_cast<std::size_t>(*o.ues))) : 0;
  o.uavs = 1 + static_cast<int>(in.Below(3));
  o.seed = in.Below(1000);
  static const double kLevels[] = {3.0, 0.5, 10.0};
  static const double kDefaults[] = {10.0, 0.1, 1000.0};
  o.heights.level_height = kLevels[in.Below(3)];
  o.heights.default_height = kDefaults[in.Below(3)];
  return o;
}

const std::vector<std::string>& OsmFixtureNames() {
  static const std::vector<std::string> kNames{
      "bad_heights.osm",  "broken_rings.osm", "courtyard.osm", "cut_extract.osm",
      "edge.osm",         "empty.osm",        "feet.osm",      "nested_parts.osm",
      "no_buildings.osm", "overlaps.osm",     "parts.osm",     "truncated.osm"};
  return kNames;
}

TEST(PlaceImportFuzz, OsmXmlRefusedOrImported) {
  std::vector<std::string> texts;
  std::vector<OsmXml> split;
  for (const auto& name : OsmFixtureNames()) {
    texts.push_back(ReadBytes(FixtureFile(name)));
    ASSERT_FALSE(texts.back().empty()) << name;
    split.push_back(SplitOsmXml(texts.back()));
    ASSERT_EQ(split.back().Text(), texts.back()) << name << ": the split must give the file back";
  }
  FuzzInput in(kPlaceSeed);
  const FuzzFolder folder;
  Watchdog watchdog;
  PlaceOutcomes outcomes;
  for (int i = 0; i < kOsmXmlInputs; ++i) {
    const std::size_t k = in.Below(texts.size());
    std::string text;
    const std::size_t mode = in.Below(20);  // mostly structural: expat is fuzzed upstream
    if (mode == 0) {
      text = in.Mutate(texts[k]);
    } else if (mode == 1) {  // the start of one file and the end of another
      const std::string& other = texts[in.Below(texts.size())];
      text = texts[k].substr(0, in.Below(texts[k].size() + 1)) +
             other.substr(in.Below(other.size() + 1));
    } else {
      OsmXml xml = split[k];
      for (std::size_t e = 1 + in.Below(4); e > 0; --e)
        EditOsmXml(xml, split, in);
      text = xml.Text();
      if (in.Chance(0.08))
        text = in.Mutate(text);
    }
    const bool known_bug = HitsKnownOsmiumXmlBug(text) && !KnownOsmiumBugsIncluded();
    std::string name = "input.osm";
    if (in.Chance(0.05)) {  // gzipped XML, now and then damaged
      name = "input.osm.gz";
      text = Gzipped(text);
      if (in.Chance(0.5))
        text = in.Mutate(text);
    }
    const PlaceImportOptions options = VenueOptions(kPlaceFixtureCentre, 100, in);
    if (known_bug)
      ++outcomes.skipped;
    else
      Import(text, name, options, "osm-xml", i, folder, watchdog, outcomes);
  }
  outcomes.ExpectBoth("osm xml", kOsmXmlInputs);
}

TEST(PlaceImportFuzz, GeoJsonRefusedOrImported) {
  const std::string place = ReadBytes(FixtureFile("place.geojson"));
  const std::string bad = ReadBytes(FixtureFile("bad_position.geojson"));
  ASSERT_FALSE(place.empty());
  ASSERT_FALSE(bad.empty());
  FuzzInput in(kPlaceSeed + 1);
  const FuzzFolder folder;
  Watchdog watchdog;
  PlaceOutcomes outcomes;
  for (int i = 0; i < kGeoJsonInputs; ++i) {
    const std::string& base = in.Chance(0.9) ? place : bad;
    std::string text;
    const std::size_t mode = in.Below(20);
    if (mode < 2) {
      text = in.Mutate(base);
    } else if (mode < 6) {
      text = in.MutateJsonValue(base);
    } else {
      json doc = json::parse(base);
      for (std::size_t e = 1 + in.Below(4); e > 0; --e)
        EditGeoJson(doc, in);
      text = WithUnwritableNumbers(doc.dump());
      if (in.Chance(0.1))
        text = in.Mutate(text);
    }
    const char* name = in.Chance(0.9) ? "input.geojson" : "input.json";
    Import(text, name, VenueOptions(kPlaceFixtureCentre, 100, in), "geojson", i, folder, watchdog,
           outcomes);
  }
  outcomes.ExpectBoth("geojson", kGeoJsonInputs);
}

TEST(PlaceImportFuzz, RandomPlacesRefusedOrImported) {
  FuzzInput in(kPlaceSeed + 2);
  const FuzzFolder folder;
  Watchdog watchdog;
  PlaceOutcomes osm, geojson;
  for (int i = 0; i < kRandomPlaceInputs; ++i) {
    const RandomPlace place = MakeRandomPlace(in);
    const PlaceImportOptions options = VenueOptions(kPlaceFixtureCentre, 100, in);
    if (i % 2 == 0) {
      std::string text = RandomPlaceAsOsmXml(place, in);
      if (in.Chance(0.2)) {
        OsmXml xml = SplitOsmXml(text);
        EditOsmXml(xml, {xml}, in);
        text = xml.Text();
      }
      if (HitsKnownOsmiumXmlBug(text) && !KnownOsmiumBugsIncluded())
        ++osm.skipped;
      else
        Import(text, "input.osm", options, "random-osm", i, folder, watchdog, osm);
    } else {
      std::string text = RandomPlaceAsGeoJson(place, in);
      if (in.Chance(0.2)) {
        json doc = json::parse(text);
        EditGeoJson(doc, in);
        text = WithUnwritableNumbers(doc.dump());
      }
      Import(text, "input.geojson", options, "random-geojson", i, folder, watchdog, geojson);
    }
  }
  osm.ExpectBoth("random places, osm xml", kRandomPlaceInputs / 2);
  geojson.ExpectBoth("random places, geojson", kRandomPlaceInputs - kRandomPlaceInputs / 2);
}

// libosmium keeps a zero byte inside a string of a PBF string table and then reads past the end
// of the tag list it made of it; the importer checks every tag list first and refuses the file.
TEST(PlaceImportFuzz, AZeroByteInATagOfAPbfIsRefusedInOneLine) {
  const std::string original =
      ReadBytes(std::string(RLPOS_SOURCE_DIR) + "/data/osm/helsinki-central.osm.pbf");
  std::vector<PbfBlock> blocks = ReadPbfBlocks(original);
  ASSERT_GT(blocks.size(), 1u);
  int changed = 0;
  for (std::size_t b = 1; b < blocks.size(); ++b) {
    std::vector<ProtoField> fields;
    ASSERT_TRUE(ParseProto(blocks[b].data, PbfMessage::kPrimitiveBlock, fields));
    for (ProtoField& f : fields) {
      if (f.number != 1 || f.kind != ProtoField::Kind::kMessage)
        continue;  // not the string table
      for (ProtoField& text : f.fields) {
        if (text.kind == ProtoField::Kind::kBytes && text.bytes == "building") {
          text.bytes = std::string("build\0ing", 9);  // same index, so the same tags use it
          ++changed;
        }
      }
    }
    blocks[b].data = SerializeProto(fields);
  }
  ASSERT_GT(changed, 0) << "no string table holds \"building\"";
  const FuzzFolder folder;
  PlaceImportOptions options;
  options.center = kExtractCentre;
  options.size = VenueSize{150, 150};
  options.ues = 4;
  options.file = folder.Write("input.osm.pbf", PbfFile(blocks));
  try {
    ImportPlace(options);
    FAIL() << "a tag with a zero byte in it was imported";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("a tag's key or value holds a zero byte"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(PlaceImportFuzz, PbfExtractRefusedOrImported) {
  const std::string original =
      ReadBytes(std::string(RLPOS_SOURCE_DIR) + "/data/osm/helsinki-central.osm.pbf");
  ASSERT_GT(original.size(), 100000u);
  const std::vector<PbfBlock> blocks = ReadPbfBlocks(original);
  ASSERT_GT(blocks.size(), 2u);
  ASSERT_EQ(blocks[0].type, "OSMHeader");
  std::vector<std::vector<ProtoField>> parsed(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    ASSERT_TRUE(ParseProto(
        blocks[b].data, b == 0 ? PbfMessage::kHeaderBlock : PbfMessage::kPrimitiveBlock, parsed[b]))
        << "block " << b;
    ASSERT_EQ(SerializeProto(parsed[b]), blocks[b].data) << "block " << b;
  }
  const FuzzFolder folder;
  // The blocks written raw make the same scenario as the file.
  PlaceImportOptions options;
  options.center = kExtractCentre;
  options.size = VenueSize{150, 150};
  options.ues = 4;
  options.file = folder.Write("input.osm.pbf", original);
  const std::string expected = ImportPlace(options).json_text;
  options.file = folder.Write("input.osm.pbf", PbfFile(blocks));
  ASSERT_EQ(ImportPlace(options).json_text, expected);

  FuzzInput in(kPlaceSeed + 3);
  Watchdog watchdog;
  PlaceOutcomes outcomes;
  for (int i = 0; i < kPbfInputs; ++i) {
    std::vector<PbfBlock> edited = blocks;
    std::string bytes;
    const std::size_t mode = in.Below(20);
    if (mode < 2) {  // the file's framing and its zlib streams
      bytes = in.Mutate(original);
    } else if (mode < 4) {  // a block dropped, given twice, moved, or of another type
      const std::size_t a = in.Below(edited.size()), b = in.Below(edited.size());
      switch (in.Below(4)) {
        case 0:
          edited.erase(edited.begin() + static_cast<long>(a));
          break;
        case 1:
          edited.insert(edited.begin() + static_cast<long>(b), edited[a]);
          break;
        case 2:
          std::swap(edited[a], edited[b]);
          break;
        default:
          edited[a].type = in.Chance(0.5) ? "OSMHeader" : in.Mutate(edited[a].type);
      }
      bytes = PbfFile(edited);
    } else if (mode < 5) {  // a block's bytes: the header's, any block's with the known bugs
      const std::size_t data_block = 1 + in.Below(edited.size() - 1);
      PbfBlock& block = edited[KnownOsmiumBugsIncluded() ? data_block : 0];
      block.data = in.Mutate(block.data);
      bytes = PbfFile(edited);
    } else {  // a block's fields, the header's now and then
      const std::size_t b = in.Chance(0.1) ? 0 : 1 + in.Below(edited.size() - 1);
      std::vector<ProtoField> fields = parsed[b];
      for (std::size_t e = 1 + in.Below(3); e > 0; --e)
        EditProto(fields, in);
      edited[b].data = SerializeProto(fields);
      bytes = PbfFile(edited);
    }
    Import(bytes, "input.osm.pbf", VenueOptions(kExtractCentre, 150, in), "pbf", i, folder,
           watchdog, outcomes);
  }
  outcomes.ExpectBoth("pbf", kPbfInputs);
}

}  // namespace
}  // namespace place_fuzz
}  // namespace rlpos
