// The unpickler of data.pkl (torch_pickle.h): each opcode torch::save writes for a module of
// float tensors, checked as it runs; anything else fails with a one-line message.
#include "worker/learning/agent_base/torch_pickle.h"

#include <utility>

namespace rlpos::torch_pickle {
namespace {

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

bool IsWordChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
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

Value Make(Kind kind) {
  Value v;
  v.kind = kind;
  return v;
}

}  // namespace

[[noreturn]] void Fail(const std::string& what) {
  throw BadFile(what);
}

std::string Printable(std::string_view text) {
  constexpr std::size_t kMaxShown = 64;
  std::string shown;
  for (char c : text.substr(0, kMaxShown))
    shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  return text.size() > kMaxShown ? shown + "..." : shown;
}

bool IsWord(std::string_view text) {
  if (text.empty() || text.size() > kMaxKeyBytes)
    return false;
  for (char c : text) {
    if (!IsWordChar(c))
      return false;
  }
  return true;
}

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

std::size_t Unpickler::Run() {
  while (Step()) {
  }
  if (at_ != in_.size())
    Fail("data.pkl: bytes after STOP");
  if (!marks_.empty() || stack_.size() != 1)
    Fail("data.pkl: STOP with other than one value on the stack");
  return stack_[0];
}

// One opcode; false at STOP.
bool Unpickler::Step() {
  const std::size_t op_at = at_;
  const auto opcode = static_cast<unsigned char>(Bytes(1)[0]);
  if ((op_at == 0) != (opcode == op::kProto))
    Fail("data.pkl: PROTO other than first");
  if (opcode == op::kStop)
    return false;
  if (!StepFrame(opcode) && !StepLiteral(opcode) && !StepObject(opcode)) {
    static const char kHex[] = "0123456789abcdef";
    Fail(std::string("data.pkl: opcode 0x") + kHex[opcode >> 4] + kHex[opcode & 15] + " at byte " +
         std::to_string(op_at) + " is not one torch::save writes for a module");
  }
  return true;
}

bool Unpickler::StepFrame(unsigned char opcode) {
  switch (opcode) {
    case op::kProto:
      if (Operand(1) != kPickleProtocol)
        Fail("data.pkl: pickle protocol other than 2");
      return true;
    case op::kBinPut:
      Memoize(Operand(1));
      return true;
    case op::kLongBinPut:
      Memoize(Operand(4));
      return true;
    case op::kBinGet:
      Recall(Operand(1));
      return true;
    case op::kLongBinGet:
      Recall(Operand(4));
      return true;
    case op::kMark:
      if (marks_.size() >= kMaxMarks)
        Fail("data.pkl: MARKs nested too deep");
      marks_.push_back(stack_.size());
      return true;
    default:
      return false;
  }
}

bool Unpickler::StepLiteral(unsigned char opcode) {
  switch (opcode) {
    case op::kGlobal:
      PushGlobal();
      return true;
    case op::kEmptyTuple:
      Push(Make(Kind::kTuple));
      return true;
    case op::kEmptyDict:
      Push(Make(Kind::kDict));
      return true;
    case op::kBinUnicode:
      PushString();
      return true;
    case op::kTuple:
      PushTuple();
      return true;
    case op::kBinPersId:
      PushStorage();
      return true;
    case op::kBinInt1:
      PushInt(static_cast<std::int64_t>(Operand(1)));
      return true;
    case op::kBinInt2:
      PushInt(static_cast<std::int64_t>(Operand(2)));
      return true;
    case op::kBinInt:
      PushInt(static_cast<std::int32_t>(static_cast<std::uint32_t>(Operand(4))));
      return true;
    case op::kNewTrue:
    case op::kNewFalse: {
      Value v = Make(Kind::kBool);
      v.number = opcode == op::kNewTrue;
      Push(std::move(v));
      return true;
    }
    default:
      return false;
  }
}

bool Unpickler::StepObject(unsigned char opcode) {
  switch (opcode) {
    case op::kReduce:
      Reduce();
      return true;
    case op::kNewObj:
      NewObject();
      return true;
    case op::kSetItems:
      SetItems();
      return true;
    case op::kBuild:
      Build();
      return true;
    default:
      return false;
  }
}

std::string_view Unpickler::Bytes(std::uint64_t count) {
  if (count > in_.size() - at_)
    Fail("data.pkl ends inside an opcode");
  const std::string_view bytes = in_.substr(at_, count);
  at_ += count;
  return bytes;
}

// A little-endian unsigned operand of `width` bytes.
std::uint64_t Unpickler::Operand(int width) {
  const std::string_view bytes = Bytes(static_cast<std::uint64_t>(width));
  std::uint64_t value = 0;
  for (int i = width - 1; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(bytes[static_cast<std::size_t>(i)]);
  return value;
}

std::string_view Unpickler::Line() {
  const std::size_t end = in_.find('\n', at_);
  if (end == std::string_view::npos || end - at_ > kMaxGlobalLineBytes)
    Fail("data.pkl: a GLOBAL without its line");
  const std::string_view line = in_.substr(at_, end - at_);
  at_ = end + 1;
  return line;
}

void Unpickler::Push(Value value) {
  if (values_.size() >= kMaxValues)
    Fail("data.pkl makes too many values");
  values_.push_back(std::move(value));
  PushIndex(values_.size() - 1);
}

void Unpickler::PushIndex(std::size_t index) {
  if (stack_.size() >= kMaxStackItems)
    Fail("data.pkl: stack too deep");
  stack_.push_back(index);
}

// Nothing below the innermost MARK may be taken: that keeps the marks within the stack.
std::size_t Unpickler::Top() const {
  if (stack_.size() == (marks_.empty() ? 0 : marks_.back()))
    Fail("data.pkl: stack underflow");
  return stack_.back();
}

std::size_t Unpickler::Pop() {
  const std::size_t top = Top();
  stack_.pop_back();
  return top;
}

std::vector<std::size_t> Unpickler::PopToMark() {
  if (marks_.empty())
    Fail("data.pkl: TUPLE or SETITEMS without MARK");
  const auto mark = static_cast<std::ptrdiff_t>(marks_.back());
  marks_.pop_back();
  std::vector<std::size_t> items(stack_.begin() + mark, stack_.end());
  stack_.erase(stack_.begin() + mark, stack_.end());
  return items;
}

const Value& Unpickler::Expect(std::size_t index, Kind kind, const std::string& what) const {
  if (values_[index].kind != kind)
    Fail("data.pkl: " + what + " is " + KindName(values_[index].kind) + ", not " + KindName(kind));
  return values_[index];
}

void Unpickler::PushGlobal() {
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

void Unpickler::Memoize(std::uint64_t slot) {
  const std::size_t top = Top();
  if (memo_.size() >= kMaxMemoEntries && memo_.count(slot) == 0)
    Fail("data.pkl: too many memo entries");
  memo_[slot] = top;
}

void Unpickler::Recall(std::uint64_t slot) {
  const auto found = memo_.find(slot);
  if (found == memo_.end())
    Fail("data.pkl: BINGET of an empty memo slot");
  PushIndex(found->second);
}

void Unpickler::PushString() {
  Value v = Make(Kind::kString);
  v.text = std::string(Bytes(Operand(4)));
  Push(std::move(v));
}

void Unpickler::PushInt(std::int64_t number) {
  Value v = Make(Kind::kInt);
  v.number = number;
  Push(std::move(v));
}

void Unpickler::PushTuple() {
  Value v = Make(Kind::kTuple);
  v.items = PopToMark();
  Push(std::move(v));
}

// The persistent id ("storage", FloatStorage, key, "cpu", floats) of a storage in data/<key>.
void Unpickler::PushStorage() {
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

void Unpickler::Reduce() {
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

void Unpickler::NewObject() {
  const std::size_t args = Pop();
  const Value& type = Expect(Pop(), Kind::kGlobal, "NEWOBJ's class");
  if (type.global != Global::kModuleClass ||
      !Expect(args, Kind::kTuple, "NEWOBJ's arguments").items.empty())
    Fail("data.pkl: NEWOBJ of " + Printable(type.text));
  Value v = Make(Kind::kObject);
  v.text = type.text;
  Push(std::move(v));
}

void Unpickler::SetItems() {
  const std::vector<std::size_t> items = PopToMark();
  const std::size_t dict = Top();
  Expect(dict, Kind::kDict, "SETITEMS's target");
  if (items.size() % 2 != 0)
    Fail("data.pkl: SETITEMS with a key without a value");
  for (std::size_t i = 0; i < items.size(); i += 2)
    Expect(items[i], Kind::kString, "a dict key");
  values_[dict].items.insert(values_[dict].items.end(), items.begin(), items.end());
}

void Unpickler::Build() {
  const std::size_t state = Pop();
  const std::size_t object = Top();
  Expect(state, Kind::kDict, "a module's state");
  if (!Expect(object, Kind::kObject, "BUILD's target").items.empty())
    Fail("data.pkl: a module built twice");
  values_[object].items.push_back(state);
}

std::vector<std::int64_t> Unpickler::Ints(std::size_t tuple, const std::string& what) const {
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
Value Unpickler::RebuildTensor(const Value& arguments) const {
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

std::int64_t Unpickler::ElementCount(const std::vector<std::int64_t>& sizes) {
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
void Unpickler::CheckContiguous(const std::vector<std::int64_t>& sizes,
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

}  // namespace rlpos::torch_pickle
