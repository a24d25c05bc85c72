#include "common/scenario_import/rlpos3_object.h"

#include <algorithm>
#include <cmath>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"

namespace rlpos {

double Rlpos3Number(const nlohmann::json& v, const std::string& path) {
  if (!v.is_number())
    throw ConfigError(path, "expected a number, got " + TypeName(v));
  const double x = v.get<double>();
  if (!std::isfinite(x))
    throw ConfigError(path, "must be a finite number");
  return x;
}

long long Rlpos3Integer(const nlohmann::json& v, const std::string& path, long long min,
                        long long max) {
  const double x = Rlpos3Number(v, path);
  if (x != std::floor(x))
    throw ConfigError(path, "expected an integer, got " + v.dump());
  if (x < static_cast<double>(min) || x > static_cast<double>(max)) {
    throw ConfigError(path, "must be in [" + std::to_string(min) + ", " + std::to_string(max) +
                                "], got " + v.dump());
  }
  return static_cast<long long>(x);
}

Rlpos3Object::Rlpos3Object(const nlohmann::json& value, std::string path,
                           std::vector<ImportWarning>& warnings)
    : value_(value), path_(std::move(path)), warnings_(warnings) {
  if (!value_.is_object())
    throw ConfigError(path_.empty() ? "/" : path_, "expected an object, got " + TypeName(value_));
}

std::string Rlpos3Object::PathOf(const std::string& key) const {
  return JoinPath(path_, key);
}

const nlohmann::json* Rlpos3Object::Optional(const std::string& key) {
  read_.push_back(key);
  const auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

const nlohmann::json& Rlpos3Object::Required(const std::string& key, const std::string& what) {
  const nlohmann::json* v = Optional(key);
  if (!v)
    throw ConfigError(PathOf(key), "is required (" + what + ")");
  return *v;
}

Rlpos3Object Rlpos3Object::Object(const std::string& key, const std::string& what) {
  return Rlpos3Object(Required(key, what), PathOf(key), warnings_);
}

Rlpos3Object Rlpos3Object::OptionalObject(const std::string& key) {
  static const nlohmann::json empty = nlohmann::json::object();
  const nlohmann::json* v = Optional(key);
  return Rlpos3Object(v ? *v : empty, PathOf(key), warnings_);
}

double Rlpos3Object::Number(const std::string& key, double fallback) {
  const nlohmann::json* v = Optional(key);
  return v ? Rlpos3Number(*v, PathOf(key)) : fallback;
}

double Rlpos3Object::RequiredNumber(const std::string& key) {
  return Rlpos3Number(Required(key, "a number"), PathOf(key));
}

long long Rlpos3Object::Integer(const std::string& key, long long fallback, long long min,
                                long long max) {
  const nlohmann::json* v = Optional(key);
  return v ? Rlpos3Integer(*v, PathOf(key), min, max) : fallback;
}

std::string Rlpos3Object::String(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = Optional(key);
  if (!v)
    return fallback;
  if (!v->is_string())
    throw ConfigError(PathOf(key), "expected a string, got " + TypeName(*v));
  return v->get<std::string>();
}

void Rlpos3Object::NotCarried(const std::string& key, const std::string& why) {
  if (Optional(key))
    Warn(key, "not carried: " + why);
}

void Rlpos3Object::Warn(const std::string& key, const std::string& message) {
  warnings_.push_back({PathOf(key), message});
}

void Rlpos3Object::Finish() {
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) == read_.end())
      Warn(it.key(), "not carried: not a field of RLpos-3's format this import knows");
  }
}

}  // namespace rlpos
