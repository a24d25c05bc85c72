#include "worker/learning/agent_base/saved_tensors.h"

#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "worker/learning/agent_base/stored_zip.h"

namespace rlpos {
namespace {

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

// The opcodes torch::save writes for a module of float tensors (protocol 2), and no others.
namespace op {
constexpr unsigned char kProto = 0x80;
constexpr unsigned char kGlobal = 'c';
constexpr unsigned char kBinPut = 'q';
constexpr unsigned char kLongBinPut = 'r';
constexpr unsigned char kBinGet = 'h';
constexpr unsigned char kLongBinGet = 'j';
constexpr unsigned char kEmptyTuple = ')';
constexpr unsigned char kEmptyDict = '}';
constexpr unsigned char kMark = '(';
constexpr unsigned char kBinUnicode = 'X';
constexpr unsigned char kTuple = 't';
constexpr unsigned char kBinPersId = 'Q';
constexpr unsigned char kBinInt1 = 'K';
constexpr unsigned char kBinInt2 = 'M';
constexpr unsigned char kBinInt = 'J';
constexpr unsigned char kNewTrue = 0x88;
constexpr unsigned char kNewFalse = 0x89;
constexpr unsigned char kReduce = 'R';
constexpr unsigned char kNewObj = 0x81;
constexpr unsigned char kSetItems = 'u';
constexpr unsigned char kBuild = 'b';
constexpr unsigned char kStop = '.';
}  // namespace op

// A failure inside the archive; ReadSavedTensors puts the file's name in front.
class BadFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Fail(const std::string& what) {
  throw BadFile(what);
}

// Text from the file as it may go into a one-line message.
std::string Printable(std::string_view text) {
  constexpr std::size_t kMaxShown = 64;
  std::string shown;
  for (char c : text.substr(0, kMaxShown))
    shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  return text.size() > kMaxShown ? shown + "..." : shown;
}

bool IsWordChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// A module attribute or storage key: it becomes part of a dotted name or an entry name.
bool IsWord(std::string_view text) {
  if (text.empty() || text.size() > kMaxKeyBytes)
    return false;
  for (char c : text) {
    if (!IsWordChar(c))
      return false;
  }
  return true;
}

// TorchScript's classes for modules: "__torch__" or "__torch__.x.y", then a word.
bool IsModuleClass(std::string_view module, std::string_view name) {
  constexpr std::string_view kRoot = "__torch__";
  if (module.substr(0, kRoot.size()) != kRoot || !IsWord(name))
    return false;
  std::string_view rest = module.substr(kRoot.size());
  while (!rest.empty()) {
    const std::size_t dot = rest.find('.', 1);
    if (rest[0] != '.' || !IsWord(rest.substr(1, dot == std::string_view::npos ? dot : dot - 1)))
      return false;
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot);
  }
  return true;
}

enum class Global { kRebuildTensor, kFloatStorage, kOrderedDict, kModuleClass };

enum class Kind { kInt, kBool, kString, kTuple, kDict, kGlobal, kObject, kStorage, kTensor };

const char* KindName(Kind kind) {
  switch (kind) {
    case Kind::kInt:
      return "an integer";
    case Kind::kBool:
      return "a bool";
    case Kind::kString:
      return "a string";
    case Kind::kTuple:
      return "a tuple";
    case Kind::kDict:
      return "a dict";
    case Kind::kGlobal:
      return "a global";
    case Kind::kObject:
      return "a module";
    case Kind::kStorage:
      return "a storage";
    case Kind::kTensor:
      return "a tensor";
  }
  return "?";
}

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

Value Make(Kind kind) {
  Value v;
  v.kind = kind;
  return v;
}

// Runs data.pkl: a stack machine over the allowed opcodes, each checked as it runs, whose REDUCEs
// may only rebuild float tensors and make empty OrderedDicts, and whose NEWOBJs may only make
// TorchScript module objects (opaque: a class name and, after BUILD, a state dict).
class Unpickler {
 public:
  explicit Unpickler(std::string_view pickle) : in_(pickle) {}

  // The index of the value the pickle leaves at its STOP.
  std::size_t Run() {
    while (Step()) {
    }
    if (at_ != in_.size())
      Fail("data.pkl: bytes after STOP");
    if (!marks_.empty() || stack_.size() != 1)
      Fail("data.pkl: STOP with other than one value on the stack");
    return stack_[0];
  }

  const Value& At(std::size_t index) const { return values_[index]; }
  std::size_t ValueCount() const { return values_.size(); }
  // The floats of the storage data/<key>, as its persistent ids say (all the same, or Run failed).
  std::int64_t StorageFloats(const std::string& key) const { return storage_floats_.at(key); }

 private:
  // One opcode; false at STOP.
  bool Step() {
    const std::size_t op_at = at_;
    const auto opcode = static_cast<unsigned char>(Bytes(1)[0]);
    if ((op_at == 0) != (opcode == op::kProto))
      Fail("data.pkl: PROTO other than first");
    switch (opcode) {
      case op::kProto:
        if (Operand(1) != kPickleProtocol)
          Fail("data.pkl: pickle protocol other than 2");
        break;
      case op::kGlobal:
        PushGlobal();
        break;
      case op::kBinPut:
        Memoize(Operand(1));
        break;
      case op::kLongBinPut:
        Memoize(Operand(4));
        break;
      case op::kBinGet:
        Recall(Operand(1));
        break;
      case op::kLongBinGet:
        Recall(Operand(4));
        break;
      case op::kEmptyTuple:
        Push(Make(Kind::kTuple));
        break;
      case op::kEmptyDict:
        Push(Make(Kind::kDict));
        break;
      case op::kMark:
        if (marks_.size() >= kMaxMarks)
          Fail("data.pkl: MARKs nested too deep");
        marks_.push_back(stack_.size());
        break;
      case op::kBinUnicode:
        PushString();
        break;
      case op::kTuple:
        PushTuple();
        break;
      case op::kBinPersId:
        PushStorage();
        break;
      case op::kBinInt1:
        PushInt(static_cast<std::int64_t>(Operand(1)));
        break;
      case op::kBinInt2:
        PushInt(static_cast<std::int64_t>(Operand(2)));
        break;
      case op::kBinInt:
        PushInt(static_cast<std::int32_t>(static_cast<std::uint32_t>(Operand(4))));
        break;
      case op::kNewTrue:
      case op::kNewFalse: {
        Value v = Make(Kind::kBool);
        v.number = opcode == op::kNewTrue;
        Push(std::move(v));
        break;
      }
      case op::kReduce:
        Reduce();
        break;
      case op::kNewObj:
        NewObject();
        break;
      case op::kSetItems:
        SetItems();
        break;
      case op::kBuild:
        Build();
        break;
      case op::kStop:
        return false;
      default: {
        static const char kHex[] = "0123456789abcdef";
        Fail(std::string("data.pkl: opcode 0x") + kHex[opcode >> 4] + kHex[opcode & 15] +
             " at byte " + std::to_string(op_at) + " is not one torch::save writes for a module");
      }
    }
    return true;
  }

  std::string_view Bytes(std::uint64_t count) {
    if (count > in_.size() - at_)
      Fail("data.pkl ends inside an opcode");
    const std::string_view bytes = in_.substr(at_, count);
    at_ += count;
    return bytes;
  }

  // A little-endian unsigned operand of `width` bytes.
  std::uint64_t Operand(int width) {
    const std::string_view bytes = Bytes(static_cast<std::uint64_t>(width));
    std::uint64_t value = 0;
    for (int i = width - 1; i >= 0; --i)
      value = (value << 8) | static_cast<unsigned char>(bytes[static_cast<std::size_t>(i)]);
    return value;
  }

  std::string_view Line() {
    const std::size_t end = in_.find('\n', at_);
    if (end == std::string_view::npos || end - at_ > kMaxGlobalLineBytes)
      Fail("data.pkl: a GLOBAL without its line");
    const std::string_view line = in_.substr(at_, end - at_);
    at_ = end + 1;
    return line;
  }

  void Push(Value value) {
    if (values_.size() >= kMaxValues)
      Fail("data.pkl makes too many values");
    values_.push_back(std::move(value));
    PushIndex(values_.size() - 1);
  }

  void PushIndex(std::size_t index) {
    if (stack_.size() >= kMaxStackItems)
      Fail("data.pkl: stack too deep");
    stack_.push_back(index);
  }

  // Nothing below the innermost MARK may be taken: that keeps the marks within the stack.
  std::size_t Top() const {
    if (stack_.size() == (marks_.empty() ? 0 : marks_.back()))
      Fail("data.pkl: stack underflow");
    return stack_.back();
  }

  std::size_t Pop() {
    const std::size_t top = Top();
    stack_.pop_back();
    return top;
  }

  std::vector<std::size_t> PopToMark() {
    if (marks_.empty())
      Fail("data.pkl: TUPLE or SETITEMS without MARK");
    const auto mark = static_cast<std::ptrdiff_t>(marks_.back());
    marks_.pop_back();
    std::vector<std::size_t> items(stack_.begin() + mark, stack_.end());
    stack_.erase(stack_.begin() + mark, stack_.end());
    return items;
  }

  const Value& Expect(std::size_t index, Kind kind, const std::string& what) const {
    if (values_[index].kind != kind)
      Fail("data.pkl: " + what + " is " + KindName(values_[index].kind) + ", not " +
           KindName(kind));
    return values_[index];
  }

  void PushGlobal() {
    const std::string_view module = Line();
    const std::string_view name = Line();
    Value v = Make(Kind::kGlobal);
    if (module == "torch._utils" && name == "_rebuild_tensor_v2")
      v.global = Global::kRebuildTensor;
    else if (module == "torch" && name == "FloatStorage")
      v.global = Global::kFloatStorage;
    else if (module == "collections" && name == "OrderedDict")
      v.global = Global::kOrderedDict;
    else if (IsModuleClass(module, name))
      v.global = Global::kModuleClass;
    else
      Fail("data.pkl: disallowed GLOBAL " + Printable(module) + " " + Printable(name));
    v.text = std::string(module) + "." + std::string(name);
    Push(std::move(v));
  }

  void Memoize(std::uint64_t slot) {
    const std::size_t top = Top();
    if (memo_.size() >= kMaxMemoEntries && memo_.count(slot) == 0)
      Fail("data.pkl: too many memo entries");
    memo_[slot] = top;
  }

  void Recall(std::uint64_t slot) {
    const auto found = memo_.find(slot);
    if (found == memo_.end())
      Fail("data.pkl: BINGET of an empty memo slot");
    PushIndex(found->second);
  }

  void PushString() {
    Value v = Make(Kind::kString);
    v.text = std::string(Bytes(Operand(4)));
    Push(std::move(v));
  }

  void PushInt(std::int64_t number) {
    Value v = Make(Kind::kInt);
    v.number = number;
    Push(std::move(v));
  }

  void PushTuple() {
    Value v = Make(Kind::kTuple);
    v.items = PopToMark();
    Push(std::move(v));
  }

  // The persistent id ("storage", FloatStorage, key, "cpu", floats) of a storage in data/<key>.
  void PushStorage() {
    const Value& id = Expect(Pop(), Kind::kTuple, "a persistent id");
    if (id.items.size() != 5 ||
        Expect(id.items[0], Kind::kString, "a persistent id's tag").text != "storage")
      Fail("data.pkl: a persistent id other than a storage's");
    if (Expect(id.items[1], Kind::kGlobal, "a storage's type").global != Global::kFloatStorage)
      Fail("data.pkl: a storage other than a FloatStorage");
    Value v = Make(Kind::kStorage);
    v.text = Expect(id.items[2], Kind::kString, "a storage's key").text;
    if (!IsWord(v.text))
      Fail("data.pkl: a storage key that is not a plain word");
    if (Expect(id.items[3], Kind::kString, "a storage's device").text != "cpu")
      Fail("data.pkl: storage " + v.text + " is not on the cpu");
    v.number = Expect(id.items[4], Kind::kInt, "a storage's size").number;
    if (v.number < 0 || v.number > kMaxStorageFloats)
      Fail("data.pkl: storage " + v.text + " has an impossible size");
    const auto known = storage_floats_.emplace(v.text, v.number).first;
    if (known->second != v.number)
      Fail("data.pkl: storage " + v.text + " with two sizes");
    Push(std::move(v));
  }

  void Reduce() {
    const std::size_t args = Pop();
    const Value& callable = Expect(Pop(), Kind::kGlobal, "REDUCE's callable");
    const Value& arguments = Expect(args, Kind::kTuple, "REDUCE's arguments");
    if (callable.global == Global::kRebuildTensor) {
      Push(RebuildTensor(arguments));
    } else if (callable.global == Global::kOrderedDict && arguments.items.empty()) {
      Push(Make(Kind::kDict));
    } else {
      Fail("data.pkl: REDUCE of " + Printable(callable.text));
    }
  }

  void NewObject() {
    const std::size_t args = Pop();
    const Value& type = Expect(Pop(), Kind::kGlobal, "NEWOBJ's class");
    if (type.global != Global::kModuleClass ||
        !Expect(args, Kind::kTuple, "NEWOBJ's arguments").items.empty())
      Fail("data.pkl: NEWOBJ of " + Printable(type.text));
    Value v = Make(Kind::kObject);
    v.text = type.text;
    Push(std::move(v));
  }

  void SetItems() {
    const std::vector<std::size_t> items = PopToMark();
    const std::size_t dict = Top();
    Expect(dict, Kind::kDict, "SETITEMS's target");
    if (items.size() % 2 != 0)
      Fail("data.pkl: SETITEMS with a key without a value");
    for (std::size_t i = 0; i < items.size(); i += 2)
      Expect(items[i], Kind::kString, "a dict key");
    values_[dict].items.insert(values_[dict].items.end(), items.begin(), items.end());
  }

  void Build() {
    const std::size_t state = Pop();
    const std::size_t object = Top();
    Expect(state, Kind::kDict, "a module's state");
    if (!Expect(object, Kind::kObject, "BUILD's target").items.empty())
      Fail("data.pkl: a module built twice");
    values_[object].items.push_back(state);
  }

  std::vector<std::int64_t> Ints(std::size_t tuple, const std::string& what) const {
    const Value& t = Expect(tuple, Kind::kTuple, what);
    if (t.items.size() > kMaxDims)
      Fail("data.pkl: a tensor of more than " + std::to_string(kMaxDims) + " dimensions");
    std::vector<std::int64_t> ints;
    for (std::size_t item : t.items)
      ints.push_back(Expect(item, Kind::kInt, what).number);
    return ints;
  }

  // _rebuild_tensor_v2(storage, storage offset, sizes, strides, requires_grad, OrderedDict()):
  // a contiguous tensor within its storage.
  Value RebuildTensor(const Value& arguments) const {
    const std::vector<std::size_t>& a = arguments.items;
    if (a.size() != 6)
      Fail("data.pkl: _rebuild_tensor_v2 with other than 6 arguments");
    const Value& storage = Expect(a[0], Kind::kStorage, "a tensor's storage");
    const std::int64_t offset = Expect(a[1], Kind::kInt, "a tensor's storage offset").number;
    const std::vector<std::int64_t> sizes = Ints(a[2], "a tensor's sizes");
    const std::vector<std::int64_t> strides = Ints(a[3], "a tensor's strides");
    Expect(a[4], Kind::kBool, "a tensor's requires_grad");
    if (!Expect(a[5], Kind::kDict, "a tensor's backward hooks").items.empty())
      Fail("data.pkl: a tensor with backward hooks");
    const std::int64_t count = ElementCount(sizes);
    CheckContiguous(sizes, strides, count);
    if (offset < 0 || offset > storage.number || count > storage.number - offset)
      Fail("data.pkl: a tensor outside its storage " + storage.text);
    Value v = Make(Kind::kTensor);
    v.text = storage.text;
    v.number = offset;
    v.sizes = sizes;
    return v;
  }

  static std::int64_t ElementCount(const std::vector<std::int64_t>& sizes) {
    std::int64_t count = 1;
    for (std::int64_t size : sizes) {
      if (size < 0)
        Fail("data.pkl: a tensor of negative size");
      if (size != 0 && count > kMaxStorageFloats / size)
        Fail("data.pkl: a tensor of too many elements");
      count *= size;
    }
    return count;
  }

  // Row-major: each dimension's stride is the product of the sizes after it. As in libtorch, the
  // stride of a dimension of size 1 does not matter, nor do any for a tensor of no elements.
  static void CheckContiguous(const std::vector<std::int64_t>& sizes,
                              const std::vector<std::int64_t>& strides, std::int64_t count) {
    if (strides.size() != sizes.size())
      Fail("data.pkl: a tensor with as many strides as sizes");
    if (count == 0)
      return;
    std::int64_t expected = 1;
    for (std::size_t d = sizes.size(); d-- > 0;) {
      if (sizes[d] != 1 && strides[d] != expected)
        Fail("data.pkl: a tensor that is not contiguous");
      expected *= sizes[d];
    }
  }

  std::string_view in_;
  std::size_t at_ = 0;
  std::vector<Value> values_;
  std::vector<std::size_t> stack_;
  std::vector<std::size_t> marks_;  // stack sizes at each open MARK
  std::unordered_map<std::uint64_t, std::size_t> memo_;
  std::map<std::string, std::int64_t> storage_floats_;
};

// The tensors in the tree of module objects data.pkl leaves, depth first in the order of their
// state dicts, named as named_parameters() names them, with their floats from data/<key>.
class TensorCollector {
 public:
  TensorCollector(const Unpickler& pickle, const StoredZip& zip)
      : pickle_(pickle), zip_(zip), visited_(pickle.ValueCount(), false) {}

  std::vector<SavedTensor> Collect(std::size_t root) {
    CollectModule(root, "", 0);
    return std::move(tensors_);
  }

 private:
  // Each value once: a pickle that shares one module or tensor between several places (or makes
  // a module its own child) could otherwise fan a small file out into a huge or endless walk.
  void Visit(std::size_t index, const std::string& name) {
    if (visited_[index])
      Fail("data.pkl: " + Shown(name) + " appears twice in the module tree");
    visited_[index] = true;
  }

  static std::string Shown(const std::string& name) { return name.empty() ? "the root" : name; }

  static std::string Join(const std::string& module, const std::string& key) {
    return module.empty() ? key : module + "." + key;
  }

  // `name`: "" for the root, "phi" for its child phi, and so on.
  void CollectModule(std::size_t object, const std::string& name, int depth) {
    const Value& module = pickle_.At(object);
    if (module.kind != Kind::kObject || module.items.empty())
      Fail("data.pkl: " + Shown(name) + " is not a built module");
    if (depth > kMaxModuleDepth)
      Fail("data.pkl: modules nested too deep");
    Visit(object, name);
    const Value& state = pickle_.At(module.items[0]);
    Visit(module.items[0], name);
    std::set<std::string> seen;
    for (std::size_t i = 0; i < state.items.size(); i += 2) {
      const std::string& key = pickle_.At(state.items[i]).text;
      if (!IsWord(key) || !seen.insert(key).second)
        Fail("data.pkl: attribute " + Printable(key) + " of " + Shown(name) +
             " misnamed or repeated");
      const std::size_t child = state.items[i + 1];
      const Kind kind = pickle_.At(child).kind;
      if (kind == Kind::kObject) {
        CollectModule(child, Join(name, key), depth + 1);
      } else if (kind == Kind::kTensor) {
        Visit(child, Join(name, key));
        tensors_.push_back(ReadTensor(pickle_.At(child), Join(name, key)));
      } else {
        Fail("data.pkl: " + Join(name, key) + " is " + KindName(kind) +
             ", neither a module nor a tensor");
      }
    }
  }

  SavedTensor ReadTensor(const Value& tensor, const std::string& name) {
    SavedTensor t;
    t.name = name;
    t.sizes = tensor.sizes;
    std::int64_t count = 1;
    for (std::int64_t size : t.sizes)
      count *= size;  // checked when the pickle ran
    // Libtorch writes a storage once however many tensors share it, so a genuine file's tensors
    // hold about as many floats as the file has room for; more is a file that fans out.
    floats_ += static_cast<std::uint64_t>(count);
    if (floats_ > zip_.FileBytes() / sizeof(float))
      Fail("data.pkl: tensors of more floats than the file holds");
    const std::string_view bytes = Storage(tensor.text);
    const std::size_t from = static_cast<std::size_t>(tensor.number) * sizeof(float);
    t.values.resize(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < t.values.size(); ++i)
      t.values[i] = LittleEndianFloat(bytes.data() + from + i * sizeof(float));
    return t;
  }

  // data/<key>, which must hold exactly the floats its persistent ids say: each tensor's offset
  // and element count were checked against that number as the pickle ran.
  std::string_view Storage(const std::string& key) {
    const auto known = storages_.find(key);
    if (known != storages_.end())
      return known->second;
    const std::string_view bytes = zip_.Read(zip_.Folder() + "/data/" + key);
    if (bytes.size() != static_cast<std::uint64_t>(pickle_.StorageFloats(key)) * sizeof(float))
      Fail("data/" + key + " is not the size its storage says");
    return storages_.emplace(key, bytes).first->second;
  }

  static float LittleEndianFloat(const char* p) {
    std::uint32_t bits = 0;
    for (int i = 3; i >= 0; --i)
      bits = (bits << 8) | static_cast<unsigned char>(p[i]);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  const Unpickler& pickle_;
  const StoredZip& zip_;
  std::vector<bool> visited_;
  std::vector<SavedTensor> tensors_;
  std::map<std::string, std::string_view> storages_;  // checked
  std::uint64_t floats_ = 0;
};

// Libtorch writes "byteorder" only in newer versions; the floats are little-endian without it.
void CheckByteOrder(const StoredZip& zip) {
  const std::string name = zip.Folder() + "/byteorder";
  if (zip.Has(name) && zip.Read(name) != "little")
    Fail("byteorder other than little-endian");
}

}  // namespace

namespace {

std::vector<SavedTensor> TensorsOf(const StoredZip& zip, const std::string& file) {
  try {
    CheckByteOrder(zip);
    const std::string_view pickle = zip.Read(zip.Folder() + "/data.pkl");
    if (pickle.size() > kMaxPickleBytes)
      Fail("data.pkl larger than " + std::to_string(kMaxPickleBytes >> 10) + " KiB");
    Unpickler unpickler(pickle);
    const std::size_t root = unpickler.Run();
    return TensorCollector(unpickler, zip).Collect(root);
  } catch (const BadFile& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
}

}  // namespace

std::vector<SavedTensor> ReadSavedTensors(const std::string& file) {
  return TensorsOf(StoredZip(file), file);
}

std::vector<SavedTensor> ReadSavedTensorsFromBytes(std::string bytes, const std::string& name) {
  return TensorsOf(StoredZip::FromBytes(std::move(bytes), name), name);
}

}  // namespace rlpos
