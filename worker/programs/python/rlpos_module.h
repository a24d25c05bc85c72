#pragma once
// What the files of the module _rlpos share: the scenario loaded as the CLI loads it, a space's
// bounds as Python takes them, and the classes bound in files of their own
// (vector_env_bindings.cc).
#include <pybind11/pybind11.h>

#include <string>
#include <utility>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario/scenario.h"
#include "worker/env/gym/spaces.h"
#include "worker/env/network/scenario_loading.h"

namespace py = pybind11;

namespace rlpos::python {

// The scenario as the CLI loads it; a bad file, key or value is a ValueError with the CLI's
// one-line message ("<file>: <JSON path>: <problem>").
inline Scenario Load(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    return LoadScenario(file, overrides);
  } catch (const ConfigError& e) {
    const bool cli = e.path().rfind("--", 0) == 0;
    throw py::value_error((cli ? "" : file + ": ") + e.describe());
  }
}

// A Box space's (low, high): the Python part makes its float32 Box of them.
using Bounds = std::pair<std::vector<double>, std::vector<double>>;
inline Bounds BoundsOf(const BoxSpace& box) {
  return {box.low, box.high};
}

// rlpos.VectorEnv (N analytic envs stepped together): its class, added to the module `m`.
void BindVectorEnv(py::module_& m);

}  // namespace rlpos::python
