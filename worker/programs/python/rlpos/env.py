"""UavPositioningEnv: the obstacle-aware UAV positioning env with Gymnasium's API, in-process."""
import json
import os

import numpy as np

from . import _rlpos
from .spaces import GYMNASIUM, Discrete, action_space_of, float32_box, gymnasium

_MAX_SEED = 2**63 - 1


def override_texts(overrides, **settings):
    """{"env.step": 5} -> ["env.step=5"], as rlpos-sim --set takes them (values as JSON)."""
    texts = []
    for path, value in (overrides or {}).items():
        if not isinstance(path, str) or not path:
            raise ValueError("overrides: keys are scenario paths such as \"env.step\", got %r"
                             % (path,))
        texts.append(path + "=" + json.dumps(value))
    for path, value in settings.items():
        if value is not None:
            texts.append(path + "=" + json.dumps(value))
    return texts


def check_env_arguments(fidelity, render_mode):
    """What the single and the parallel env take besides the scenario, checked alike."""
    if render_mode is not None:
        raise ValueError("render_mode: the env renders nothing; leave it None")
    if fidelity not in (None, "analytic", "packet"):
        raise ValueError("fidelity: expected \"analytic\" or \"packet\", got %r" % (fidelity,))


def random_start_option(options):
    """reset's options, {"random_start": bool} or none: whether the UAVs start at random."""
    if not options:
        return False
    unknown = sorted(set(options) - {"random_start"})
    if unknown or not isinstance(options.get("random_start", False), bool):
        raise ValueError("options: expected {\"random_start\": bool}, got %r" % (options,))
    return options.get("random_start", False)


def _check_seed(seed, what):
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)) \
            or not 0 <= int(seed) <= _MAX_SEED:
        raise ValueError("%s: expected an integer in [0, 2**63 - 1], got %r" % (what, seed))
    return int(seed)


class WrappedEnvProperties:
    """What the single env and the parallel env both tell of the C++ env they wrap (`_env`)."""

    @property
    def fidelity(self):
        return self._env.fidelity

    @property
    def steps_per_episode(self):
        return self._env.steps_per_episode

    @property
    def scenario(self):
        """The env's scenario as loaded (file, overrides, defaults), every field explicit, as a
        dict: what rlpos-sim train writes as a policy folder's scenario.json."""
        return json.loads(self._env.scenario_json)

    @property
    def moves(self):
        """The names of the discrete actions, by index."""
        return list(self._env.actions)


class UavPositioningEnv(WrappedEnvProperties, gymnasium.Env if GYMNASIUM else object):
    """One UAV above the UEs of a scenario; each step moves it and measures one decision
    interval (packet fidelity: ns-3 runs it; analytic: the model of rlpos-sim's analytic
    fidelity).

    Observations: the scenario's env.observations (x, y, z, n_los by default), float32.
    Actions: Discrete(len(env.actions)) moves, or with env.action_space "continuous" a Box
    displacement (dx, dy, dz) in [-env.step, env.step] metres.
    Episodes end truncated after env.episode_duration; none terminates.
    reset(seed=s) starts the episode with RngRun s; a reset without a seed takes the next run
    (the first: `seed`, or the scenario's agent.seed * 1000000 + 1 as rlpos-sim train does).
    reset(options={"random_start": True}) starts every UAV at a point of its zone drawn from the
    run (exploring starts, as agent.exploring_starts trains); without it, at the baseline.
    info: position, n_los, throughput_mbps, demands_met, snr_db and, with env.action_mask, an
    action_mask (1: the move changes the position).
    """

    metadata = {"render_modes": []}

    def __init__(self, scenario, fidelity=None, seed=None, overrides=None, render_mode=None):
        check_env_arguments(fidelity, render_mode)
        self.render_mode = None
        self._env = _rlpos.Env(os.fspath(scenario),
                               override_texts(overrides, **{"env.fidelity": fidelity}))
        self.action_space = action_space_of(self._env)
        self.observation_space = float32_box(self._env.observation_bounds)
        # The C++ side returns the observation as a float32 array clipped to this space and the
        # info dict as it is handed out; a plain int action in range goes straight to it.
        self._discrete_n = self._env.action_count
        if seed is None:
            self._next_run = self._env.agent_seed * 1000000 + 1
        else:
            self._next_run = _check_seed(seed, "seed")
            self.action_space.seed(self._next_run)

    def reset(self, *, seed=None, options=None):
        if GYMNASIUM:
            super().reset(seed=seed)
        random_start = random_start_option(options)
        if seed is not None:
            self._next_run = _check_seed(seed, "seed")
        run = self._next_run
        self._next_run = run + 1 if run < _MAX_SEED else 0
        return self._env.reset(run, random_start)

    def step(self, action):
        if type(action) is int and 0 <= action < self._discrete_n:
            return self._env.step(action)
        if isinstance(self.action_space, Discrete):
            n = self.action_space.n
            if isinstance(action, np.ndarray) and action.shape == ():
                action = action.item()
            if isinstance(action, (bool, np.bool_)) or not isinstance(action, (int, np.integer)) \
                    or not 0 <= int(action) < n:
                raise ValueError("action: expected an integer in [0, %d), got %r" % (n, action))
            return self._env.step(int(action))
        else:
            try:
                d = np.asarray(action, dtype=np.float64)
            except (TypeError, ValueError):
                d = np.full(0, np.nan)
            if d.shape != (3,) or not np.all(np.isfinite(d)) \
                    or np.any(d < self.action_space.low) or np.any(d > self.action_space.high):
                raise ValueError("action: expected a displacement (dx, dy, dz) within [%g, %g] m, "
                                 "got %r" % (self.action_space.low[0], self.action_space.high[0],
                                             action))
            return self._env.step_continuous(d.tolist())

    def close(self):
        """Gives ns-3 back: another env, oracle or evaluation may then start."""
        self._env.close()
