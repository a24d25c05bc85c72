#include "common/config/object_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/config/config_error.h"
#include "common/config/did_you_mean.h"

namespace rlpos {

std::string JoinPath(const std::string& parent, const std::string& key) {
  return parent + "/" + key;
}
std::string JoinPath(const std::string& parent, std::size_t index) {
  return parent + "/" + std::to_string(index);
}

std::string TypeName(const nlohmann::json& v) {
  if (v.is_number())
    return "a number";
  if (v.is_string())
    return "a string";
  if (v.is_boolean())
    return "a boolean";
  if (v.is_array())
    return "an array";
  if (v.is_object())
    return "an object";
  return "null";
}

namespace {
std::string FormatNumber(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}
}  // namespace

double CheckedNumber(const nlohmann::json& v, const std::string& path, NumberRange range) {
  if (!v.is_number())
    throw ConfigError(path, "expected a number, got " + TypeName(v));
  const double x = v.get<double>();
  if (!std::isfinite(x))
    throw ConfigError(path, "must be a finite number");
  if (x < range.min || (range.min_exclusive && x == range.min)) {
    if (range.min == 0.0) {
      throw ConfigError(path, range.min_exclusive ? "must be positive, got " + FormatNumber(x)
                                                  : "must not be negative, got " + FormatNumber(x));
    }
    throw ConfigError(path, "must be " + std::string(range.min_exclusive ? "> " : ">= ") +
                                FormatNumber(range.min) + ", got " + FormatNumber(x));
  }
  if (x > range.max) {
    throw ConfigError(path, "must be <= " + FormatNumber(range.max) + ", got " + FormatNumber(x));
  }
  return x;
}

ObjectReader::ObjectReader(const nlohmann::json& value, std::string path)
    : value_(value), path_(std::move(path)) {
  if (!value_.is_object())
    throw ConfigError(path_, "expected an object, got " + TypeName(value_));
}

bool ObjectReader::Has(const std::string& key) const {
  return value_.contains(key);
}

const nlohmann::json& ObjectReader::Get(const std::string& key) {
  known_.push_back(key);
  read_.push_back(key);
  return value_.at(key);
}

double ObjectReader::Number(const std::string& key, double fallback, NumberRange range) {
  known_.push_back(key);
  if (!Has(key))
    return fallback;
  return CheckedNumber(Get(key), PathOf(key), range);
}

double ObjectReader::RequiredNumber(const std::string& key, NumberRange range) {
  if (!Has(key))
    throw ConfigError(PathOf(key), "is required");
  return CheckedNumber(Get(key), PathOf(key), range);
}

long long ObjectReader::Integer(const std::string& key, long long fallback, long long min,
                                long long max) {
  known_.push_back(key);
  if (!Has(key))
    return fallback;
  const auto& v = Get(key);
  if (!v.is_number_integer()) {
    throw ConfigError(PathOf(key),
                      "expected an integer, got " +
                          (v.is_number() ? std::string("a fractional number") : TypeName(v)));
  }
  const long long x = v.get<long long>();
  if (x < min || x > max) {
    throw ConfigError(PathOf(key), "must be in [" + std::to_string(min) + ", " +
                                       std::to_string(max) + "], got " + std::to_string(x));
  }
  return x;
}

bool ObjectReader::Bool(const std::string& key, bool fallback) {
  known_.push_back(key);
  if (!Has(key))
    return fallback;
  const auto& v = Get(key);
  if (!v.is_boolean())
    throw ConfigError(PathOf(key), "expected a boolean, got " + TypeName(v));
  return v.get<bool>();
}

std::string ObjectReader::String(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) {
  known_.push_back(key);
  if (!Has(key))
    return fallback;
  const auto& v = Get(key);
  if (!v.is_string())
    throw ConfigError(PathOf(key), "expected a string, got " + TypeName(v));
  std::string s = v.get<std::string>();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed)
      list += (list.empty() ? "" : ", ") + a;
    std::string message = "unknown value \"" + s + "\" (one of: " + list + ")";
    const std::string hint = ClosestMatch(s, allowed);
    if (!hint.empty())
      message += "; did you mean \"" + hint + "\"?";
    throw ConfigError(PathOf(key), message);
  }
  return s;
}

const nlohmann::json* ObjectReader::Child(const std::string& key) {
  known_.push_back(key);
  if (!Has(key))
    return nullptr;
  return &Get(key);
}

void ObjectReader::Finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) != read_.end())
      continue;
    std::string message = "unknown key \"" + it.key() + "\"";
    const std::string hint = ClosestMatch(it.key(), known_);
    if (!hint.empty())
      message += "; did you mean \"" + hint + "\"?";
    throw ConfigError(PathOf(it.key()), message);
  }
}

std::vector<std::string> ReadStringList(const nlohmann::json& v, const std::string& path,
                                        const std::vector<std::string>& allowed) {
  if (!v.is_array() || v.empty())
    throw ConfigError(path, "expected a non-empty array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    // Reuse the enum check of ObjectReader through a one-key object.
    const nlohmann::json wrapper = {
        {"value", v[i]}};  // outlives the reader, which keeps a reference
    ObjectReader item(wrapper, path);
    try {
      out.push_back(item.String("value", "", allowed));
    } catch (const ConfigError& e) {
      throw ConfigError(JoinPath(path, i), e.problem());
    }
  }
  return out;
}

}  // namespace rlpos
