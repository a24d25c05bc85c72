// ReadSavedTensors: the archive's data.pkl run by the unpickler (torch_pickle.h), and the tree of
// modules it leaves walked to its float tensors.
#include "worker/learning/agent_base/saved_tensors.h"

#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "worker/learning/agent_base/stored_zip.h"
#include "worker/learning/agent_base/torch_pickle.h"

namespace rlpos {
namespace {

using torch_pickle::BadFile;
using torch_pickle::Fail;
using torch_pickle::IsWord;
using torch_pickle::Kind;
using torch_pickle::KindName;
using torch_pickle::kMaxModuleDepth;
using torch_pickle::kMaxPickleBytes;
using torch_pickle::Printable;
using torch_pickle::Unpickler;
using torch_pickle::Value;

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
