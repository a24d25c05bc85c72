#pragma once
// One JSON object of an RLpos-3 config, read key by key. Unlike the scenario's ObjectReader, a
// key nobody read is not an error: Finish() turns it into a warning, because the source format
// has fields that have no equivalent here and fields this import does not know.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/scenario_import/rlpos3_import.h"

namespace rlpos {

class Rlpos3Object {
 public:
  // Throws ConfigError at `path` when `value` is not an object.
  Rlpos3Object(const nlohmann::json& value, std::string path, std::vector<ImportWarning>& warnings);

  const std::string& path() const { return path_; }
  std::string PathOf(const std::string& key) const;
  bool Has(const std::string& key) const { return value_.contains(key); }
  std::vector<ImportWarning>& warnings() const { return warnings_; }

  // The child (marked as read), or nullptr when absent.
  const nlohmann::json* Optional(const std::string& key);
  // The child; absent: ConfigError "is required (`what`)".
  const nlohmann::json& Required(const std::string& key, const std::string& what);
  // A child object, read the same way (required).
  Rlpos3Object Object(const std::string& key, const std::string& what);
  // A child object that may be absent (then read as an empty one).
  Rlpos3Object OptionalObject(const std::string& key);

  // Typed values (a wrong type is a ConfigError at the key's path).
  double Number(const std::string& key, double fallback);
  double RequiredNumber(const std::string& key);
  long long Integer(const std::string& key, long long fallback, long long min, long long max);
  std::string String(const std::string& key, const std::string& fallback);
  // `key` has no equivalent here: when present, a warning "not carried: <why>".
  void NotCarried(const std::string& key, const std::string& why);
  // A warning about `key` (carried, but changed).
  void Warn(const std::string& key, const std::string& message);

  // Warns about every key that was neither read nor declared not carried.
  void Finish();

 private:
  const nlohmann::json& value_;
  std::string path_;
  std::vector<ImportWarning>& warnings_;
  std::vector<std::string> read_;
};

// Checks that `v` is a finite number; ConfigError at `path` otherwise.
double Rlpos3Number(const nlohmann::json& v, const std::string& path);
// Checks that `v` is an integer in [min, max]; ConfigError at `path` otherwise.
long long Rlpos3Integer(const nlohmann::json& v, const std::string& path, long long min,
                        long long max);

}  // namespace rlpos
