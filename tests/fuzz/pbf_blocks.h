#pragma once
// The blocks of PBF files for the fuzz of the place importer (place_import_fuzz_test.cc): read
// and written again, and their protobuf fields parsed, edited as what they are and encoded again.
#include <cstdint>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_input.h"

namespace rlpos::testing {

// A block of a PBF file, uncompressed.
struct PbfBlock {
  std::string type;  // "OSMHeader" or "OSMData"
  std::string data;
};

// The blocks of a PBF file (a 4-byte size, a BlobHeader, a Blob, each), inflated; none when it
// does not read.
std::vector<PbfBlock> ReadPbfBlocks(const std::string& file);
// The blocks as a PBF file, each in a raw (uncompressed) blob: edits of a block reach the
// decoder of its content rather than zlib's check.
std::string PbfFile(const std::vector<PbfBlock>& blocks);

// The messages of a PBF file (OSM-binary's fileformat.proto and osmformat.proto) whose fields
// the fuzz edits as what they are: nested messages and packed varints. Other length-delimited
// fields are bytes (strings).
enum class PbfMessage {
  kOther,
  kHeaderBlock,
  kPrimitiveBlock,
  kStringTable,
  kGroup,
  kNode,
  kDense,
  kDenseInfo,
  kWay,
  kRelation,
  kInfo
};

// A field of a protobuf message (wire types 0 and 2: PBF files have no others).
struct ProtoField {
  enum class Kind { kVarint, kBytes, kMessage, kPacked };
  std::uint64_t number = 0;
  Kind kind = Kind::kVarint;
  std::uint64_t value = 0;               // kVarint
  std::string bytes;                     // kBytes
  PbfMessage type = PbfMessage::kOther;  // kMessage
  std::vector<ProtoField> fields;        // kMessage
  std::vector<std::uint64_t> values;     // kPacked
};

// `data` as the fields of a `type` message; false when it is not one.
bool ParseProto(const std::string& data, PbfMessage type, std::vector<ProtoField>& fields);
std::string SerializeProto(const std::vector<ProtoField>& fields);
// One edit of a parsed block: a varint (an id, the granularity, an offset), an element of a
// packed array (a delta-coded id or coordinate, a string index, a member type) made odd,
// dropped or given twice, a string of the table made another, a field dropped, given twice or
// moved, or the bytes of a message (the string table) damaged. Unless KnownOsmiumBugsIncluded,
// odd varints stay below 2^30 (no coordinate or id overflows), only the string table is damaged
// (its bytes hold no numbers), and no string of the table gets a zero byte.
void EditProto(std::vector<ProtoField>& block, FuzzInput& in);

}  // namespace rlpos::testing
