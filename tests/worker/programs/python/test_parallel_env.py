"""rlpos.parallel_env against PettingZoo's ParallelEnv contract. Debian packages no pettingzoo, so
these tests check what its parallel_api_test and parallel_seed_test check (the spaces, the
agents' bookkeeping, the keys and types of what reset and step return, observations inside
their spaces, seeding determinism), on a three-UAV scenario (urban3) and a one-UAV one (B);
the real parallel_api_test runs where pettingzoo is importable."""
import inspect

import numpy as np
import pytest

import rlpos
from conftest import closed_after, scenario_path
from test_env_contract import check_space, same

SHORT = {"env.episode_duration": 1}  # 10 steps of 0.1 s
CASES = {
    "urban3": ("urban3", {}),
    "urban3-continuous": ("urban3", {"agent.algorithm": "sac",
                                     "env.action_space": "continuous"}),
    "b": ("b", {}),
}


def make(name, seed=3, **overrides):
    scenario, extra = CASES[name]
    return rlpos.parallel_env(scenario_path(scenario), fidelity="analytic", seed=seed,
                              overrides={**SHORT, **extra, **overrides})


@pytest.fixture(params=sorted(CASES))
def env(request):
    yield from closed_after(make(request.param))


def sample(env, agents=None):
    return {a: env.action_space(a).sample() for a in (env.agents if agents is None else agents)}


def check_observations(env, observations):
    assert isinstance(observations, dict) and set(observations) == set(env.possible_agents)
    for agent, obs in observations.items():
        space = env.observation_space(agent)
        assert isinstance(obs, np.ndarray) and obs.dtype == space.dtype == np.float32
        assert obs.shape == space.shape and space.contains(obs), (agent, obs)


def check_state(env):
    state = env.state()
    assert isinstance(state, np.ndarray) and state.dtype == env.state_space.dtype == np.float32
    assert state.shape == env.state_space.shape and env.state_space.contains(state), state
    return state


def test_the_agents_are_the_uavs_and_their_spaces_are_fixed_objects(env):
    names = {"urban3": ["uav1", "uav2", "uav3"], "b": ["uav"]}
    assert env.possible_agents == names["b" if len(env.possible_agents) == 1 else "urban3"]
    assert env.agents == [] and env.num_agents == 0  # no episode yet
    assert env.max_num_agents == len(env.possible_agents)
    for agent in env.possible_agents:
        assert env.observation_space(agent) is env.observation_space(agent)
        assert env.action_space(agent) is env.action_space(agent)
        check_space(env.observation_space(agent), "observation_space(%s)" % agent)
        check_space(env.action_space(agent), "action_space(%s)" % agent)
    check_space(env.state_space, "state_space")
    k, n = len(env.possible_agents), {1: 4, 3: 20}[len(env.possible_agents)]
    assert env.state_space.shape == (3 * k + 3 * n + 2,)
    assert env.metadata["name"] == "rlpos_uav_positioning_v0"
    assert env.metadata["is_parallelizable"] is True
    assert env.render_mode is None and env.render() is None
    assert env.unwrapped is env
    with pytest.raises(ValueError, match="agent: 'nobody' is not one of"):
        env.action_space("nobody")


def test_the_signatures_of_reset_and_step(env):
    reset = inspect.signature(env.reset).parameters
    assert list(reset) == ["seed", "options"]
    assert reset["seed"].default is None and reset["options"].default is None
    assert list(inspect.signature(env.step).parameters) == ["actions"]


def test_a_whole_episode_keeps_the_books(env):
    # PettingZoo's parallel_api_test: reset takes seed and options (any keys), the dicts have
    # one key per live agent, agents empty once every agent is truncated.
    env.reset(seed=0, options={"options": 1})
    observations, infos = env.reset()
    check_observations(env, observations)
    assert set(infos) == set(env.agents) == set(env.possible_agents)
    assert all(isinstance(i, dict) for i in infos.values())
    check_state(env)
    for agent in env.possible_agents:
        env.action_space(agent).seed(1)
    steps = 0
    while env.agents:
        live = list(env.agents)
        observations, rewards, terminations, truncations, infos = env.step(sample(env))
        steps += 1
        assert steps <= env.steps_per_episode, "the episode outlived env.episode_duration"
        check_observations(env, observations)
        for d in (rewards, terminations, truncations, infos):
            assert isinstance(d, dict) and set(d) == set(live)
        assert all(isinstance(r, float) and np.isfinite(r) for r in rewards.values())
        assert len(set(rewards.values())) == 1  # a team: one reward
        assert all(isinstance(t, bool) for t in list(terminations.values())
                   + list(truncations.values()))
        assert not any(terminations.values())
        assert env.agents == ([] if all(truncations.values()) else live)
        assert set(env.agents) <= set(env.possible_agents)
        check_state(env)
    assert steps == env.steps_per_episode == 10


def test_the_per_agent_views_and_the_state_agree():
    env = make("urban3")
    observations, infos = env.reset(seed=1)
    k = 3
    for _ in range(4):
        observations, rewards, _, _, infos = env.step(sample(env))
    state = env.state()
    served = 0
    for u, agent in enumerate(env.possible_agents):
        obs = observations[agent]
        assert list(obs[-k:]) == [1.0 if v == u else 0.0 for v in range(k)]  # itself active
        assert np.array_equal(obs[:-k], observations[env.possible_agents[0]][:-k])
        x, y, z = infos[agent]["position"]
        assert (obs[u], obs[k + u], obs[2 * k + u]) == (np.float32(x), np.float32(y),
                                                         np.float32(z))
        assert tuple(state[3 * u:3 * u + 3]) == (np.float32(x), np.float32(y), np.float32(z))
        served += infos[agent]["ues_served"]
    assert served == 20
    los = state[3 * k:3 * k + 60:3]
    assert set(los) <= {0.0, 1.0} and los.sum() == infos["uav1"]["n_los"] == obs[3 * k]
    assert state[-1] == infos["uav1"]["demands_met"]
    # Each agent's team state: the team's shares, then its own load first.
    for agent in env.possible_agents:
        team = infos[agent]["team_state"]
        assert team.dtype == np.float32 and team.shape == (22,)
        assert team[0] == np.float32(infos[agent]["n_los"] / 20)
        assert team[1] == np.float32(infos[agent]["demands_met"] / 20)
        assert team[3] == np.float32(3 / 6)
        assert team[5] == np.float32(infos[agent]["ues_served"] / 20)
        assert list(team[4:13:3]) == [1.0, 1.0, 1.0] and not team[13:].any()
    assert sum(infos[a]["team_state"][5] for a in env.possible_agents) == pytest.approx(1.0)
    env.close()


def test_one_uav_flies_as_rlpos_make_does():
    single = rlpos.make(scenario_path("b"), fidelity="analytic", overrides=SHORT)
    team = make("b")
    first, _ = single.reset(seed=4, options={"random_start": True})
    observations, _ = team.reset(seed=4, options={"random_start": True})
    assert np.array_equal(observations["uav"], first)
    rng = np.random.default_rng(0)
    truncated = False
    while not truncated:
        action = int(rng.integers(7))
        observation, reward, _, truncated, info = single.step(action)
        observations, rewards, _, truncations, infos = team.step({"uav": action})
        assert np.array_equal(observations["uav"], observation)
        assert rewards["uav"] == reward and truncations["uav"] == truncated
        assert infos["uav"]["position"] == info["position"]
    single.close()
    team.close()


def flight(env, seed, options=None):
    """PettingZoo's parallel_seed_test: reset(seed), seeded action spaces, every step."""
    trajectory = [env.reset(seed=seed, options=options)]
    for u, agent in enumerate(env.agents):
        env.action_space(agent).seed(42 + u)
    while env.agents:
        trajectory.append(env.step(sample(env)))
        assert len(trajectory) <= env.steps_per_episode + 1, "agents outlived the episode"
    return trajectory


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_same_seed_gives_the_same_episode(name):
    one, two = make(name), make(name)
    options = {"random_start": True}
    first = flight(one, 42, options)
    assert same(flight(two, 42, options), first)
    assert same(flight(one, 42, options), first)
    assert not same(flight(one, 43, options), first)  # another start
    one.close()
    two.close()


def test_bad_actions_are_one_line_value_errors_and_change_nothing():
    env = make("urban3")
    env.reset(seed=1)
    before = env.state()
    ok = {"uav1": 0, "uav2": 0, "uav3": 0}
    bad = [
        ({"uav1": 0, "uav2": 0}, r"missing \['uav3'\]"),
        ({**ok, "uav9": 0}, r"unknown agents \['uav9'\]"),
        ({**ok, "uav2": 7}, r"actions\['uav2'\]: expected an integer in \[0, 7\)"),
        ({**ok, "uav2": -1}, r"actions\['uav2'\]"),
        ({**ok, "uav3": 1.0}, r"actions\['uav3'\]"),
        ({**ok, "uav3": True}, r"actions\['uav3'\]"),
        ([0, 0, 0], "expected a dict"),
    ]
    for actions, message in bad:
        with pytest.raises(ValueError, match=message) as error:
            env.step(actions)
        assert "\n" not in str(error.value)
    assert np.array_equal(env.state(), before)
    env.step({a: np.int64(0) for a in env.agents})  # numpy integers are actions
    continuous = make("urban3-continuous")
    continuous.reset(seed=1)
    still = {"uav1": [0, 0, 0], "uav2": [0, 0, 0], "uav3": [0, 0, 0]}
    for displacement in ([0, 0, 5.5], [0, 0], [np.nan, 0, 0], "up"):
        with pytest.raises(ValueError, match=r"actions\['uav2'\]: expected a displacement"):
            continuous.step({**still, "uav2": displacement})
    continuous.step(still)
    for options in ({"random_start": 1}, "random_start"):
        with pytest.raises(ValueError, match="options"):
            env.reset(options=options)
    with pytest.raises(ValueError, match="seed"):
        env.reset(seed=-1)
    env.close()
    continuous.close()


def test_stepping_an_ended_episode_or_a_closed_env_is_a_runtime_error():
    env = make("b")
    with pytest.raises(RuntimeError, match="call reset"):
        env.step({"uav": 0})  # no episode yet
    with pytest.raises(RuntimeError, match="reset"):
        env.state()
    flight(env, 1)
    with pytest.raises(RuntimeError, match="call reset"):
        env.step({"uav": 0})  # the episode ended
    env.reset()
    env.close()
    env.close()  # twice is allowed
    assert env.agents == []
    for call in (lambda: env.step({"uav": 0}), env.reset, env.state):
        with pytest.raises(RuntimeError, match="closed"):
            call()


def test_packet_level_parallel_envs_take_turns_with_ns3():
    first = rlpos.parallel_env(scenario_path("campus2"), fidelity="packet")
    with pytest.raises(RuntimeError, match="one per process"):
        rlpos.parallel_env(scenario_path("campus2"), fidelity="packet")
    first.close()
    rlpos.parallel_env(scenario_path("campus2"), fidelity="packet").close()


def test_pettingzoo_parallel_api_test():
    pettingzoo_test = pytest.importorskip("pettingzoo.test")
    import pettingzoo

    for name in sorted(CASES):
        env = make(name)
        assert isinstance(env, pettingzoo.ParallelEnv)
        pettingzoo_test.parallel_api_test(env, num_cycles=20)
        env.close()
        pettingzoo_test.parallel_seed_test(lambda: make(name), num_cycles=20)
