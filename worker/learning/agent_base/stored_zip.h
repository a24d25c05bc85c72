#pragma once
// A strict reader of the zip archives torch::save writes, for files that come from other
// machines: the whole file in memory (bounded), its end records and central directory checked up
// front, and only stored (uncompressed) entries handed out, each with its local header matched
// against the central directory and its CRC-32 checked. No libtorch.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace rlpos {

class StoredZip {
 public:
  static constexpr std::uint64_t kMaxFileBytes = std::uint64_t{256} << 20;

  // Reads `file` and checks its directory. Throws std::runtime_error "<file>: <what is wrong>" for
  // a missing, unreadable or oversized file and for anything that is not a plain zip archive whose
  // entries all sit in one top-level folder.
  explicit StoredZip(const std::string& file);
  // The same checks of an archive already in memory (at most kMaxFileBytes), `name` standing for
  // the file in messages.
  static StoredZip FromBytes(std::string bytes, const std::string& name);

  const std::string& File() const { return file_; }
  std::uint64_t FileBytes() const { return bytes_.size(); }
  // The folder every entry is in: "policy" for "policy/data.pkl".
  const std::string& Folder() const { return folder_; }
  bool Has(const std::string& name) const { return entries_.count(name) != 0; }
  // A stored entry's bytes, valid as long as this object. Throws std::runtime_error naming the file
  // and the entry if it is missing or compressed, or its local header, bounds or CRC-32 are wrong.
  std::string_view Read(const std::string& name) const;

 private:
  struct Entry {
    std::uint16_t flags = 0;
    std::uint16_t method = 0;
    std::uint32_t crc = 0;
    std::uint32_t compressed_size = 0;
    std::uint32_t size = 0;
    std::uint32_t local_header = 0;  // offset
  };

  StoredZip() = default;
  void CheckDirectory();
  void ReadWholeFile();
  std::uint64_t FindEndRecord() const;
  void CheckZip64End(std::uint64_t at, std::uint64_t entries, std::uint64_t directory_bytes,
                     std::uint64_t directory_offset) const;
  void ReadCentralDirectory(std::uint64_t end_record);
  std::uint64_t ReadCentralEntry(std::uint64_t at, std::uint64_t directory_end);
  void CheckOneFolder();
  void CheckDataDescriptor(std::uint64_t at, const std::string& name, const Entry& entry) const;
  // bytes_[at, at + size), or a failure naming `what` if that runs past the end of the file.
  std::string_view Record(std::uint64_t at, std::uint64_t size, const std::string& what) const;
  [[noreturn]] void Fail(const std::string& what) const;

  std::string file_;
  std::string bytes_;
  std::uint64_t directory_offset_ = 0;  // entries' data ends before it
  std::string folder_;
  std::map<std::string, Entry> entries_;
};

}  // namespace rlpos
