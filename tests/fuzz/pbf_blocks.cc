// The blocks of PBF files for the place importer's fuzz: read (inflated) and written again, and
// their protobuf fields parsed, serialized and edited as what they are.
#include "tests/fuzz/pbf_blocks.h"

#include <zlib.h>

#include <tuple>
#include <utility>

#include "tests/fuzz/place_inputs.h"

namespace rlpos::testing {

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

// A packed value deleted, doubled, made odd, or the values cut short.
void EditPackedValues(ProtoParts& parts, FuzzInput& in) {
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
      values[static_cast<std::size_t>(at)] = WeirdVarint(values[static_cast<std::size_t>(at)], in);
  }
}

// A string made a key or value the importer looks for, another string, or mutated.
void EditString(ProtoParts& parts, FuzzInput& in) {
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
}

// A submessage's bytes mutated (only the string table's, unless the known bugs are included).
void DamageSubmessage(ProtoParts& parts, FuzzInput& in) {
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
}

// A field of a message deleted, doubled, or swapped with another.
void EditMessageFields(ProtoParts& parts, FuzzInput& in) {
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

}  // namespace

void EditProto(std::vector<ProtoField>& block, FuzzInput& in) {
  ProtoParts parts;
  CollectProto(block, parts);
  const std::size_t edit = in.Below(11);
  if (edit < 3 && !parts.varints.empty()) {
    ProtoField& f = *parts.varints[in.Below(parts.varints.size())];
    f.value = WeirdVarint(f.value, in);
  } else if (edit < 7 && !parts.packed.empty()) {
    EditPackedValues(parts, in);
  } else if (edit < 9 && !parts.strings.empty()) {
    EditString(parts, in);
  } else if (edit == 10) {
    DamageSubmessage(parts, in);
  } else {
    EditMessageFields(parts, in);
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

}  // namespace rlpos::testing
