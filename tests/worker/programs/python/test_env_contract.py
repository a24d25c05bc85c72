"""What Gymnasium's check_env checks, checked without gymnasium (Debian packages none, so CI
runs test_env_api's check_env case nowhere): the spaces, the reset and step signatures and
return types, observations inside the observation space, seeding determinism, close. With
gymnasium importable, the same checks run on its spaces."""
import inspect
import math

import numpy as np
import pytest

import rlpos
from conftest import closed_after, scenario_path

SHORT = {"env.episode_duration": 1}  # 10 steps of 0.1 s
KINDS = {
    "discrete": {},
    "continuous": {"agent.algorithm": "sac", "env.action_space": "continuous"},
}


def same(a, b):
    """Gymnasium's data_equivalence: equal types, and equal values all the way down."""
    if type(a) is not type(b):
        return False
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray):
        return a.dtype == b.dtype and a.shape == b.shape and np.array_equal(
            a, b, equal_nan=a.dtype.kind == "f")
    if isinstance(a, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return a == b


def check_space(space, what):
    assert all(callable(getattr(space, m, None)) for m in ("sample", "contains", "seed")), what
    assert isinstance(space.shape, tuple), what
    if hasattr(space, "n"):
        assert space.shape == () and space.n > 0, what
        return
    assert space.low.shape == space.high.shape == space.shape, what
    assert space.low.dtype == space.high.dtype == space.dtype == np.float32, what
    assert np.all(np.isfinite(space.low)) and np.all(np.isfinite(space.high)), what
    assert np.all(space.low <= space.high), what


def check_observation(env, observation):
    assert isinstance(observation, np.ndarray)
    assert observation.dtype == env.observation_space.dtype
    assert observation.shape == env.observation_space.shape
    assert env.observation_space.contains(observation), observation


def check_step_result(env, result):
    assert isinstance(result, tuple) and len(result) == 5
    observation, reward, terminated, truncated, info = result
    check_observation(env, observation)
    assert isinstance(reward, (float, int, np.floating, np.integer)) and np.isfinite(reward)
    assert isinstance(terminated, (bool, np.bool_)) and isinstance(truncated, (bool, np.bool_))
    assert isinstance(info, dict)
    return result


@pytest.fixture(params=sorted(KINDS))
def kind_env(request):
    yield from closed_after(rlpos.make(scenario_path("b"), fidelity="analytic", seed=3,
                                       overrides={**SHORT, **KINDS[request.param]}))


def test_the_spaces_and_attributes(kind_env):
    env = kind_env
    check_space(env.action_space, "action_space")
    check_space(env.observation_space, "observation_space")
    assert isinstance(env.metadata, dict) and env.metadata.get("render_modes") == []
    assert env.render_mode is None
    env.action_space.seed(11)
    samples = [env.action_space.sample() for _ in range(20)]
    assert all(env.action_space.contains(a) for a in samples)
    env.action_space.seed(11)  # a seeded space samples the same actions again
    assert same([env.action_space.sample() for _ in range(20)], samples)


def test_the_signatures_of_reset_and_step(kind_env):
    reset = inspect.signature(kind_env.reset).parameters
    for name in ("seed", "options"):
        assert reset[name].kind == inspect.Parameter.KEYWORD_ONLY
        assert reset[name].default is None
    assert list(inspect.signature(kind_env.step).parameters) == ["action"]


def test_random_start_options_are_seeded_and_checked(kind_env):
    env = kind_env
    baseline = env.reset(seed=5)[1]["position"]
    first = env.reset(seed=5, options={"random_start": True})[1]["position"]
    again = env.reset(seed=5, options={"random_start": True})[1]["position"]
    other = env.reset(seed=6, options={"random_start": True})[1]["position"]
    assert list(first) == list(again)
    assert list(first) != list(baseline) or list(other) != list(baseline)
    for bad in ({"random_start": 1}, {"start": True}):
        with pytest.raises(ValueError, match="options"):
            env.reset(seed=5, options=bad)


def test_a_whole_episode_returns_what_the_api_says(kind_env):
    env = kind_env
    result = env.reset(seed=2, options=None)
    assert isinstance(result, tuple) and len(result) == 2
    check_observation(env, result[0])
    assert isinstance(result[1], dict)
    env.action_space.seed(2)
    steps, truncated = 0, False
    while not truncated:
        _, _, terminated, truncated, _ = check_step_result(env, env.step(env.action_space.sample()))
        assert not terminated
        steps += 1
        assert steps <= env.steps_per_episode
    assert steps == env.steps_per_episode == 10
    # After the episode, reset without a seed starts the next one.
    check_observation(env, env.reset()[0])


def test_same_seed_same_trajectory_another_seed_another():
    # Packet level: the RngRun decides the channel, so a seed can change the trajectory.
    env = rlpos.make(scenario_path("b"), fidelity="packet", overrides=SHORT)
    try:
        def flight(seed):
            env.action_space.seed(0)  # the same actions: only the env's seed differs
            trajectory = [env.reset(seed=seed)]
            while len(trajectory) == 1 or not trajectory[-1][3]:  # until truncated
                trajectory.append(check_step_result(env, env.step(env.action_space.sample())))
            return trajectory

        first = flight(4)
        assert len(first) == env.steps_per_episode + 1
        assert same(flight(4), first)
        assert not same(flight(5), first)
    finally:
        env.close()


def test_close_releases_the_env_once_and_for_all(kind_env):
    env = kind_env
    env.reset(seed=1)
    env.close()
    env.close()  # closing twice is allowed
    with pytest.raises(RuntimeError, match="closed"):
        env.reset()
    with pytest.raises(RuntimeError, match="closed"):
        env.step(env.action_space.sample())
