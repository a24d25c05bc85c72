"""VectorEnv: N analytic UAV positioning envs stepped together in C++, with Gymnasium's
VectorEnv API (next-step autoreset)."""
import os

import numpy as np

from . import _rlpos
from .env import override_texts, random_start_option
from .spaces import GYMNASIUM, Discrete, action_space_of, batch_space, float32_box, gymnasium

MAX_ENVS = 4096
_MAX_SEED = 2**63 - 1

if GYMNASIUM:
    AUTORESET_MODE = gymnasium.vector.AutoresetMode.NEXT_STEP
else:
    AUTORESET_MODE = "next_step"


def _is_int(x):
    return isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_))


def _seed(value, what):
    if not _is_int(value) or not 0 <= int(value) <= _MAX_SEED:
        raise ValueError("%s: expected an integer in [0, 2**63 - 1], got %r" % (what, value))
    return int(value)


class VectorEnv(gymnasium.vector.VectorEnv if GYMNASIUM else object):
    """N analytic envs of one scenario, or of a list (env i gets scenarios[i % len]), stepped
    together over a pool of threads without the GIL.

    reset(seed=s) resets env i with run s + i (a list: one seed or None per env); without a seed
    each env takes its next run (the first: make_vec's seed + i, or the scenario's
    agent.seed * 1000000 + 1 + i). Returns (observations [N, D] float32, infos).
    step(actions) with actions of action_space (N move indices, or N x 3 displacements) returns
    (observations, rewards float64, terminations bool, truncations bool, infos). Autoreset is
    Gymnasium's next-step mode: an env that ended at one step ignores its action at the next,
    resets (next run, no options) and returns the reset observation, reward 0, False, False.
    infos: arrays with one row per env, each with its "_key" mask (all True): position [N, 3]
    (the first UAV's), n_los, throughput_mbps, demands_met, action_mask [N, A] int8 (with
    env.action_mask), and with several UAVs positions [N, U, 3] and active_uav.
    """

    metadata = {"autoreset_mode": AUTORESET_MODE, "render_modes": []}
    render_mode = None
    spec = None
    closed = False

    def __init__(self, scenarios, num_envs=1, fidelity="analytic", seed=None, overrides=None,
                 threads=None):
        if not _is_int(num_envs) or not 1 <= num_envs <= MAX_ENVS:
            raise ValueError("num_envs: expected an integer from 1 to %d, got %r"
                             % (MAX_ENVS, num_envs))
        num_envs = int(num_envs)
        if fidelity == "packet":
            raise ValueError("fidelity: make_vec runs analytic envs only; packet-level envs are "
                             "one per process (ns-3's simulator is global): run one process per "
                             "env, each with rlpos.make(..., fidelity=\"packet\")")
        if fidelity not in (None, "analytic"):
            raise ValueError("fidelity: expected \"analytic\", got %r" % (fidelity,))
        if isinstance(scenarios, (str, bytes, os.PathLike)):
            scenarios = [scenarios]
        scenarios = list(scenarios)
        if not scenarios:
            raise ValueError("scenario: expected a scenario file or a non-empty list of them")
        if seed is not None:
            seed = _seed(seed, "seed")
            if seed > _MAX_SEED - (num_envs - 1):
                raise ValueError("seed: seed + num_envs - 1 must be at most 2**63 - 1, got %r"
                                 % (seed,))
        if threads is not None and (not _is_int(threads) or not 1 <= threads <= num_envs):
            raise ValueError("threads: expected None or an integer from 1 to num_envs (%d), "
                             "got %r" % (num_envs, threads))
        self._env = _rlpos.VectorEnv([os.fspath(s) for s in scenarios],
                                     override_texts(overrides, **{"env.fidelity": fidelity}),
                                     num_envs, seed, threads or 0)
        self.num_envs = num_envs
        self.single_action_space = action_space_of(self._env)
        self.single_observation_space = float32_box(self._env.observation_bounds)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        if seed is not None:
            self.single_action_space.seed(seed)
            self.action_space.seed(seed)

    @property
    def threads(self):
        """The threads that step the envs (the caller's included)."""
        return self._env.threads

    @property
    def scenario_names(self):
        """Each env's scenario name, by env index."""
        return list(self._env.scenario_names)

    @property
    def moves(self):
        """The names of the discrete actions, by index."""
        return list(self._env.actions)

    def reset(self, *, seed=None, options=None):
        random_start = random_start_option(options)
        n = self.num_envs
        if seed is None:
            seeds = []
        elif _is_int(seed):
            first = _seed(seed, "seed")
            if first > _MAX_SEED - (n - 1):
                raise ValueError("seed: seed + num_envs - 1 must be at most 2**63 - 1, got %r"
                                 % (seed,))
            seeds = [first + i for i in range(n)]
            if GYMNASIUM:
                super().reset(seed=first)  # seeds the vector env's np_random, as Gymnasium's
        else:
            if isinstance(seed, (str, bytes)) or not hasattr(seed, "__len__") or len(seed) != n:
                raise ValueError("seed: expected an integer, None, or a list of %d integers or "
                                 "None, got %r" % (n, seed))
            seeds = [None if s is None else _seed(s, "seed[%d]" % i) for i, s in enumerate(seed)]
        observations, fields = self._env.reset(seeds, random_start)
        return observations, self._infos(fields)

    def step(self, actions):
        a = np.asarray(actions)
        n = self.num_envs
        if isinstance(self.single_action_space, Discrete):
            shape, kinds, what = (n,), "iu", "integer move indices"
        else:
            shape, kinds, what = (n,) + tuple(self.single_action_space.shape), "iuf", "numbers"
        if a.dtype.kind not in kinds:
            raise ValueError("actions: expected %s, got dtype %s" % (what, a.dtype))
        if a.shape != shape:
            raise ValueError("actions: expected shape %s, got %s" % (shape, a.shape))
        if a.dtype.kind == "u" and a.dtype.itemsize == 8 and a.size and a.max() > _MAX_SEED:
            # C++ checks the range; uint64 values this large would wrap on their way (int64).
            i = int(np.argmax(a > _MAX_SEED))
            raise ValueError("actions[%d]: expected a move index in [0, %d), got %d"
                             % (i, self.single_action_space.n, a[i]))
        observations, rewards, terminations, truncations, fields = self._env.step(a)
        return observations, rewards, terminations, truncations, self._infos(fields)

    def close(self, **kwargs):
        """Stops the threads and frees the envs; closing twice is allowed."""
        if self.closed:
            return
        self._env.close()
        self.closed = True

    def _infos(self, fields):
        positions = fields.pop("positions")
        active = fields.pop("active_uav")
        infos = {"position": positions[:, 0, :].copy() if positions.shape[1] > 1
                 else positions.reshape(self.num_envs, 3)}
        if positions.shape[1] > 1:
            infos["positions"] = positions
            infos["active_uav"] = active
        infos.update(fields)
        masks = np.ones((len(infos), self.num_envs), np.bool_)  # one allocation, a row per key
        for key, mask in zip(list(infos), masks):
            infos["_" + key] = mask
        return infos

    def __repr__(self):
        return "rlpos.VectorEnv(%s, num_envs=%d)" % (", ".join(sorted(set(self.scenario_names)))
                                                    if not self.closed else "closed",
                                                    self.num_envs)
