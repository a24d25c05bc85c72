#include "worker/learning/agent_base/stored_zip.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace rlpos {
namespace {

constexpr std::uint32_t kLocalHeaderSignature = 0x04034b50;
constexpr std::uint32_t kCentralHeaderSignature = 0x02014b50;
constexpr std::uint32_t kEndSignature = 0x06054b50;
constexpr std::uint32_t kZip64EndSignature = 0x06064b50;
constexpr std::uint32_t kZip64LocatorSignature = 0x07064b50;
constexpr std::uint32_t kDataDescriptorSignature = 0x08074b50;

constexpr std::uint64_t kLocalHeaderBytes = 30;
constexpr std::uint64_t kCentralHeaderBytes = 46;
constexpr std::uint64_t kEndBytes = 22;
constexpr std::uint64_t kZip64EndBytes = 56;
constexpr std::uint64_t kZip64EndFollowing = kZip64EndBytes - 12;  // its own size field
constexpr std::uint64_t kZip64LocatorBytes = 20;
constexpr std::uint64_t kDataDescriptorBytes = 12;  // after an optional signature
constexpr std::uint64_t kMaxCommentBytes = 0xffff;
constexpr std::uint64_t kMaxNameBytes = 1024;

constexpr std::uint16_t kDataDescriptorFlag = 1u << 3;  // CRC and sizes follow the data
constexpr std::uint16_t kUtf8NameFlag = 1u << 11;
constexpr std::uint16_t kStoredMethod = 0;
// A 32-bit field at this value means "see the zip64 extra field", which a file of at most
// kMaxFileBytes never needs.
constexpr std::uint32_t kZip64Marker32 = 0xffffffff;
constexpr std::uint16_t kZip64Marker16 = 0xffff;

// The little-endian field of `width` bytes at `at` of a record the caller has bounds-checked.
std::uint64_t Field(std::string_view record, std::size_t at, int width) {
  std::uint64_t value = 0;
  for (int i = width - 1; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(record[at + static_cast<std::size_t>(i)]);
  return value;
}

std::uint16_t U16(std::string_view record, std::size_t at) {
  return static_cast<std::uint16_t>(Field(record, at, 2));
}
std::uint32_t U32(std::string_view record, std::size_t at) {
  return static_cast<std::uint32_t>(Field(record, at, 4));
}
std::uint64_t U64(std::string_view record, std::size_t at) {
  return Field(record, at, 8);
}

// CRC-32 as zip computes it (reflected polynomial 0xEDB88320), one table lookup per byte.
std::array<std::uint32_t, 256> MakeCrcTable() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int bit = 0; bit < 8; ++bit)
      c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}

std::uint32_t Crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = MakeCrcTable();
  std::uint32_t c = 0xffffffffu;
  for (char byte : bytes)
    c = table[(c ^ static_cast<unsigned char>(byte)) & 0xffu] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

bool IsNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

// Relative, '/'-separated, of plain characters, no empty, "." or ".." part: torch::save's names
// are of this shape, and nothing else then reaches a lookup or an error message.
bool IsPlainName(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameBytes)
    return false;
  std::size_t part_start = 0;
  for (std::size_t i = 0; i <= name.size(); ++i) {
    if (i < name.size() && name[i] != '/') {
      if (!IsNameChar(name[i]))
        return false;
      continue;
    }
    const std::string_view part = name.substr(part_start, i - part_start);
    if (part.empty() || part == "." || part == "..")
      return false;
    part_start = i + 1;
  }
  return true;
}

}  // namespace

StoredZip::StoredZip(const std::string& file) : file_(file) {
  ReadWholeFile();
  CheckDirectory();
}

StoredZip StoredZip::FromBytes(std::string bytes, const std::string& name) {
  StoredZip zip;
  zip.file_ = name;
  if (bytes.size() > kMaxFileBytes)
    zip.Fail("larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB");
  zip.bytes_ = std::move(bytes);
  zip.CheckDirectory();
  return zip;
}

void StoredZip::CheckDirectory() {
  ReadCentralDirectory(FindEndRecord());
  CheckOneFolder();
}

void StoredZip::Fail(const std::string& what) const {
  throw std::runtime_error(file_ + ": " + what);
}

std::string_view StoredZip::Record(std::uint64_t at, std::uint64_t size,
                                   const std::string& what) const {
  if (at > bytes_.size() || size > bytes_.size() - at)
    Fail(what + " runs past the end of the file");
  return std::string_view(bytes_).substr(at, size);
}

void StoredZip::ReadWholeFile() {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file_, error))
    Fail("no such file");
  const std::uintmax_t size = std::filesystem::file_size(file_, error);
  if (error)
    Fail("cannot read its size");
  if (size > kMaxFileBytes)
    Fail("larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB");
  std::ifstream in(file_, std::ios::binary);
  bytes_.resize(size);
  if (!in.read(bytes_.data(), static_cast<std::streamsize>(size)) || in.peek() != EOF)
    Fail("cannot read it whole");
}

// The end record is the last 22 bytes but for a comment of up to 64 KiB, whose length it gives:
// the one whose comment reaches exactly the end of the file.
std::uint64_t StoredZip::FindEndRecord() const {
  if (bytes_.size() < kEndBytes)
    Fail("not a zip archive (too short)");
  const std::uint64_t last = bytes_.size() - kEndBytes;
  const std::uint64_t first = last > kMaxCommentBytes ? last - kMaxCommentBytes : 0;
  for (std::uint64_t at = last + 1; at-- > first;) {
    if (U32(bytes_, at) == kEndSignature && at + kEndBytes + U16(bytes_, at + 20) == bytes_.size())
      return at;
  }
  Fail("not a zip archive (no end of central directory record)");
}

// torch::save also writes zip64's end record and its locator between the directory and the end
// record; they must say what the end record says.
void StoredZip::CheckZip64End(std::uint64_t at, std::uint64_t entries,
                              std::uint64_t directory_bytes, std::uint64_t directory_offset) const {
  const std::string_view r =
      Record(at, kZip64EndBytes + kZip64LocatorBytes, "the zip64 end record");
  const std::size_t locator = kZip64EndBytes;
  const bool consistent = U32(r, 0) == kZip64EndSignature && U64(r, 4) == kZip64EndFollowing &&
                          U32(r, 16) == 0 && U32(r, 20) == 0 && U64(r, 24) == entries &&
                          U64(r, 32) == entries && U64(r, 40) == directory_bytes &&
                          U64(r, 48) == directory_offset &&
                          U32(r, locator) == kZip64LocatorSignature && U32(r, locator + 4) == 0 &&
                          U64(r, locator + 8) == at && U32(r, locator + 16) == 1;
  if (!consistent)
    Fail("the zip64 end record disagrees with the end record");
}

void StoredZip::ReadCentralDirectory(std::uint64_t end_record) {
  const std::string_view end = Record(end_record, kEndBytes, "the end record");
  const std::uint16_t entries = U16(end, 10);
  const std::uint32_t directory_bytes = U32(end, 12);
  directory_offset_ = U32(end, 16);
  if (U16(end, 4) != 0 || U16(end, 6) != 0 || U16(end, 8) != entries)
    Fail("a zip archive split over several disks");
  if (entries == kZip64Marker16 || directory_bytes == kZip64Marker32 ||
      directory_offset_ == kZip64Marker32)
    Fail("zip64 sizes in the end record");
  const std::uint64_t directory_end = directory_offset_ + directory_bytes;
  if (directory_end > end_record)
    Fail("the central directory overlaps the end record");
  const std::uint64_t gap = end_record - directory_end;
  if (gap == kZip64EndBytes + kZip64LocatorBytes)
    CheckZip64End(directory_end, entries, directory_bytes, directory_offset_);
  else if (gap != 0)
    Fail("unknown bytes between the central directory and the end record");

  std::uint64_t at = directory_offset_;
  for (int i = 0; i < entries; ++i)
    at = ReadCentralEntry(at, directory_end);
  if (at != directory_end)
    Fail("the central directory's size disagrees with its entries");
}

// One central directory header at `at`; returns where the next one starts.
std::uint64_t StoredZip::ReadCentralEntry(std::uint64_t at, std::uint64_t directory_end) {
  const std::string_view header = Record(at, kCentralHeaderBytes, "a central directory entry");
  if (U32(header, 0) != kCentralHeaderSignature)
    Fail("a central directory entry without its signature");
  Entry entry;
  entry.flags = U16(header, 8);
  entry.method = U16(header, 10);
  entry.crc = U32(header, 16);
  entry.compressed_size = U32(header, 20);
  entry.size = U32(header, 24);
  const std::uint64_t name_bytes = U16(header, 28);
  const std::uint64_t next = at + kCentralHeaderBytes + name_bytes + U16(header, 30) +
                             U16(header, 32);  // name, extra field, comment
  entry.local_header = U32(header, 42);
  if (next > directory_end)
    Fail("a central directory entry runs past the directory");
  const std::string name(bytes_, at + kCentralHeaderBytes, name_bytes);
  if (!IsPlainName(name))
    Fail("an entry name that is not a plain relative path");
  if ((entry.flags & ~(kDataDescriptorFlag | kUtf8NameFlag)) != 0)
    Fail("entry " + name + " has flags other than a data descriptor's (encrypted?)");
  if (U16(header, 34) != 0)
    Fail("entry " + name + " starts on another disk");
  if (entry.compressed_size == kZip64Marker32 || entry.size == kZip64Marker32 ||
      entry.local_header == kZip64Marker32)
    Fail("entry " + name + " has zip64 sizes");
  if (entry.local_header + kLocalHeaderBytes > directory_offset_)
    Fail("entry " + name + "'s local header is not before the central directory");
  if (!entries_.emplace(name, entry).second)
    Fail("entry " + name + " is in the archive twice");
  return next;
}

// torch::save puts every entry in one folder named after the archive; a file that mixes folders
// is not one of its files.
void StoredZip::CheckOneFolder() {
  if (entries_.empty())
    Fail("an empty zip archive");
  const std::string& some = entries_.begin()->first;
  const std::size_t slash = some.find('/');
  if (slash == std::string::npos)
    Fail("entry " + some + " is not in a folder");
  folder_ = some.substr(0, slash);
  for (const auto& [name, entry] : entries_) {
    if (name.compare(0, slash + 1, some, 0, slash + 1) != 0)
      Fail("entries in more than one folder (" + folder_ + ", " + name + ")");
  }
}

std::string_view StoredZip::Read(const std::string& name) const {
  const auto found = entries_.find(name);
  if (found == entries_.end())
    Fail("no entry " + name);
  const Entry& entry = found->second;
  if (entry.method != kStoredMethod)
    Fail("entry " + name + " is compressed (method " + std::to_string(entry.method) +
         "); only stored entries are read");
  if (entry.compressed_size != entry.size)
    Fail("stored entry " + name + " has two sizes");

  const std::string_view local = Record(entry.local_header, kLocalHeaderBytes, "a local header");
  const std::uint64_t name_bytes = U16(local, 26);
  const std::uint64_t data_at =
      entry.local_header + kLocalHeaderBytes + name_bytes + U16(local, 28);
  const bool same_header =
      U32(local, 0) == kLocalHeaderSignature && U16(local, 6) == entry.flags &&
      U16(local, 8) == entry.method &&
      Record(entry.local_header + kLocalHeaderBytes, name_bytes, "a local header") == name;
  if (!same_header)
    Fail("entry " + name + "'s local header disagrees with the central directory");
  // With a data descriptor the local header may leave CRC and sizes at 0 (torch::save does).
  const bool descriptor = (entry.flags & kDataDescriptorFlag) != 0;
  const auto agrees = [descriptor](std::uint32_t local_value, std::uint32_t central_value) {
    return local_value == central_value || (descriptor && local_value == 0);
  };
  if (!agrees(U32(local, 14), entry.crc) || !agrees(U32(local, 18), entry.compressed_size) ||
      !agrees(U32(local, 22), entry.size))
    Fail("entry " + name + "'s local header disagrees with the central directory");

  const std::string_view data = Record(data_at, entry.size, "entry " + name);
  if (data_at + entry.size > directory_offset_)
    Fail("entry " + name + " overlaps the central directory");
  if (descriptor)
    CheckDataDescriptor(data_at + entry.size, name, entry);
  if (Crc32(data) != entry.crc)
    Fail("entry " + name + " fails its CRC-32 check");
  return data;
}

void StoredZip::CheckDataDescriptor(std::uint64_t at, const std::string& name,
                                    const Entry& entry) const {
  if (U32(Record(at, 4, "entry " + name + "'s data descriptor"), 0) == kDataDescriptorSignature)
    at += 4;  // the signature is optional
  const std::string_view d =
      Record(at, kDataDescriptorBytes, "entry " + name + "'s data descriptor");
  if (at + kDataDescriptorBytes > directory_offset_ || U32(d, 0) != entry.crc ||
      U32(d, 4) != entry.compressed_size || U32(d, 8) != entry.size)
    Fail("entry " + name + "'s data descriptor disagrees with the central directory");
}

}  // namespace rlpos
