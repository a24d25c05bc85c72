#include "common/store/legacy_argv.h"

#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "common/job/job.h"

namespace rlpos {

LegacyJobFields LegacyJobFieldsFromArgv(const std::string& argv_json) {
  std::vector<std::string> argv;
  try {
    argv = nlohmann::json::parse(argv_json).get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(e.what());
  }
  LegacyJobFields f;
  nlohmann::json overrides = nlohmann::json::array();
  for (std::size_t i = 1; i + 1 < argv.size(); ++i) {
    const std::string& flag = argv[i];
    const std::string& value = argv[i + 1];
    if (flag == "--fidelity") {
      f.fidelity = value;
    } else if (flag == "--positioner") {
      f.positioner = value;
    } else if (flag == "--duration") {
      f.duration_s = std::stod(value);
    } else if (flag == "--set") {
      const ScenarioOverride o = ParseOverride(value);
      overrides.push_back({o.path, o.value});
    } else if (flag == "--position" && value != "{position}") {
      std::istringstream in(value);
      Vec3 p;
      char c1 = 0, c2 = 0;
      if (in >> p.x >> c1 >> p.y >> c2 >> p.z && c1 == ',' && c2 == ',')
        f.position = p;
    } else {
      continue;
    }
    ++i;
  }
  f.overrides_json = overrides.dump();
  return f;
}

}  // namespace rlpos
