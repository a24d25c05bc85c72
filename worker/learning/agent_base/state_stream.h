#pragma once
// A training's exact state as bytes (a checkpoint to resume from): numbers written as their bits,
// so that a resumed training computes what the uninterrupted one would have. Native byte order:
// a checkpoint is read back by the same build on the same kind of machine.
#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rlpos::state {

template <typename T>
void Write(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
T Read(std::istream& in) {
  T value{};
  if (!in.read(reinterpret_cast<char*>(&value), sizeof value))
    throw std::runtime_error("truncated");
  return value;
}

template <typename T>
void WriteVector(std::ostream& out, const std::vector<T>& values) {
  Write<std::uint64_t>(out, values.size());
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(T)));
}

// Reads a vector that must have `expected` elements (the size the reader's own state has), or
// none where `may_be_empty`.
template <typename T>
void ReadVector(std::istream& in, std::vector<T>& values, std::size_t expected, const char* what,
                bool may_be_empty = false) {
  const auto size = Read<std::uint64_t>(in);
  if (may_be_empty && size == 0) {
    values.clear();
    return;
  }
  if (size != expected) {
    throw std::runtime_error(std::string(what) + ": " + std::to_string(size) +
                             " values, expected " + std::to_string(expected));
  }
  values.resize(expected);
  if (!in.read(reinterpret_cast<char*>(values.data()),
               static_cast<std::streamsize>(expected * sizeof(T))))
    throw std::runtime_error("truncated");
}

}  // namespace rlpos::state
