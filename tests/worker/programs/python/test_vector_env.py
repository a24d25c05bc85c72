"""rlpos.make_vec: Gymnasium's VectorEnv contract checked without gymnasium (the spaces, reset
and step signatures, dtypes and shapes, next-step autoreset, close), the same trajectory as
rlpos.make's env, and its errors, none of which leaks a thread."""
import inspect
import json
import os

import numpy as np
import pytest

import rlpos
from rlpos.spaces import GYMNASIUM
from conftest import closed_after, scenario_path

SHORT = {"env.episode_duration": 1}  # 10 steps of 0.1 s
CONTINUOUS = {"agent.algorithm": "sac", "env.action_space": "continuous"}
INFO_KEYS = {"position", "n_los", "throughput_mbps", "demands_met", "action_mask"}


def threads_of_this_process():
    return len(os.listdir("/proc/self/task"))


@pytest.fixture
def envs(scenario_b):
    yield from closed_after(
        rlpos.make_vec(scenario_b, num_envs=4, seed=3, overrides=SHORT, threads=2))


def check_infos(infos, n, keys):
    assert isinstance(infos, dict)
    assert {k for k in infos if not k.startswith("_")} == keys
    for key in keys:
        assert isinstance(infos[key], np.ndarray) and infos[key].shape[0] == n, key
        mask = infos["_" + key]
        assert mask.dtype == np.bool_ and mask.shape == (n,) and mask.all(), key


def test_the_attributes_and_spaces(envs):
    assert envs.num_envs == 4
    assert envs.threads == 2
    assert envs.single_action_space.n == 7
    assert envs.single_observation_space.shape == (4,)
    assert envs.single_observation_space.dtype == np.float32
    assert list(envs.action_space.nvec) == [7] * 4  # MultiDiscrete, as Gymnasium batches
    assert envs.observation_space.shape == (4, 4)
    assert envs.observation_space.dtype == np.float32
    assert np.array_equal(envs.observation_space.low[2], envs.single_observation_space.low)
    mode = envs.metadata["autoreset_mode"]
    if GYMNASIUM:
        import gymnasium
        assert mode is gymnasium.vector.AutoresetMode.NEXT_STEP
    else:
        assert mode == "next_step"
    assert envs.render_mode is None and envs.closed is False
    for _ in range(10):
        assert envs.action_space.contains(envs.action_space.sample())


def test_the_signatures_of_reset_and_step(envs):
    reset = inspect.signature(envs.reset).parameters
    for name in ("seed", "options"):
        assert reset[name].kind == inspect.Parameter.KEYWORD_ONLY
        assert reset[name].default is None
    assert list(inspect.signature(envs.step).parameters) == ["actions"]


def test_reset_and_step_return_batched_arrays(envs):
    observations, infos = envs.reset(seed=5)
    assert observations.dtype == np.float32 and observations.shape == (4, 4)
    assert envs.observation_space.contains(observations)
    assert observations.tolist() == [[50, 50, 25, 1]] * 4
    check_infos(infos, 4, INFO_KEYS)
    assert infos["position"].shape == (4, 3) and infos["position"].dtype == np.float64
    assert infos["n_los"].dtype == np.int64 and infos["throughput_mbps"].dtype == np.float64
    assert infos["action_mask"].dtype == np.int8 and infos["action_mask"].shape == (4, 7)
    envs.action_space.seed(1)
    for step in range(1, 13):
        result = envs.step(envs.action_space.sample())
        assert isinstance(result, tuple) and len(result) == 5
        observations, rewards, terminations, truncations, infos = result
        assert envs.observation_space.contains(observations)
        assert rewards.dtype == np.float64 and rewards.shape == (4,)
        assert terminations.dtype == np.bool_ and truncations.dtype == np.bool_
        assert terminations.shape == truncations.shape == (4,)
        assert not terminations.any()
        assert truncations.all() == (step == 10) and (truncations.any() == (step == 10))
        check_infos(infos, 4, INFO_KEYS)
        if step == 11:  # next-step autoreset: the reset observation, reward 0
            assert observations.tolist() == [[50, 50, 25, 1]] * 4
            assert rewards.tolist() == [0.0] * 4


def test_n_1_flies_exactly_rlpos_make_s_trajectory(scenario_b):
    for overrides in (SHORT, {**SHORT, **CONTINUOUS}):
        one = rlpos.make(scenario_b, fidelity="analytic", seed=8, overrides=overrides)
        vec = rlpos.make_vec(scenario_b, num_envs=1, seed=8, overrides=overrides)
        try:
            obs, info = one.reset(options={"random_start": True})
            vobs, vinfos = vec.reset(options={"random_start": True})
            one.action_space.seed(4)
            ended, resets = False, 0
            for _ in range(35):
                action = one.action_space.sample()
                vobs, vrew, vterm, vtrunc, vinfos = vec.step(np.array([action]))
                if ended:  # the vector env resets itself; the single env is reset by hand
                    obs, info = one.reset()
                    reward, terminated, truncated = 0.0, False, False
                    resets += 1
                else:
                    obs, reward, terminated, truncated, info = one.step(action)
                ended = terminated or truncated
                assert np.array_equal(vobs[0], obs) and vobs.dtype == obs.dtype
                assert vrew[0] == reward and vterm[0] == terminated and vtrunc[0] == truncated
                assert tuple(vinfos["position"][0]) == info["position"]
                for key in ("n_los", "throughput_mbps", "demands_met"):
                    assert vinfos[key][0] == info[key], key
                if "action_mask" in info:
                    assert np.array_equal(vinfos["action_mask"][0], info["action_mask"])
            assert resets == 3
        finally:
            one.close()
            vec.close()


def test_seeds_an_int_a_list_or_the_next_runs(scenario_b):
    envs = rlpos.make_vec(scenario_b, num_envs=3, overrides=SHORT)
    try:
        start = {"random_start": True}
        by_int = envs.reset(seed=20, options=start)[1]["position"]
        by_list = envs.reset(seed=[20, 21, 22], options=start)[1]["position"]
        assert np.array_equal(by_int, by_list)
        mixed = envs.reset(seed=[20, None, 22], options=start)[1]["position"]
        assert np.array_equal(mixed[[0, 2]], by_int[[0, 2]])
        # None: each env's next run, here the one after 21 (env 1's last seed).
        single = rlpos.make(scenario_b, fidelity="analytic", overrides=SHORT)
        assert tuple(mixed[1]) == single.reset(seed=22, options=start)[1]["position"]
        single.close()
        assert not np.array_equal(by_int[0], by_int[1]) or not np.array_equal(by_int[1], by_int[2])
    finally:
        envs.close()


def test_a_list_of_scenarios_alternates(scenario_b, tmp_path):
    with open(scenario_b) as f:
        document = json.load(f)
    document["name"] = "B-open"
    document["buildings"] = []  # the same spaces, another channel
    open_b = tmp_path / "open.json"
    open_b.write_text(json.dumps(document))
    envs = rlpos.make_vec([scenario_b, open_b], num_envs=3, overrides=SHORT)
    try:
        assert envs.scenario_names == ["B", "B-open", "B"]
        _, infos = envs.reset(seed=1)
        assert infos["n_los"].tolist() == [1, 4, 1]  # at the baseline, no tower in the way
    finally:
        envs.close()


def test_continuous_actions(scenario_b):
    envs = rlpos.make_vec(scenario_b, num_envs=2, seed=1, overrides={**SHORT, **CONTINUOUS})
    try:
        assert envs.single_action_space.shape == (3,)
        assert envs.action_space.shape == (2, 3) and envs.action_space.dtype == np.float32
        observations, infos = envs.reset()
        assert "action_mask" not in infos
        observations, rewards, _, _, infos = envs.step(
            np.array([[0, -5, 0], [5, 5, 5]], np.float32))
        assert infos["position"].tolist() == [[50, 45, 25], [55, 55, 30]]
    finally:
        envs.close()


def test_several_uavs_fly_as_in_rlpos_make():
    urban3 = scenario_path("urban3")
    envs = rlpos.make_vec(urban3, num_envs=2, seed=1, overrides=SHORT)
    singles = [rlpos.make(urban3, fidelity="analytic", seed=s, overrides=SHORT) for s in (1, 2)]
    try:
        observations, infos = envs.reset(options={"random_start": True})
        envs.action_space.seed(3)
        for t in range(12):
            for i, single in enumerate(singles):
                if t == 0:
                    obs, info = single.reset(options={"random_start": True})
                elif t == 11:  # after the last step of the episode, the autoreset
                    obs, info = single.reset()
                else:
                    obs, _, _, _, info = single.step(actions[i])
                assert np.array_equal(observations[i], obs)
                assert tuple(infos["position"][i]) == info["position"]
                assert [tuple(p) for p in infos["positions"][i]] == info["positions"]
                assert infos["active_uav"][i] == info["active_uav"]
            actions = envs.action_space.sample()
            observations, _, _, _, infos = envs.step(actions)
    finally:
        envs.close()
        for single in singles:
            single.close()


# Bad input: a one-line ValueError (RuntimeError for the state) naming what is wrong, and no
# thread left behind.
def one_line_error(kind, match, f):
    with pytest.raises(kind, match=match) as e:
        f()
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("num_envs", [0, 4097, -1, 2.0, True, None])
def test_bad_num_envs(scenario_b, num_envs):
    before = threads_of_this_process()
    one_line_error(ValueError, "num_envs", lambda: rlpos.make_vec(scenario_b, num_envs=num_envs))
    assert threads_of_this_process() == before


def test_packet_fidelity_points_to_one_process_per_env(scenario_b):
    before = threads_of_this_process()
    one_line_error(ValueError, "one process per", lambda: rlpos.make_vec(
        scenario_b, num_envs=2, fidelity="packet"))
    # The scenario's own fidelity (B: packet), kept with fidelity=None, is refused in C++.
    one_line_error(ValueError, "one process per", lambda: rlpos.make_vec(
        scenario_b, num_envs=2, fidelity=None))
    assert threads_of_this_process() == before


def test_scenarios_whose_spaces_differ(scenario_b, tmp_path):
    with open(scenario_b) as f:
        document = json.load(f)
    document["name"] = "B3"
    document.setdefault("env", {})["observations"] = ["x", "y", "z"]
    fewer = tmp_path / "fewer.json"
    fewer.write_text(json.dumps(document))
    before = threads_of_this_process()
    one_line_error(ValueError, r"scenario 1 \(B3\) and scenario 0 \(B\) differ in their "
                               r"observation space", lambda: rlpos.make_vec(
                                   [scenario_b, str(fewer)], num_envs=4))
    assert threads_of_this_process() == before


BAD_DISCRETE = [
    (np.array([0, 1, 2]), "shape"),                      # 3 actions for 4 envs
    (np.array([[0], [1], [2], [3]]), "shape"),
    (np.array([0.0, 1.0, 2.0, 3.0]), "dtype"),
    (np.array([True, False, True, False]), "dtype"),
    (np.array(["up"] * 4), "dtype"),
    (np.array([0, 1, 7, 2]), r"actions\[2\]: expected a move index in \[0, 7\), got 7"),
    (np.array([0, -1, 1, 2]), r"actions\[1\]"),
    (np.array([0, 1, 2, 2**64 - 1], np.uint64), r"actions\[3\]: .* got 18446744073709551615"),
    (3, "shape"),
]


@pytest.mark.parametrize("actions,match", BAD_DISCRETE)
def test_bad_discrete_actions(envs, actions, match):
    envs.reset(seed=1)
    before = threads_of_this_process()
    one_line_error(ValueError, match, lambda: envs.step(actions))
    assert threads_of_this_process() == before
    # Nothing stepped: the next good step is the episode's first.
    _, _, _, truncations, _ = envs.step(np.zeros(4, np.int64))
    assert not truncations.any()


@pytest.mark.parametrize("actions,match", [
    (np.zeros((2, 2)), "shape"),
    (np.zeros(6), "shape"),
    (np.array([[0, 0, 0], [0, 5.5, 0]]), r"actions\[1\]\[1\]: expected within \[-5, 5\] m"),
    (np.array([[0, 0, np.nan], [0, 0, 0]]), r"actions\[0\]\[2\]"),
    (np.array([[0, 0, 0], [0, 0, 0]], dtype=complex), "dtype"),
])
def test_bad_continuous_actions(scenario_b, actions, match):
    envs = rlpos.make_vec(scenario_b, num_envs=2, seed=1, overrides={**SHORT, **CONTINUOUS})
    try:
        envs.reset()
        one_line_error(ValueError, match, lambda: envs.step(actions))
    finally:
        envs.close()


@pytest.mark.parametrize("seed", [-1, 2**63, 1.5, "1", [1, 2], [1, 2, 3, -4]])
def test_bad_seeds(envs, seed):
    one_line_error(ValueError, "seed", lambda: envs.reset(seed=seed))


@pytest.mark.parametrize("threads", [0, 5, 1.0])
def test_bad_threads(scenario_b, threads):
    one_line_error(ValueError, "threads", lambda: rlpos.make_vec(scenario_b, num_envs=4,
                                                                 threads=threads))


def test_bad_options(envs):
    for options in ({"random_start": 1}, {"reset_mask": np.ones(4, bool)}):
        one_line_error(ValueError, "options", lambda: envs.reset(options=options))


def test_stepping_before_reset_or_after_close_is_a_runtime_error(scenario_b):
    before = threads_of_this_process()
    envs = rlpos.make_vec(scenario_b, num_envs=8, overrides=SHORT, threads=4)
    assert threads_of_this_process() == before + 3  # the caller's thread is the fourth
    one_line_error(RuntimeError, "reset", lambda: envs.step(np.zeros(8, np.int64)))
    envs.reset()
    envs.close()
    assert threads_of_this_process() == before
    envs.close()  # closing twice is allowed
    assert envs.closed
    one_line_error(RuntimeError, "closed", lambda: envs.step(np.zeros(8, np.int64)))
    one_line_error(RuntimeError, "closed", lambda: envs.reset())
