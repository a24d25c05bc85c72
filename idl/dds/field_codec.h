#pragma once
// The two directions of a message's field list (dds/message_fields.h). Encoder fills Cyclone's C
// type from the C++ struct (for Writer); Decoder fills the C++ struct from a received C sample
// (for Reader::Take). Both have the same methods, one per kind of field, each taking the C++
// field first and the C field second, so that one list of calls describes a message both ways.
// Every bound and enum value is checked here; a failed check throws MessageError naming the
// field.
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "common/wire/limits.h"
#include "common/wire/policy_bundle.h"
#include "idl/dds/message_error.h"

namespace rlpos::codec {

// Throws unless `count` (bytes or elements) is within `bound`.
inline void CheckBound(std::size_t count, std::size_t bound, const char* field, const char* unit) {
  if (count > bound) {
    throw MessageError(field, std::to_string(count) + " " + unit + " exceed the bound of " +
                                  std::to_string(bound));
  }
}

// A received sequence: within its bound, and with a buffer when it is not empty.
template <typename Seq>
void CheckReceived(const Seq& c, std::size_t bound, const char* field, const char* unit) {
  CheckBound(c._length, bound, field, unit);
  if (c._length > 0 && c._buffer == nullptr)
    throw MessageError(field, std::to_string(c._length) + " " + unit + " without a buffer");
}

// The value of a received enum field, read as bytes: loading a C enum that holds a value outside
// its enumerators is undefined behaviour in C++, and the wire may hold any value.
template <typename C>
int CheckedEnum(const C& c, int last, const char* field) {
  static_assert(sizeof(C) == sizeof(std::int32_t), "Cyclone's C enums are 32-bit");
  std::int32_t value;
  std::memcpy(&value, &c, sizeof value);
  if (value < 0 || value > last)
    throw MessageError(field, std::to_string(value) + " is not a known value");
  return value;
}

// The buffers that the sequences of one encoded sample point into; they live as long as it.
class SequenceBuffers {
 public:
  // `n` zeroed elements, or nullptr when n is 0 (an empty sequence has no buffer).
  template <typename T>
  T* New(std::size_t n) {
    if (n == 0)
      return nullptr;
    std::unique_ptr<T[]> block(new T[n]());
    blocks_.emplace_back(block.get(), [](void* p) { delete[] static_cast<T*>(p); });
    return block.release();
  }

 private:
  std::vector<std::unique_ptr<void, void (*)(void*)>> blocks_;
};

class Encoder {
 public:
  explicit Encoder(SequenceBuffers& buffers) : buffers_(buffers) {}

  bool KeysOnly() const { return false; }  // every field is written, keys and the rest

  template <typename T, typename C>
  void Value(const T& m, C& c) {
    c = static_cast<C>(m);
  }

  // A bounded string: an inline array of its bound and a NUL.
  template <std::size_t N>
  void Text(const std::string& m, char (&c)[N], const char* field) {
    CheckBound(m.size(), N - 1, field, "bytes");
    if (m.find('\0') != std::string::npos)
      throw MessageError(field, "a NUL byte inside the text");
    std::memcpy(c, m.data(), m.size());
    c[m.size()] = '\0';
  }

  // A text better cut to its bound than not sent (a reply's message).
  template <std::size_t N>
  void CutText(const std::string& m, char (&c)[N], const char* field) {
    Text(m.substr(0, N - 1), c, field);
  }

  // `last`: the IDL enum's last value (the decoder checks it).
  template <typename E, typename C>
  void Enum(E m, C& c, int /*last*/, const char* /*field*/) {
    c = static_cast<C>(m);
  }

  // A text the wire carries as an enum: names[i] is value i's; a text not among them goes as 0.
  // `when`: whether the decoder keeps the value.
  template <std::size_t K, typename C>
  void NamedEnum(const std::string& m, C& c, const std::array<const char*, K>& names,
                 const char* /*field*/, bool /*when*/ = true) {
    int value = 0;
    for (std::size_t i = 0; i < K; ++i) {
      if (m == names[i])
        value = static_cast<int>(i);
    }
    c = static_cast<C>(value);
  }

  // An octet sequence borrows the text: dds_write serializes before it returns.
  template <typename Seq>
  void Octets(const std::string& m, Seq& c, std::size_t bound, const char* field) {
    CheckBound(m.size(), bound, field, "bytes");
    c._maximum = c._length = static_cast<std::uint32_t>(m.size());
    c._buffer = reinterpret_cast<std::uint8_t*>(const_cast<char*>(m.data()));
    c._release = false;
  }

  // A sequence of structs (or of bounded strings); `fields(element, c_element)` maps one.
  template <typename T, typename Seq, typename Fields>
  void Sequence(const std::vector<T>& m, Seq& c, std::size_t bound, const char* field,
                Fields fields) {
    CheckBound(m.size(), bound, field, "elements");
    using Element = std::remove_pointer_t<decltype(c._buffer)>;
    Element* buffer = buffers_.New<Element>(m.size());
    for (std::size_t i = 0; i < m.size(); ++i)
      fields(m[i], buffer[i]);
    c._maximum = c._length = static_cast<std::uint32_t>(m.size());
    c._buffer = buffer;
    c._release = false;
  }

  // Absent travels as an empty sequence.
  template <typename T, typename Seq, typename Fields>
  void OptionalSequence(const std::optional<std::vector<T>>& m, Seq& c, std::size_t bound,
                        const char* field, Fields fields) {
    const std::vector<T> none;
    Sequence(m ? *m : none, c, bound, field, fields);
  }

  // An optional with its presence flag beside it on the wire.
  template <typename T, typename C>
  void Optional(const std::optional<T>& m, bool& has, C& c) {
    has = m.has_value();
    c = static_cast<C>(m.value_or(T{}));
  }

  // An optional that travels as 0 when absent.
  template <typename T, typename C>
  void OptionalOrZero(const std::optional<T>& m, C& c) {
    c = static_cast<C>(m.value_or(T{}));
  }

  // An optional that travels as 0 when absent; decoded only `when`.
  template <typename T, typename C>
  void OptionalWhen(const std::optional<T>& m, C& c, bool /*when*/) {
    OptionalOrZero(m, c);
  }

  // A policy bundle travels as its files (its sha256 beside it, `claimed`); none: no files.
  template <typename Seq, typename Fields>
  void Policy(const std::optional<PolicyBundle>& m, Seq& c, const std::string& /*claimed*/,
              Fields fields) {
    const std::vector<PolicyFile> none;
    Sequence(m ? m->files : none, c, wire::kMaxPolicyFiles, "policy files", fields);
  }

 private:
  SequenceBuffers& buffers_;
};

class Decoder {
 public:
  // `keys_only`: a sample without data (disposed, or no writers) holds only its key fields.
  explicit Decoder(bool keys_only) : keys_only_(keys_only) {}

  bool KeysOnly() const { return keys_only_; }

  template <typename T, typename C>
  void Value(T& m, const C& c) {
    m = static_cast<T>(c);
  }

  // Cyclone's decoder NUL-terminates a received array; strnlen keeps to the array anyway.
  template <std::size_t N>
  void Text(std::string& m, const char (&c)[N], const char* /*field*/) {
    m.assign(c, strnlen(c, N));
  }

  template <std::size_t N>
  void CutText(std::string& m, const char (&c)[N], const char* field) {
    Text(m, c, field);
  }

  template <typename E, typename C>
  void Enum(E& m, const C& c, int last, const char* field) {
    m = static_cast<E>(CheckedEnum(c, last, field));
  }

  template <std::size_t K, typename C>
  void NamedEnum(std::string& m, const C& c, const std::array<const char*, K>& names,
                 const char* field, bool when = true) {
    const int value = CheckedEnum(c, static_cast<int>(K) - 1, field);
    if (when)
      m = names[static_cast<std::size_t>(value)];
  }

  template <typename Seq>
  void Octets(std::string& m, const Seq& c, std::size_t bound, const char* field) {
    CheckReceived(c, bound, field, "bytes");
    if (c._length > 0)
      m.assign(reinterpret_cast<const char*>(c._buffer), c._length);
  }

  template <typename T, typename Seq, typename Fields>
  void Sequence(std::vector<T>& m, const Seq& c, std::size_t bound, const char* field,
                Fields fields) {
    CheckReceived(c, bound, field, "elements");
    m.assign(c._length, T{});
    for (std::uint32_t i = 0; i < c._length; ++i)
      fields(m[i], c._buffer[i]);
  }

  // An empty sequence is absent.
  template <typename T, typename Seq, typename Fields>
  void OptionalSequence(std::optional<std::vector<T>>& m, const Seq& c, std::size_t bound,
                        const char* field, Fields fields) {
    std::vector<T> elements;
    Sequence(elements, c, bound, field, fields);
    if (!elements.empty())
      m = std::move(elements);
  }

  template <typename T, typename C>
  void Optional(std::optional<T>& m, const bool& has, const C& c) {
    if (has)
      m = static_cast<T>(c);
  }

  template <typename T, typename C>
  void OptionalOrZero(std::optional<T>& m, const C& c) {
    if (c != 0)
      m = static_cast<T>(c);
  }

  template <typename T, typename C>
  void OptionalWhen(std::optional<T>& m, const C& c, bool when) {
    if (when)
      m = static_cast<T>(c);
  }

  // Decoded as received, with the sha256 its order claims (decoded before it): CheckJobOrder
  // holds it to that.
  template <typename Seq, typename Fields>
  void Policy(std::optional<PolicyBundle>& m, const Seq& c, const std::string& claimed,
              Fields fields) {
    std::vector<PolicyFile> files;
    Sequence(files, c, wire::kMaxPolicyFiles, "policy files", fields);
    if (!files.empty())
      m = ReceivedPolicyBundle(std::move(files), claimed);
  }

 private:
  bool keys_only_;
};

}  // namespace rlpos::codec
