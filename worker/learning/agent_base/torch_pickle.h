#pragma once
// The pickle of a saved network (data.pkl, as torch::save writes it for a module of float
// tensors) run by a bounded and strict unpickler, and the values it makes: the file-format half
// of ReadSavedTensors (saved_tensors.cc, which walks the values to the tensors). Internal to
// this folder.
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "worker/learning/agent_base/stored_zip.h"

namespace rlpos::torch_pickle {

// Far above what a network of this project needs (its data.pkl is under 1 KiB), far below what
// would strain memory: every opcode makes at most one value.
constexpr std::size_t kMaxPickleBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxValues = std::size_t{1} << 18;
constexpr std::size_t kMaxStackItems = std::size_t{1} << 16;
constexpr std::size_t kMaxMarks = 1024;
constexpr std::size_t kMaxMemoEntries = std::size_t{1} << 18;
constexpr std::size_t kMaxGlobalLineBytes = 256;
constexpr std::size_t kMaxDims = 16;
constexpr std::size_t kMaxKeyBytes = 256;
constexpr int kMaxModuleDepth = 64;
constexpr std::int64_t kMaxStorageFloats = StoredZip::kMaxFileBytes / sizeof(float);
constexpr std::uint64_t kPickleProtocol = 2;

// A failure inside the archive; ReadSavedTensors puts the file's name in front.
class BadFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Fail(const std::string& what);

// Text from the file as it may go into a one-line message.
std::string Printable(std::string_view text);

// A module attribute or storage key: it becomes part of a dotted name or an entry name.
bool IsWord(std::string_view text);

enum class Global { kRebuildTensor, kFloatStorage, kOrderedDict, kModuleClass };

enum class Kind { kInt, kBool, kString, kTuple, kDict, kGlobal, kObject, kStorage, kTensor };

const char* KindName(Kind kind);

// One value the pickle makes. Values live in one arena and name each other by index, so that a
// pickle making a dict hold itself leaks nothing, and the walk over modules can mark each visited.
struct Value {
  Kind kind = Kind::kInt;
  std::int64_t number = 0;  // kInt, kBool; kStorage: its floats; kTensor: its storage offset
  Global global = Global::kOrderedDict;  // kGlobal
  std::string text;  // kString; kGlobal, kObject: the class; kStorage, kTensor: the storage key
  // kTuple: its items; kDict: key, value, key, value...; kObject: its state dict once built.
  std::vector<std::size_t> items;
  std::vector<std::int64_t> sizes;  // kTensor
};

// Runs data.pkl: a stack machine over the allowed opcodes, each checked as it runs, whose REDUCEs
// may only rebuild float tensors and make empty OrderedDicts, and whose NEWOBJs may only make
// TorchScript module objects (opaque: a class name and, after BUILD, a state dict).
class Unpickler {
 public:
  explicit Unpickler(std::string_view pickle) : in_(pickle) {}

  // The index of the value the pickle leaves at its STOP.
  std::size_t Run();

  const Value& At(std::size_t index) const { return values_[index]; }
  std::size_t ValueCount() const { return values_.size(); }
  // The floats of the storage data/<key>, as its persistent ids say (all the same, or Run failed).
  std::int64_t StorageFloats(const std::string& key) const { return storage_floats_.at(key); }

 private:
  bool Step();
  // Each runs `opcode` if it is of its kind and says whether it was: the protocol, marks and
  // memo; the values pushed as the pickle spells them; the objects made of values on the stack.
  bool StepFrame(unsigned char opcode);
  bool StepLiteral(unsigned char opcode);
  bool StepObject(unsigned char opcode);
  std::string_view Bytes(std::uint64_t count);
  std::uint64_t Operand(int width);
  std::string_view Line();
  void Push(Value value);
  void PushIndex(std::size_t index);
  std::size_t Top() const;
  std::size_t Pop();
  std::vector<std::size_t> PopToMark();
  const Value& Expect(std::size_t index, Kind kind, const std::string& what) const;
  void PushGlobal();
  void Memoize(std::uint64_t slot);
  void Recall(std::uint64_t slot);
  void PushString();
  void PushInt(std::int64_t number);
  void PushTuple();
  void PushStorage();
  void Reduce();
  void NewObject();
  void SetItems();
  void Build();
  std::vector<std::int64_t> Ints(std::size_t tuple, const std::string& what) const;
  Value RebuildTensor(const Value& arguments) const;
  static std::int64_t ElementCount(const std::vector<std::int64_t>& sizes);
  static void CheckContiguous(const std::vector<std::int64_t>& sizes,
                              const std::vector<std::int64_t>& strides, std::int64_t count);

  std::string_view in_;
  std::size_t at_ = 0;
  std::vector<Value> values_;
  std::vector<std::size_t> stack_;
  std::vector<std::size_t> marks_;  // stack sizes at each open MARK
  std::unordered_map<std::uint64_t, std::size_t> memo_;
  std::map<std::string, std::int64_t> storage_floats_;
};

}  // namespace rlpos::torch_pickle
