"""rlpos.make_vec against Gymnasium itself, where gymnasium is importable. Debian packages none,
so CMake registers this suite only where it imports; test_vector_env.py checks the same contract
without it. It is a gymnasium.vector.VectorEnv, Gymnasium's vector wrappers run on it, and it gives
what gymnasium.vector.SyncVectorEnv over rlpos.make gives for the same seeds and actions."""
import warnings

import numpy as np
import pytest

import rlpos

gymnasium = pytest.importorskip("gymnasium")

SHORT = {"env.episode_duration": 1}  # 10 steps of 0.1 s


def test_it_is_a_gymnasium_vector_env_with_next_step_autoreset(scenario_b):
    envs = rlpos.make_vec(scenario_b, num_envs=3, seed=1, overrides=SHORT)
    try:
        assert isinstance(envs, gymnasium.vector.VectorEnv)
        assert envs.metadata["autoreset_mode"] is gymnasium.vector.AutoresetMode.NEXT_STEP
        assert envs.action_space == gymnasium.vector.utils.batch_space(
            envs.single_action_space, 3)
        assert envs.observation_space == gymnasium.vector.utils.batch_space(
            envs.single_observation_space, 3)
    finally:
        envs.close()
    assert envs.closed


def test_gymnasium_vector_wrappers_run_on_it(scenario_b):
    envs = rlpos.make_vec(scenario_b, num_envs=4, seed=1, overrides=SHORT)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # e.g. a missing or wrong autoreset_mode
        wrapped = gymnasium.wrappers.vector.RecordEpisodeStatistics(
            gymnasium.wrappers.vector.NormalizeObservation(envs))
        wrapped.reset(seed=2)
        wrapped.action_space.seed(2)
        episodes = 0
        for _ in range(25):
            *_, infos = wrapped.step(wrapped.action_space.sample())
            if "episode" in infos:
                episodes += int(infos["_episode"].sum())
                assert np.all(infos["episode"]["l"][infos["_episode"]] == 10)
    wrapped.close()
    assert episodes == 8  # each of the 4 envs ended at steps 10 and 21


@pytest.mark.parametrize("overrides", [SHORT, {**SHORT, "agent.algorithm": "sac",
                                               "env.action_space": "continuous"}])
def test_the_same_as_sync_vector_env_over_rlpos_make(scenario_b, overrides):
    n = 3
    sync = gymnasium.vector.SyncVectorEnv(
        [lambda: rlpos.make(scenario_b, fidelity="analytic", overrides=overrides)] * n)
    ours = rlpos.make_vec(scenario_b, num_envs=n, overrides=overrides)
    try:
        assert sync.single_action_space == ours.single_action_space
        assert sync.single_observation_space == ours.single_observation_space
        assert sync.action_space == ours.action_space
        assert sync.observation_space == ours.observation_space
        options = {"random_start": True}
        a, a_infos = sync.reset(seed=40, options=options)
        b, b_infos = ours.reset(seed=40, options=options)
        assert np.array_equal(a, b) and a.dtype == b.dtype
        ours.action_space.seed(9)
        for _ in range(30):
            actions = ours.action_space.sample()
            a_result = sync.step(actions)
            b_result = ours.step(actions)
            for x, y in zip(a_result[:4], b_result[:4]):
                assert np.array_equal(x, y) and x.dtype == y.dtype
            a_infos, b_infos = a_result[4], b_result[4]
            for key in ("n_los", "throughput_mbps", "demands_met", "action_mask"):
                if key in a_infos:
                    assert np.array_equal(a_infos[key], b_infos[key]), key
                    assert np.array_equal(a_infos["_" + key], b_infos["_" + key]), key
            assert np.array_equal(np.array(list(a_infos["position"]), float), b_infos["position"])
    finally:
        sync.close()
        ours.close()
