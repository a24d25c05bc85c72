// The torch-free reader of torch::save's files against libtorch itself: the names, shapes and
// bits of named_parameters() for networks of both kinds and for the shipped policies; and, for the
// file being untrusted, a one-line std::runtime_error (never a crash, never garbage) for missing,
// empty, truncated and corrupted files, compressed entries, and pickles outside the allowed few
// opcodes, globals and tensor shapes.
#include "worker/learning/agent_base/saved_tensors.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/temp_dir.h"
#include "worker/learning/agent/mlp.h"
#include "worker/learning/agent/ue_set_module.h"
#include "worker/learning/agent_base/stored_zip.h"

namespace rlpos::saved_tensors_test {
namespace {

using rlpos::testing::ReadFile;
using rlpos::testing::TempDir;
using rlpos::testing::WriteFile;

bool SameBits(const float* a, const float* b, std::size_t count) {
  return count == 0 || std::memcmp(a, b, count * sizeof(float)) == 0;
}

void ExpectSameAsParameters(const std::vector<SavedTensor>& saved,
                            const torch::nn::Module& module) {
  const auto parameters = module.named_parameters();
  ASSERT_EQ(saved.size(), parameters.size());
  std::size_t i = 0;
  for (const auto& parameter : parameters) {
    const SavedTensor& t = saved[i++];
    EXPECT_EQ(t.name, parameter.key());
    const torch::Tensor values = parameter.value().detach().contiguous();
    EXPECT_EQ(t.sizes, values.sizes().vec()) << t.name;
    ASSERT_EQ(static_cast<std::int64_t>(t.values.size()), values.numel()) << t.name;
    EXPECT_TRUE(SameBits(t.values.data(), values.data_ptr<float>(), t.values.size())) << t.name;
  }
}

bool SameTensors(const std::vector<SavedTensor>& a, const std::vector<SavedTensor>& b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].name != b[i].name || a[i].sizes != b[i].sizes ||
        a[i].values.size() != b[i].values.size() ||
        !SameBits(a[i].values.data(), b[i].values.data(), a[i].values.size()))
      return false;
  }
  return true;
}

// `bytes` written to `file` and read: the tensors, or nothing after a std::runtime_error that is
// one line naming the file. Any other exception fails the test that called it.
std::optional<std::vector<SavedTensor>> ReadOrFail(const std::string& file,
                                                   const std::string& bytes) {
  WriteFile(file, bytes);
  try {
    return ReadSavedTensors(file);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return std::nullopt;
  }
}

// The message of the std::runtime_error reading `bytes` throws ("" if it reads).
std::string FailureOf(const std::string& file, const std::string& bytes) {
  WriteFile(file, bytes);
  try {
    ReadSavedTensors(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// --- A minimal zip writer, so that tests can build archives whose CRCs are right and whose
// entries say what the test wants.

std::uint32_t Crc32(const std::string& bytes) {
  std::uint32_t c = 0xffffffffu;
  for (char byte : bytes) {
    c ^= static_cast<unsigned char>(byte);
    for (int bit = 0; bit < 8; ++bit)
      c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

void Put(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i)
    out += static_cast<char>((value >> (8 * i)) & 0xff);
}

struct ZipEntry {
  std::string name;
  std::string bytes;
  bool deflate = false;  // as one stored deflate block: a valid stream, method 8
};

std::string Deflated(const std::string& bytes) {
  std::string block(1, '\x01');  // final block, stored
  Put(block, bytes.size(), 2);
  Put(block, ~bytes.size() & 0xffff, 2);
  return block + bytes;
}

std::string ZipArchive(const std::vector<ZipEntry>& entries) {
  std::string out;
  std::string directory;
  for (const ZipEntry& e : entries) {
    const std::string data = e.deflate ? Deflated(e.bytes) : e.bytes;
    const auto offset = out.size();
    std::string fields;  // version needed .. uncompressed size
    Put(fields, 20, 2);
    Put(fields, 0, 2);
    Put(fields, e.deflate ? 8 : 0, 2);
    Put(fields, 0, 4);  // time, date
    Put(fields, Crc32(e.bytes), 4);
    Put(fields, data.size(), 4);
    Put(fields, e.bytes.size(), 4);
    Put(out, 0x04034b50, 4);
    out += fields;
    Put(out, e.name.size(), 2);
    Put(out, 0, 2);
    out += e.name + data;
    Put(directory, 0x02014b50, 4);
    Put(directory, 20, 2);  // made by
    directory += fields;
    Put(directory, e.name.size(), 2);
    Put(directory, 0, 4);  // extra field and comment lengths
    Put(directory, 0, 8);  // disk, attributes
    Put(directory, offset, 4);
    directory += e.name;
  }
  const auto directory_offset = out.size();
  out += directory;
  Put(out, 0x06054b50, 4);
  Put(out, 0, 4);
  Put(out, entries.size(), 2);
  Put(out, entries.size(), 2);
  Put(out, directory.size(), 4);
  Put(out, directory_offset, 4);
  Put(out, 0, 2);
  return out;
}

// data.pkl and the storages of a file torch::save wrote, as they are, in folder "m".
struct SavedParts {
  std::string pickle;
  std::vector<std::string> storages;  // data/0, data/1...
};

SavedParts PartsOf(const std::string& file) {
  const StoredZip zip(file);
  SavedParts parts;
  parts.pickle = std::string(zip.Read(zip.Folder() + "/data.pkl"));
  for (int k = 0; zip.Has(zip.Folder() + "/data/" + std::to_string(k)); ++k)
    parts.storages.emplace_back(zip.Read(zip.Folder() + "/data/" + std::to_string(k)));
  return parts;
}

std::string Repacked(const SavedParts& parts, bool deflate_pickle = false) {
  std::vector<ZipEntry> entries;
  for (std::size_t k = 0; k < parts.storages.size(); ++k)
    entries.push_back({"m/data/" + std::to_string(k), parts.storages[k]});
  entries.push_back({"m/data.pkl", parts.pickle, deflate_pickle});
  entries.push_back({"m/version", "3\n"});
  return ZipArchive(entries);
}

// --- Hand-written pickles of one module with one tensor, in the opcodes torch::save uses.

std::string Str(const std::string& s) {
  std::string out = "X";
  Put(out, s.size(), 4);
  return out + s;
}

std::string Int(std::int64_t v) {
  std::string out;
  if (v >= 0 && v < 256) {
    out = "K";
    Put(out, static_cast<std::uint64_t>(v), 1);
  } else if (v >= 0 && v < 65536) {
    out = "M";
    Put(out, static_cast<std::uint64_t>(v), 2);
  } else {
    out = "J";
    Put(out, static_cast<std::uint64_t>(v), 4);
  }
  return out;
}

std::string IntTuple(const std::vector<std::int64_t>& values) {
  std::string out = "(";
  for (std::int64_t v : values)
    out += Int(v);
  return out + "t";
}

std::string Global(const std::string& module, const std::string& name) {
  return "c" + module + "\n" + name + "\n";
}

struct OneTensor {
  std::vector<std::int64_t> sizes{2, 3};
  std::vector<std::int64_t> strides{3, 1};
  std::int64_t offset = 1;
  std::int64_t storage_floats = 7;
  std::string storage_type = Global("torch", "FloatStorage");
  std::string rebuild = Global("torch._utils", "_rebuild_tensor_v2");
  std::string device = "cpu";
  std::string module_class = Global("__torch__", "Module");
};

std::string OneTensorPickle(const OneTensor& t) {
  const std::string storage = "(" + Str("storage") + t.storage_type + Str("0") + Str(t.device) +
                              Int(t.storage_floats) + "tQ";
  const std::string tensor = t.rebuild + "(" + storage + Int(t.offset) + IntTuple(t.sizes) +
                             IntTuple(t.strides) + "\x88" + Global("collections", "OrderedDict") +
                             ")Rt" + "R";
  return "\x80\x02" + t.module_class + ")\x81}(" + Str("weight") + tensor + "ub.";
}

// Floats 0, 1, 2... as a storage's bytes.
std::string CountingStorage(int floats) {
  std::string bytes;
  for (int i = 0; i < floats; ++i) {
    const float f = static_cast<float>(i);
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    Put(bytes, bits, 4);
  }
  return bytes;
}

std::string OneTensorArchive(const std::string& pickle, int storage_floats = 7) {
  return ZipArchive({{"m/data/0", CountingStorage(storage_floats)}, {"m/data.pkl", pickle}});
}

// --- The tests.

class SavedTensorsTest : public ::testing::Test {
 protected:
  // A small MLP's file, as the fuzzing tests' subject: mostly structure, little float data.
  std::string SaveSmallMlp() {
    torch::manual_seed(5);
    auto net = MakeMlp({6}, 4, 3);
    const std::string file = dir_.File("small.pt");
    torch::save(net, file);
    return file;
  }

  TempDir dir_;
};

TEST_F(SavedTensorsTest, MlpReadsAsItsNamedParameters) {
  torch::manual_seed(11);
  auto net = MakeMlp({16, 8}, 5, 3);
  const std::string file = dir_.File("mlp.pt");
  torch::save(net, file);
  ExpectSameAsParameters(ReadSavedTensors(file), *net);
}

// More memo slots than BINPUT's byte and a weight of more elements than BININT2's: LONG_BINPUT,
// LONG_BINGET and BININT.
TEST_F(SavedTensorsTest, DeepWideMlpReadsAsItsNamedParameters) {
  torch::manual_seed(12);
  std::vector<int> hidden(70, 3);
  hidden[0] = 256;
  auto net = MakeMlp(hidden, 300, 2);
  const std::string file = dir_.File("deep.pt");
  torch::save(net, file);
  const std::string pickle = PartsOf(file).pickle;
  ASSERT_NE(pickle.find("r\x00\x01\x00\x00", 0, 5), std::string::npos);  // LONG_BINPUT 256
  ExpectSameAsParameters(ReadSavedTensors(file), *net);
}

TEST_F(SavedTensorsTest, UeSetModuleReadsAsItsNamedParameters) {
  torch::manual_seed(13);
  UeSetModule module(2 + 4 * 7, SlotBlock{2, 4, 7}, std::vector<int>{8, 6}, std::vector<int>{16},
                     3);
  const std::string file = dir_.File("set.pt");
  torch::save(module, file);
  const std::vector<SavedTensor> saved = ReadSavedTensors(file);
  ASSERT_FALSE(saved.empty());
  EXPECT_EQ(saved.front().name, "phi.0.weight");
  EXPECT_EQ(saved.back().name, "rho.2.bias");
  ExpectSameAsParameters(saved, *module);
}

// The shipped MLPs read as torch::load reads them into a MakeMlp of the widths the tensors say.
TEST_F(SavedTensorsTest, ShippedPoliciesReadAsTorchLoadsThem) {
  for (const std::string policy : {"generalist-1uav", "generalist-multi"}) {
    SCOPED_TRACE(policy);
    const std::string file = std::string(RLPOS_SOURCE_DIR) + "/policies/" + policy + "/policy.pt";
    const std::vector<SavedTensor> saved = ReadSavedTensors(file);
    ASSERT_EQ(saved.size(), 6u);  // three Linear layers
    std::vector<int> hidden;
    for (std::size_t i = 0; i + 2 < saved.size(); i += 2)
      hidden.push_back(static_cast<int>(saved[i].sizes[0]));
    const int in = static_cast<int>(saved.front().sizes[1]);
    const int out = static_cast<int>(saved.back().sizes[0]);
    EXPECT_EQ(hidden, (std::vector<int>{128, 128}));
    std::ifstream settings(std::string(RLPOS_SOURCE_DIR) + "/policies/" + policy +
                           "/scenario.json");
    const auto actions = nlohmann::json::parse(settings)["env"]["actions"];
    EXPECT_EQ(out, static_cast<int>(actions.size()));  // one logit per move
    auto net = MakeMlp(hidden, in, out);
    torch::load(net, file);
    ExpectSameAsParameters(saved, *net);
  }
}

// The test's own zip writer, and a reader that does not lean on torch::save's particular layout
// (aligned entries, data descriptors, zip64 end records).
TEST_F(SavedTensorsTest, RepackedArchiveReadsTheSame) {
  const std::string file = SaveSmallMlp();
  const std::vector<SavedTensor> original = ReadSavedTensors(file);
  const auto repacked = ReadOrFail(dir_.File("repacked.pt"), Repacked(PartsOf(file)));
  ASSERT_TRUE(repacked.has_value());
  EXPECT_TRUE(SameTensors(*repacked, original));
}

TEST_F(SavedTensorsTest, HandWrittenPickleReadsItsTensor) {
  const auto saved = ReadOrFail(dir_.File("hand.pt"), OneTensorArchive(OneTensorPickle({})));
  ASSERT_TRUE(saved.has_value());
  ASSERT_EQ(saved->size(), 1u);
  EXPECT_EQ(saved->front().name, "weight");
  EXPECT_EQ(saved->front().sizes, (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(saved->front().values, (std::vector<float>{1, 2, 3, 4, 5, 6}));  // from offset 1
}

TEST_F(SavedTensorsTest, MissingAndEmptyFilesFail) {
  const std::string missing = dir_.File("missing.pt");
  try {
    ReadSavedTensors(missing);
    ADD_FAILURE() << "read a missing file";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": no such file");
  }
  EXPECT_THROW(ReadSavedTensors(dir_.path()), std::runtime_error);  // a folder
  EXPECT_NE(FailureOf(dir_.File("empty.pt"), "").find("empty.pt: not a zip archive"),
            std::string::npos);
}

TEST_F(SavedTensorsTest, TruncatedFilesFail) {
  const std::string small = ReadFile(SaveSmallMlp());
  const std::string shipped =
      ReadFile(std::string(RLPOS_SOURCE_DIR) + "/policies/generalist-multi/policy.pt");
  // Every length of the small file; the shipped one is mostly float data.
  for (const auto& [bytes, stride] : {std::pair{small, 1}, std::pair{shipped, 997}}) {
    std::vector<std::size_t> lengths;
    for (std::size_t n = 0; n < bytes.size(); n += stride)
      lengths.push_back(n);
    for (std::size_t cut = 1; cut <= 30; ++cut)
      lengths.push_back(bytes.size() - cut);
    for (std::size_t n : lengths)
      EXPECT_FALSE(ReadOrFail(dir_.File("cut.pt"), bytes.substr(0, n)).has_value()) << n;
  }
}

// A corrupted byte either fails the read or changes nothing that is read (a timestamp, padding,
// the compressed code): never garbage, never a crash.
TEST_F(SavedTensorsTest, FlippedBytesFailOrChangeNothing) {
  const std::string small_file = SaveSmallMlp();
  const std::string shipped_file =
      std::string(RLPOS_SOURCE_DIR) + "/policies/generalist-multi/policy.pt";
  std::mt19937 g(2024);
  int failed = 0;
  int flips = 0;
  for (const auto& [file, count] : {std::pair{small_file, 400}, std::pair{shipped_file, 100}}) {
    const std::string bytes = ReadFile(file);
    const std::vector<SavedTensor> original = ReadSavedTensors(file);
    std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
    std::uniform_int_distribution<int> mask(1, 255);
    for (int i = 0; i < count; ++i, ++flips) {
      std::string flipped = bytes;
      const std::size_t at = position(g);
      flipped[at] = static_cast<char>(flipped[at] ^ mask(g));
      const auto read = ReadOrFail(dir_.File("flipped.pt"), flipped);
      failed += !read.has_value();
      if (read) {
        EXPECT_TRUE(SameTensors(*read, original)) << "byte " << at << " of " << file;
      }
    }
  }
  EXPECT_GT(failed, flips / 4);  // most of a small file is headers and data that are checked
}

TEST_F(SavedTensorsTest, CorruptedFloatFailsTheCrc) {
  SavedParts parts = PartsOf(SaveSmallMlp());
  const std::string good = Repacked(parts);
  std::string bad = good;
  const std::size_t at = good.find(parts.storages[0]) + 5;  // data/0 comes first
  bad[at] = static_cast<char>(bad[at] ^ 0x40);
  EXPECT_NE(FailureOf(dir_.File("crc.pt"), bad).find("entry m/data/0 fails its CRC-32 check"),
            std::string::npos);
}

TEST_F(SavedTensorsTest, CompressedEntryFails) {
  const SavedParts parts = PartsOf(SaveSmallMlp());
  EXPECT_NE(FailureOf(dir_.File("deflated.pt"), Repacked(parts, true))
                .find("entry m/data.pkl is compressed (method 8)"),
            std::string::npos);
}

TEST_F(SavedTensorsTest, EntryNamesMustBePlainInOneFolder) {
  const std::string pickle = OneTensorPickle({});
  const std::string storage = CountingStorage(7);
  for (const std::string data : {"../data/0", "m/../data/0", "/m/data/0", "n/data/0"}) {
    SCOPED_TRACE(data);
    const std::string zip = ZipArchive({{data, storage}, {"m/data.pkl", pickle}});
    EXPECT_FALSE(ReadOrFail(dir_.File("names.pt"), zip).has_value());
  }
}

// Each pickle is a valid archive's data.pkl (right CRC): the unpickler's own checks.
TEST_F(SavedTensorsTest, PicklesOutsideTheAllowedFewFail) {
  OneTensor transposed;
  transposed.strides = {1, 2};
  OneTensor past_end;
  past_end.offset = 2;
  OneTensor huge;
  huge.sizes = {1 << 20, 1 << 20, 1 << 20};
  huge.strides = {1, 1, 1};
  OneTensor negative;
  negative.sizes = {-1, 3};
  OneTensor doubles;
  doubles.storage_type = Global("torch", "DoubleStorage");
  OneTensor system;
  system.rebuild = Global("os", "system");
  OneTensor cuda;
  cuda.device = "cuda:0";
  OneTensor plain_class;
  plain_class.module_class = Global("builtins", "object");
  OneTensor larger_storage;
  larger_storage.storage_floats = 8;  // than data/0 holds
  const std::string self_child =
      "\x80\x02" + Global("__torch__", "Module") + ")\x81q\x01}(" + Str("self") + "h\x01ub.";
  struct Case {
    std::string pickle;
    std::string says;
  };
  const std::vector<Case> cases{
      {OneTensorPickle(transposed), "not contiguous"},
      {OneTensorPickle(past_end), "outside its storage"},
      {OneTensorPickle(huge), "too many elements"},
      {OneTensorPickle(negative), "negative size"},
      {OneTensorPickle(doubles), "disallowed GLOBAL torch DoubleStorage"},
      {OneTensorPickle(system), "disallowed GLOBAL os system"},
      {OneTensorPickle(cuda), "not on the cpu"},
      {OneTensorPickle(plain_class), "disallowed GLOBAL builtins object"},
      {OneTensorPickle(larger_storage), "data/0 is not the size its storage says"},
      {self_child, "self appears twice"},
      {"\x80\x02N.", "opcode 0x4e at byte 2"},
      {"\x80\x03}.", "protocol other than 2"},
      {"}.", "PROTO other than first"},
      {"\x80\x02h\x07.", "empty memo slot"},
      {"\x80\x02}}.", "other than one value"},
      {"\x80\x02}.", "the root is not a built module"},
      {"\x80\x02" + std::string(2000, '(') + ".", "MARKs nested too deep"},
      {"\x80\x02" + std::string(70000, ')') + ".", "stack too deep"},
      {"\x80\x02(t", "ends inside an opcode"},
      {OneTensorPickle({}) + ".", "bytes after STOP"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.says);
    const std::string file = dir_.File("case.pt");
    const std::string failure = FailureOf(file, OneTensorArchive(c.pickle));
    EXPECT_EQ(failure.rfind(file + ": ", 0), 0u) << failure;
    EXPECT_NE(failure.find(c.says), std::string::npos) << failure;
  }
}

// Every truncation, and every byte flipped two ways, of a real data.pkl in an archive whose CRCs
// are right: the unpickler's bounds, not the CRC, must hold.
TEST_F(SavedTensorsTest, DamagedPicklesFailOrRead) {
  const SavedParts parts = PartsOf(SaveSmallMlp());
  const std::string file = dir_.File("pickle.pt");
  for (std::size_t n = 0; n < parts.pickle.size(); ++n) {
    SavedParts cut = parts;
    cut.pickle.resize(n);
    EXPECT_FALSE(ReadOrFail(file, Repacked(cut)).has_value()) << n;
  }
  std::mt19937 g(7);
  std::uniform_int_distribution<int> mask(1, 255);
  for (std::size_t at = 0; at < parts.pickle.size(); ++at) {
    for (int flip : {0xff, mask(g)}) {
      SavedParts flipped = parts;
      flipped.pickle[at] = static_cast<char>(flipped.pickle[at] ^ flip);
      ReadOrFail(file, Repacked(flipped));
    }
  }
}

}  // namespace
}  // namespace rlpos::saved_tensors_test
