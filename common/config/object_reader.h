#pragma once
// Reads one JSON object field by field, tracking the JSON path for error messages, and
// rejects keys nobody read (with a "did you mean").
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rlpos {

struct NumberRange {
  double min = -1e300;
  double max = 1e300;
  bool min_exclusive = false;
};
inline NumberRange NonNegative() {
  return {0.0, 1e300, false};
}
inline NumberRange Positive() {
  return {0.0, 1e300, true};
}
inline NumberRange Between(double lo, double hi) {
  return {lo, hi, false};
}

std::string JoinPath(const std::string& parent, const std::string& key);
std::string JoinPath(const std::string& parent, std::size_t index);

class ObjectReader {
 public:
  // Throws ConfigError if `value` is not an object.
  ObjectReader(const nlohmann::json& value, std::string path);

  const std::string& path() const { return path_; }
  std::string PathOf(const std::string& key) const { return JoinPath(path_, key); }
  bool Has(const std::string& key) const;

  double Number(const std::string& key, double fallback, NumberRange range = {});
  double RequiredNumber(const std::string& key, NumberRange range = {});
  long long Integer(const std::string& key, long long fallback, long long min, long long max);
  bool Bool(const std::string& key, bool fallback);
  std::string String(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed = {});
  // The raw child (marked as read), or nullptr when absent.
  const nlohmann::json* Child(const std::string& key);

  // Throws ConfigError naming the first key that was never read.
  void Finish() const;

 private:
  const nlohmann::json& Get(const std::string& key);
  const nlohmann::json& value_;
  std::string path_;
  std::vector<std::string> read_;
  std::vector<std::string> known_;
};

// Value checks shared by the readers (also used for array elements).
double CheckedNumber(const nlohmann::json& v, const std::string& path, NumberRange range);
// A non-empty array of strings, each one of `allowed` (empty: any).
std::vector<std::string> ReadStringList(const nlohmann::json& v, const std::string& path,
                                        const std::vector<std::string>& allowed);
std::string TypeName(const nlohmann::json& v);

}  // namespace rlpos
