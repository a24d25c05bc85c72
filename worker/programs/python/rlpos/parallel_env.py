"""ParallelUavEnv: every UAV of a scenario as an agent, with PettingZoo's ParallelEnv API,
in-process (the env of rlpos.make, stepped with one action per UAV at once)."""
import os

import numpy as np

from . import _rlpos
from .env import (_MAX_SEED, WrappedEnvProperties, _check_seed, check_env_arguments,
                  override_texts)
from .spaces import action_space_of, float32_box

try:
    import pettingzoo

    PETTINGZOO = True
except ImportError:  # everything works the same without it
    pettingzoo = None
    PETTINGZOO = False


class ParallelUavEnv(WrappedEnvProperties, pettingzoo.ParallelEnv if PETTINGZOO else object):
    """The UAVs of a scenario as agents that all move at once in each step, one decision
    interval per step (packet fidelity: ns-3 runs it; analytic: the analytic model).

    possible_agents: the UAVs' names, in the scenario's order; agents: the live ones (empty
    before the first reset and once the episode ends).
    observation_space(agent): the scenario's env.observations with that UAV as the active one
    (with several UAVs a one-hot of the UAV itself closes it), float32. action_space(agent):
    Discrete(len(env.actions)), or with env.action_space "continuous" a Box displacement in
    [-env.step, env.step]^3 m. Both return the same object at every call.
    Conflicts: each UAV's move is resolved alone (its zone, buildings), then a UAV that would
    end closer than 1 m to another's end point is refused and stays, the highest index first,
    until none does (a lower index has priority).
    Rewards: the env's reward, the same for every agent (a team). Episodes end truncated for
    every agent after env.episode_duration; none terminates.
    state(): the global state for a centralised critic (state_space: x, y, z of each UAV; per
    UE its LoS to its UAV, the SNR to it, the serving UAV's index; the throughput; the demands
    met), float32.
    infos[agent]: position, ues_served, n_los, throughput_mbps, demands_met and, with
    env.action_mask, action_mask (int8, 1: the move changes the UAV's position with the others
    where they are).
    reset(seed=s) starts the episode with RngRun s; without a seed, the next run (the first:
    `seed`, or agent.seed * 1000000 + 1). reset(options={"random_start": True}) starts every UAV
    at a point of its zone drawn from the run; other option keys are ignored.
    """

    metadata = {"name": "rlpos_uav_positioning_v0", "render_modes": [], "is_parallelizable": True}

    def __init__(self, scenario, fidelity=None, seed=None, overrides=None, render_mode=None):
        check_env_arguments(fidelity, render_mode)
        self.render_mode = None
        self._env = _rlpos.ParallelEnv(os.fspath(scenario),
                                       override_texts(overrides, **{"env.fidelity": fidelity}))
        self.possible_agents = list(self._env.agent_names)
        self.agents = []
        self._index = {agent: u for u, agent in enumerate(self.possible_agents)}
        # A space of its own for each agent: each samples from its own seed.
        self.observation_spaces = {agent: float32_box(self._env.observation_bounds)
                                   for agent in self.possible_agents}
        self.action_spaces = {agent: action_space_of(self._env) for agent in self.possible_agents}
        self.state_space = float32_box(self._env.state_bounds)
        self._state = None
        if seed is None:
            self._next_run = self._env.agent_seed * 1000000 + 1
        else:
            self._next_run = _check_seed(seed, "seed")
            for u, agent in enumerate(self.possible_agents):
                self.action_spaces[agent].seed((self._next_run + u) % (_MAX_SEED + 1))

    @property
    def num_agents(self):
        return len(self.agents)

    @property
    def max_num_agents(self):
        return len(self.possible_agents)

    @property
    def unwrapped(self):
        return self

    def observation_space(self, agent):
        return self.observation_spaces[self._known(agent)]

    def action_space(self, agent):
        return self.action_spaces[self._known(agent)]

    def reset(self, seed=None, options=None):
        random_start = False
        if options:
            if not isinstance(options, dict) \
                    or not isinstance(options.get("random_start", False), bool):
                raise ValueError("options: expected {\"random_start\": bool}, got %r" % (options,))
            random_start = options.get("random_start", False)
        if seed is not None:
            self._next_run = _check_seed(seed, "seed")
        run = self._next_run
        observations, state, info = self._env.reset(run, random_start)
        self._next_run = run + 1 if run < _MAX_SEED else 0
        self.agents = list(self.possible_agents)
        self._state = state
        return self._observations(observations), self._infos(info)

    def step(self, actions):
        if self._env.closed:
            raise RuntimeError("rlpos: the parallel env is closed")
        if not self.agents:
            raise RuntimeError("rlpos: no episode is running (it ended, or none started); "
                               "call reset() first")
        if not isinstance(actions, dict):
            raise ValueError("actions: expected a dict {agent: action}, got %s"
                             % type(actions).__name__)
        unknown = [a for a in actions if a not in self._index]
        missing = [a for a in self.agents if a not in actions]
        if unknown or missing:
            raise ValueError("actions: expected one action for each of %s; %s" % (
                self.agents, "unknown agents %r" % unknown if unknown else "missing %r" % missing))
        if self._env.action_count > 0:
            result = self._env.step([self._discrete(a, actions[a]) for a in self.agents])
        else:
            result = self._env.step_continuous([self._displacement(a, actions[a])
                                                for a in self.agents])
        observations, state, reward, terminated, truncated, info = result
        self._state = state
        agents = self.agents
        if terminated or truncated:
            self.agents = []
        return (self._observations(observations), {a: float(reward) for a in agents},
                {a: bool(terminated) for a in agents}, {a: bool(truncated) for a in agents},
                self._infos(info))

    def state(self):
        if self._env.closed:
            raise RuntimeError("rlpos: the parallel env is closed")
        if self._state is None:
            raise RuntimeError("rlpos: no state before the first reset(); call reset() first")
        return np.clip(np.asarray(self._state, np.float32), self.state_space.low,
                       self.state_space.high)

    def render(self):
        """Renders nothing (render_mode is None)."""
        return None

    def close(self):
        """Gives ns-3 back (packet fidelity): another env, oracle or evaluation may then start."""
        self._env.close()
        self.agents = []

    def _known(self, agent):
        if agent not in self._index:
            raise ValueError("agent: %r is not one of %s" % (agent, self.possible_agents))
        return agent

    def _discrete(self, agent, action):
        n = self._env.action_count
        if isinstance(action, np.ndarray) and action.shape == ():
            action = action.item()
        if isinstance(action, (bool, np.bool_)) or not isinstance(action, (int, np.integer)) \
                or not 0 <= int(action) < n:
            raise ValueError("actions[%r]: expected an integer in [0, %d), got %r"
                             % (agent, n, action))
        return int(action)

    def _displacement(self, agent, action):
        space = self.action_spaces[agent]
        try:
            d = np.asarray(action, dtype=np.float64)
        except (TypeError, ValueError):
            d = np.full(0, np.nan)
        if d.shape != (3,) or not np.all(np.isfinite(d)) \
                or np.any(d < space.low) or np.any(d > space.high):
            raise ValueError("actions[%r]: expected a displacement (dx, dy, dz) within [%g, %g] m,"
                             " got %r" % (agent, space.low[0], space.high[0], action))
        return d.tolist()

    def _observations(self, values):
        space = self.observation_spaces[self.possible_agents[0]]
        return {agent: np.clip(np.asarray(values[u], np.float32), space.low, space.high)
                for u, agent in enumerate(self.possible_agents)}

    def _infos(self, info):
        masks = info.get("action_masks")
        infos = {}
        for u, agent in enumerate(self.possible_agents):
            agent_info = {
                "position": tuple(info["positions"][u]),
                "ues_served": sum(1 for s in info["serving_uav"] if s == u),
                "n_los": info["n_los"],
                "throughput_mbps": info["throughput_mbps"],
                "demands_met": info["demands_met"],
            }
            if masks is not None:
                agent_info["action_mask"] = np.asarray(masks[u], np.int8)
            # What a centralised critic sees beside the agent's observation, the same layout in
            # every scenario (worker/env/gym/team_state.h).
            agent_info["team_state"] = np.asarray(info["team_states"][u], np.float32)
            infos[agent] = agent_info
        return infos
