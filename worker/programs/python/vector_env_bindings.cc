// rlpos.VectorEnv's C++ side: N analytic envs stepped together (worker/env/vector_env), bound
// for the module _rlpos (rlpos_module.cc).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "worker/env/vector_env/batched_env.h"
#include "worker/programs/python/rlpos_module.h"

namespace rlpos::python {
namespace {

// N analytic envs stepped together (worker/env/vector_env), for rlpos.VectorEnv. Each call fills
// numpy arrays it allocates, without the GIL: the observations are copied once, from the envs
// into the array Python receives.
class PyVectorEnv {
 public:
  PyVectorEnv(const std::vector<std::string>& files, const std::vector<std::string>& overrides,
              std::size_t num_envs, std::optional<std::uint64_t> seed, std::size_t threads) {
    std::vector<Scenario> scenarios;
    for (const auto& file : files)
      scenarios.push_back(Load(file, overrides));
    BatchedEnvOptions options;
    options.num_envs = num_envs;
    options.seed = seed;
    options.threads = threads;
    env_ = std::make_unique<BatchedEnv>(scenarios, options);  // invalid_argument: ValueError
  }

  std::size_t NumEnvs() const { return Open().NumEnvs(); }
  std::size_t Threads() const { return Open().Threads(); }
  std::size_t UavCount() const { return Open().UavCount(); }
  int ActionCount() const { return Open().ActionSpace().n; }
  Bounds ActionBounds() const { return BoundsOf(Open().ContinuousActionSpace()); }
  Bounds ObservationBounds() const { return BoundsOf(Open().ObservationSpace()); }
  std::vector<std::string> ScenarioNames() const {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < Open().NumEnvs(); ++i)
      names.push_back(Open().ScenarioOf(i).name);
    return names;
  }
  std::vector<std::string> Moves() const { return Open().ScenarioOf(0).env.actions; }

  // (observations, fields): fields = the info arrays by name.
  py::tuple Reset(const std::vector<std::optional<std::uint64_t>>& seeds, bool random_start) {
    Arrays a = Allocate(false);
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      Open().Reset(seeds, ResetOptions{random_start}, a.buffers);
    }
    return py::make_tuple(a.observations, a.fields);
  }

  // (observations, rewards, terminations, truncations, fields). `actions`: N move indices, or
  // N x 3 displacements; the Python side has checked their dtype and shape.
  py::tuple Step(const py::array& actions) {
    Arrays a = Allocate(true);
    if (Open().ActionSpace().n > 0) {
      const auto moves =
          py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(actions);
      if (!moves)
        throw py::value_error("actions: expected integer move indices");
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      Open().Step(moves.data(), static_cast<std::size_t>(moves.size()), a.buffers);
    } else {
      const auto d =
          py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(actions);
      if (!d)
        throw py::value_error("actions: expected displacements (numbers)");
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      Open().StepContinuous(d.data(), static_cast<std::size_t>(d.size()), a.buffers);
    }
    return py::make_tuple(a.observations, a.rewards, a.terminated, a.truncated, a.fields);
  }

  void Close() {
    std::unique_ptr<BatchedEnv> env;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      env = std::move(env_);
    }
    py::gil_scoped_release release;  // joins the pool's threads
    env.reset();
  }
  bool closed() const { return env_ == nullptr; }

 private:
  BatchedEnv& Open() const {
    if (!env_)
      throw std::runtime_error("rlpos: the vector env is closed");
    return *env_;
  }

  struct Arrays {
    py::array_t<float> observations;
    py::array_t<double> rewards;
    py::array_t<bool> terminated, truncated;
    py::dict fields;
    BatchBuffers buffers;
  };

  Arrays Allocate(bool step) const {
    const BatchedEnv& env = Open();
    const auto n = static_cast<py::ssize_t>(env.NumEnvs());
    Arrays a;
    a.observations = py::array_t<float>({n, static_cast<py::ssize_t>(env.ObservationDim())});
    a.buffers.observations = a.observations.mutable_data();
    if (step) {
      a.rewards = py::array_t<double>(n);
      a.terminated = py::array_t<bool>(n);
      a.truncated = py::array_t<bool>(n);
      a.buffers.rewards = a.rewards.mutable_data();
      a.buffers.terminated = a.terminated.mutable_data();
      a.buffers.truncated = a.truncated.mutable_data();
    }
    py::array_t<double> positions({n, static_cast<py::ssize_t>(env.UavCount()), py::ssize_t{3}});
    py::array_t<std::int64_t> active(n), n_los(n), demands(n);
    py::array_t<double> throughput(n);
    a.buffers.positions = positions.mutable_data();
    a.buffers.active_uav = active.mutable_data();
    a.buffers.n_los = n_los.mutable_data();
    a.buffers.throughput_mbps = throughput.mutable_data();
    a.buffers.demands_met = demands.mutable_data();
    a.fields["positions"] = positions;
    a.fields["active_uav"] = active;
    a.fields["n_los"] = n_los;
    a.fields["throughput_mbps"] = throughput;
    a.fields["demands_met"] = demands;
    if (env.HasActionMask()) {
      py::array_t<std::int8_t> mask({n, static_cast<py::ssize_t>(env.ActionCount())});
      a.buffers.action_mask = mask.mutable_data();
      a.fields["action_mask"] = mask;
    }
    return a;
  }

  std::unique_ptr<BatchedEnv> env_;
  std::mutex mutex_;  // one call at a time per vector env (the GIL is released inside)
};

}  // namespace

void BindVectorEnv(py::module_& m) {
  py::class_<PyVectorEnv>(m, "VectorEnv")
      .def(py::init<const std::vector<std::string>&, const std::vector<std::string>&, std::size_t,
                    std::optional<std::uint64_t>, std::size_t>(),
           py::arg("scenarios"), py::arg("overrides"), py::arg("num_envs"), py::arg("seed"),
           py::arg("threads"))
      .def_property_readonly("num_envs", &PyVectorEnv::NumEnvs)
      .def_property_readonly("threads", &PyVectorEnv::Threads)
      .def_property_readonly("uav_count", &PyVectorEnv::UavCount)
      .def_property_readonly("action_count", &PyVectorEnv::ActionCount)
      .def_property_readonly("action_bounds", &PyVectorEnv::ActionBounds)
      .def_property_readonly("observation_bounds", &PyVectorEnv::ObservationBounds)
      .def_property_readonly("scenario_names", &PyVectorEnv::ScenarioNames)
      .def_property_readonly("actions", &PyVectorEnv::Moves)
      .def_property_readonly("closed", &PyVectorEnv::closed)
      .def("reset", &PyVectorEnv::Reset, py::arg("seeds"), py::arg("random_start"))
      .def("step", &PyVectorEnv::Step, py::arg("actions"))
      .def("close", &PyVectorEnv::Close);
}

}  // namespace rlpos::python
