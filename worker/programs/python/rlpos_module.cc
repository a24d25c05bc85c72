// _rlpos: the C++ side of the Python package rlpos (worker/programs/python/rlpos/). The env runs in
// the calling process, with ns-3, and without the GIL while ns-3 or the analytic model works. The
// Gymnasium surface (spaces, numpy arrays, registration) is the package's Python part.
#include "worker/programs/python/rlpos_module.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "common/config/config_error.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/positioning/positioners/positioners.h"

namespace rlpos::python {
namespace {

// The packet level holds ns-3's simulator, node list and building list, which are process-wide,
// and each UavNetwork starts from Simulator::Destroy: one packet-level user at a time (an env,
// an oracle search that re-scores at packet level, an evaluation). The analytic fidelity owns
// what it uses (worker/env/analytic): any number at once, and no lease.
class Ns3Lease {
 public:
  explicit Ns3Lease(const char* user) {
    std::lock_guard<std::mutex> lock(Mutex());
    if (Holder()) {
      throw std::runtime_error(std::string("rlpos: cannot start ") + user + ": " + Holder() +
                               " holds ns-3 (packet level: one per process, its simulator and "
                               "building list are global); close() it first, or run each in a "
                               "process of its own (analytic envs have no such limit)");
    }
    Holder() = user;
  }
  ~Ns3Lease() {
    std::lock_guard<std::mutex> lock(Mutex());
    Holder() = nullptr;
  }
  Ns3Lease(const Ns3Lease&) = delete;
  Ns3Lease& operator=(const Ns3Lease&) = delete;

 private:
  static std::mutex& Mutex() {
    static std::mutex m;
    return m;
  }
  static const char*& Holder() {
    static const char* holder = nullptr;
    return holder;
  }
};

py::list PositionsList(const Placement& placement) {
  py::list positions;
  for (const auto& q : placement)
    positions.append(py::make_tuple(q.x, q.y, q.z));
  return positions;
}

// The info dict's keys, made and interned once: a step builds no key strings. Never freed, so
// that no Python object is released after the interpreter is gone.
struct InfoKeys {
  static py::str Make(const char* name) {
    return py::reinterpret_steal<py::str>(PyUnicode_InternFromString(name));
  }
  py::str position = Make("position"), positions = Make("positions"),
          serving_uav = Make("serving_uav"), active_uav = Make("active_uav"), n_los = Make("n_los"),
          throughput_mbps = Make("throughput_mbps"), demands_met = Make("demands_met"),
          snr_db = Make("snr_db"), action_mask = Make("action_mask");
};

const InfoKeys& Keys() {
  static const InfoKeys* keys = new InfoKeys();
  return *keys;
}

// Built here, as the Python API hands them out, so that a step costs Python no conversions.
py::dict InfoDict(const StepInfo& info, const ActionMask& mask) {
  const InfoKeys& k = Keys();
  py::dict d;
  const Vec3& p = info.positions.front();
  d[k.position] = py::make_tuple(p.x, p.y, p.z);  // the first UAV's
  if (info.positions.size() > 1) {
    d[k.positions] = PositionsList(info.positions);
    d[k.serving_uav] = info.serving;
    d[k.active_uav] = info.active_uav;
  }
  d[k.n_los] = info.n_los;
  d[k.throughput_mbps] = info.throughput_mbps;
  d[k.demands_met] = info.demands_met;
  d[k.snr_db] = info.snr_db;
  if (!mask.empty()) {
    // int8, Gymnasium's convention for masks.
    py::array_t<std::int8_t> m(static_cast<py::ssize_t>(mask.size()));
    std::copy(mask.begin(), mask.end(), m.mutable_data());
    d[k.action_mask] = std::move(m);
  }
  return d;
}

// The observation as a float32 array clipped to the space (Float32Clip).
py::array_t<float> Observation(const std::vector<double>& values, const Float32Clip& clip) {
  py::array_t<float> out(static_cast<py::ssize_t>(values.size()));
  clip.Apply(values, out.mutable_data());
  return out;
}

// One UavPositioningEnv held for Python: its lease of ns-3 at packet level, its lock (the GIL is
// released while it steps, one step at a time per env), and what both bindings read of it.
class PyEnvHandle {
 public:
  // `lease_user` names it in the error of a second packet-level user; `closed_error` is the
  // error of a call after Close(). Both are string literals (the lease keeps the pointer).
  PyEnvHandle(const std::string& file, const std::vector<std::string>& overrides,
              const char* lease_user, const char* closed_error)
      : closed_error_(closed_error) {
    Scenario s = Load(file, overrides);
    if (s.env.fidelity == "packet")
      lease_ = std::make_unique<Ns3Lease>(lease_user);
    env_ = std::make_unique<UavPositioningEnv>(std::move(s));
  }

  const Scenario& scenario() const { return Open().scenario(); }
  int ActionCount() const { return Open().ActionSpace().n; }
  int StepsPerEpisode() const { return Open().StepsPerEpisode(); }
  Bounds ActionBounds() const { return BoundsOf(Open().ContinuousActionSpace()); }
  Bounds ObservationBounds() const { return BoundsOf(Open().ObservationSpace()); }

  void Close() {
    std::lock_guard<std::mutex> lock(mutex_);
    env_.reset();
    lease_.reset();
  }
  bool closed() const { return env_ == nullptr; }

 protected:
  UavPositioningEnv& Open() const {
    if (!env_)
      throw std::runtime_error(closed_error_);
    return *env_;
  }
  std::mutex mutex_;

 private:
  const char* closed_error_;
  std::unique_ptr<Ns3Lease> lease_;
  std::unique_ptr<UavPositioningEnv> env_;
};

class PyEnv : public PyEnvHandle {
 public:
  PyEnv(const std::string& file, const std::vector<std::string>& overrides)
      : PyEnvHandle(file, overrides, "a packet-level env", "rlpos: the env is closed"),
        clip_(Open().ObservationSpace()) {}

  py::tuple Reset(std::uint64_t seed, bool random_start) {
    const Outcome o = Run([&](UavPositioningEnv& env) {
      StepResult r;
      r.observation = env.Reset(seed, ResetOptions{random_start});
      r.info = env.LastInfo();
      return r;
    });
    return py::make_tuple(Observation(o.result.observation, clip_),
                          InfoDict(o.result.info, o.mask));
  }

  py::tuple Step(int action) {
    return Finish(Run([&](UavPositioningEnv& env) { return env.Step(action); }));
  }
  py::tuple StepContinuous(const std::vector<double>& displacement) {
    return Finish(Run([&](UavPositioningEnv& env) { return env.StepContinuous(displacement); }));
  }

  // Benchmarks: `steps` steps of a fixed action sequence in C++, from a reset with `seed`;
  // returns the wall seconds of the steps alone.
  double TimeSteps(const std::vector<int>& actions, int steps, std::uint64_t seed) {
    if (actions.empty())
      throw py::value_error("TimeSteps needs at least one action");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    UavPositioningEnv& env = Open();
    env.Reset(seed);
    const auto started = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) {
      const StepResult r = env.Step(actions[static_cast<std::size_t>(i) % actions.size()]);
      if (r.truncated || r.terminated)
        env.Reset(seed);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

 private:
  struct Outcome {
    StepResult result;
    ActionMask mask;  // the actions allowed after it
  };

  // Runs `step` on the env without the GIL, under the env's lock, with what Python reads of the
  // env's state afterwards taken under the same lock.
  template <typename F>
  Outcome Run(F step) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    try {
      Outcome o{step(Open()), {}};
      o.mask = Open().ValidActions();
      return o;
    } catch (const std::out_of_range& e) {
      throw py::value_error(e.what());  // an action outside the action space
    }
  }

  // Gymnasium's five values, in their final Python types.
  py::tuple Finish(const Outcome& o) const {
    const StepResult& r = o.result;
    return py::make_tuple(Observation(r.observation, clip_), r.reward, r.terminated, r.truncated,
                          InfoDict(r.info, o.mask));
  }

  Float32Clip clip_;
};

// Several UAVs as agents (rlpos.parallel_env): every UAV moves at once in each step
// (UavPositioningEnv::JointStep). Returns plain lists; the package's Python part makes the
// per-agent dicts and numpy arrays.
class PyParallelEnv : public PyEnvHandle {
 public:
  PyParallelEnv(const std::string& file, const std::vector<std::string>& overrides)
      : PyEnvHandle(file, overrides, "a packet-level parallel env",
                    "rlpos: the parallel env is closed") {}

  std::vector<std::string> AgentNames() const {
    std::vector<std::string> names;
    for (const auto& uav : scenario().uavs)
      names.push_back(uav.name);
    return names;
  }
  Bounds StateBounds() const { return BoundsOf(Open().StateSpace()); }

  // (observations per UAV, state, info)
  py::tuple Reset(std::uint64_t seed, bool random_start) {
    const Outcome o = Run([&](UavPositioningEnv& env) {
      JointStepResult r;
      env.Reset(seed, ResetOptions{random_start});
      r.observations = env.AgentObservations();
      r.state = env.State();
      r.info = env.LastInfo();
      return r;
    });
    return py::make_tuple(o.result.observations, o.result.state, Info(o));
  }
  // (observations per UAV, state, team reward, terminated, truncated, info)
  py::tuple Step(const std::vector<int>& actions) {
    return Finish(Run([&](UavPositioningEnv& env) { return env.JointStep(actions); }));
  }
  py::tuple StepContinuous(const std::vector<std::vector<double>>& displacements) {
    return Finish(
        Run([&](UavPositioningEnv& env) { return env.JointStepContinuous(displacements); }));
  }

 private:
  struct Outcome {
    JointStepResult result;
    std::vector<ActionMask> masks;                 // per UAV, after it
    std::vector<std::vector<double>> team_states;  // per UAV (team_state.h), after it
  };

  // As PyEnv::Run: without the GIL, under the env's lock.
  template <typename F>
  Outcome Run(F step) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    try {
      Outcome o{step(Open()), {}, {}};
      for (std::size_t u = 0; u < o.result.observations.size(); ++u) {
        o.masks.push_back(Open().ValidActionsOf(u));
        o.team_states.push_back(Open().TeamStateOf(u));
      }
      return o;
    } catch (const std::out_of_range& e) {
      throw py::value_error(e.what());  // an action outside the action space
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());  // not one action per UAV
    }
  }

  // The team's info: every UAV's position and mask, each UE's serving UAV, LoS and SNR, and
  // the run's figures (no active_uav: JointStep has no turns).
  static py::dict Info(const Outcome& o) {
    const StepInfo& info = o.result.info;
    py::dict d;
    d["positions"] = PositionsList(info.positions);
    d["serving_uav"] = info.serving;
    d["n_los"] = info.n_los;
    d["los"] = std::vector<int>(info.los.begin(), info.los.end());
    d["throughput_mbps"] = info.throughput_mbps;
    d["demands_met"] = info.demands_met;
    d["snr_db"] = info.snr_db;
    if (!o.masks.empty() && !o.masks.front().empty()) {
      py::list masks;
      for (const auto& mask : o.masks)
        masks.append(std::vector<int>(mask.begin(), mask.end()));
      d["action_masks"] = masks;
    }
    d["team_states"] = o.team_states;
    return d;
  }

  static py::tuple Finish(const Outcome& o) {
    const JointStepResult& r = o.result;
    return py::make_tuple(r.observations, r.state, r.reward, r.terminated, r.truncated, Info(o));
  }
};

py::list Oracle(const std::string& file, const std::vector<std::string>& overrides,
                double grid_step, int packet_candidates, double packet_duration, std::size_t top) {
  const Scenario s = Load(file, overrides);
  OracleOptions options;
  options.grid_step = grid_step;
  options.packet_candidates = packet_candidates;
  options.packet_duration = packet_duration;
  std::vector<ScoredPlacement> ranked;
  {
    std::optional<Ns3Lease> lease;
    if (packet_candidates > 0)
      lease.emplace("an oracle search with packet-level candidates");
    py::gil_scoped_release release;
    ranked = OracleSearch(s, options);
  }
  py::list out;
  if (top > 0 && ranked.size() > top)
    ranked.resize(top);
  for (const auto& c : ranked) {
    py::dict d;
    const Vec3& p = c.placement.front();
    d["position"] = py::make_tuple(p.x, p.y, p.z);
    if (c.placement.size() > 1)
      d["positions"] = PositionsList(c.placement);
    d["analytic_reward"] = c.analytic_reward;
    d["packet_reward"] = c.packet_reward ? py::object(py::float_(*c.packet_reward)) : py::none();
    d["n_los"] = c.n_los;
    d["throughput_mbps"] = c.throughput_mbps;
    out.append(d);
  }
  return out;
}

std::string Evaluate(const std::string& file, const std::vector<std::string>& overrides,
                     const std::vector<std::vector<double>>& positions) {
  const Scenario s = Load(file, overrides);
  Placement placement;
  try {
    std::vector<std::string> texts;
    for (const auto& p : positions) {
      if (p.size() != 3)
        throw py::value_error("position: expected (x, y, z) per UAV");
      texts.push_back(FormatPosition({p[0], p[1], p[2]}));
    }
    placement = ParsePlacement(s, texts, "position");
  } catch (const ConfigError& e) {
    throw py::value_error(e.describe());
  }
  RunMetrics metrics;
  {
    Ns3Lease lease("a packet-level evaluation");
    py::gil_scoped_release release;
    metrics = EvaluatePosition(s, placement);
    std::string why;  // as rlpos-sim eval adds it: null where the analytic model refuses s
    metrics.reward = PacketEvalReward(s, placement, why);
  }
  nlohmann::json out = ToJson(metrics);
  out["scenario"] = s.name;
  return out.dump();  // the Python side parses it: the same JSON as rlpos-sim eval --json
}

}  // namespace
}  // namespace rlpos::python

PYBIND11_MODULE(_rlpos, m) {
  using namespace rlpos::python;
  m.doc() =
      "C++ side of rlpos: the UAV positioning env (one env, a batch, or every UAV as an agent), "
      "the oracle and packet-level evaluation";
  // What the single env and the parallel env both tell of their scenario and spaces.
  py::class_<PyEnvHandle>(m, "EnvHandle")
      .def_property_readonly("action_count", &PyEnvHandle::ActionCount)
      .def_property_readonly("action_bounds", &PyEnvHandle::ActionBounds)
      .def_property_readonly("observation_bounds", &PyEnvHandle::ObservationBounds)
      .def_property_readonly("steps_per_episode", &PyEnvHandle::StepsPerEpisode)
      .def_property_readonly("scenario_name",
                             [](const PyEnvHandle& e) { return e.scenario().name; })
      .def_property_readonly("fidelity",
                             [](const PyEnvHandle& e) { return e.scenario().env.fidelity; })
      .def_property_readonly("agent_seed",
                             [](const PyEnvHandle& e) { return e.scenario().agent.seed; })
      .def_property_readonly("actions",
                             [](const PyEnvHandle& e) { return e.scenario().env.actions; })
      // The scenario as loaded (file, overrides, defaults), every field explicit: what
      // rlpos-sim train writes as a policy folder's scenario.json.
      .def_property_readonly("scenario_json",
                             [](const PyEnvHandle& e) { return ToJson(e.scenario()).dump(); })
      .def_property_readonly("closed", &PyEnvHandle::closed)
      .def("close", &PyEnvHandle::Close);
  py::class_<PyEnv, PyEnvHandle>(m, "Env")
      .def(py::init<const std::string&, const std::vector<std::string>&>(), py::arg("scenario"),
           py::arg("overrides"))
      .def("reset", &PyEnv::Reset, py::arg("seed"), py::arg("random_start") = false)
      .def("step", &PyEnv::Step, py::arg("action"))
      .def("step_continuous", &PyEnv::StepContinuous, py::arg("displacement"))
      .def("time_steps", &PyEnv::TimeSteps, py::arg("actions"), py::arg("steps"), py::arg("seed"));
  BindVectorEnv(m);
  py::class_<PyParallelEnv, PyEnvHandle>(m, "ParallelEnv")
      .def(py::init<const std::string&, const std::vector<std::string>&>(), py::arg("scenario"),
           py::arg("overrides"))
      .def_property_readonly("agent_names", &PyParallelEnv::AgentNames)
      .def_property_readonly("state_bounds", &PyParallelEnv::StateBounds)
      .def("reset", &PyParallelEnv::Reset, py::arg("seed"), py::arg("random_start") = false)
      .def("step", &PyParallelEnv::Step, py::arg("actions"))
      .def("step_continuous", &PyParallelEnv::StepContinuous, py::arg("displacements"));
  m.def("oracle", &Oracle, py::arg("scenario"), py::arg("overrides"), py::arg("grid_step"),
        py::arg("packet_candidates"), py::arg("packet_duration"), py::arg("top"));
  m.def("evaluate", &Evaluate, py::arg("scenario"), py::arg("overrides"), py::arg("position"));
}
