"""rlpos: obstacle-aware UAV positioning on ns-3, for Python RL code.

    import rlpos
    env = rlpos.make("campaigns/scenarios/b.json", fidelity="analytic", seed=1,
                     overrides={"env.step": 5})
    observation, info = env.reset(seed=1)
    observation, reward, terminated, truncated, info = env.step(env.action_space.sample())

    envs = rlpos.make_vec("campaigns/scenarios/b.json", num_envs=64, seed=1)
    observations, infos = envs.reset()
    observations, rewards, terminations, truncations, infos = envs.step(envs.action_space.sample())

    team = rlpos.parallel_env("campaigns/scenarios/urban3.json", fidelity="analytic", seed=1)
    observations, infos = team.reset(seed=1)          # every UAV an agent (PettingZoo's API)
    actions = {agent: team.action_space(agent).sample() for agent in team.agents}
    observations, rewards, terminations, truncations, infos = team.step(actions)

    rlpos.save_torchscript_policy(torch_module, env, "my-policy")   # then, in a shell:
    # rlpos-sim position --positioner rl --policy my-policy --scenario campaigns/scenarios/b.json

With gymnasium importable the env is a gymnasium.Env, registered as "rlpos/UavPositioning-v0",
and make_vec's a gymnasium.vector.VectorEnv; with pettingzoo importable the parallel env is a
pettingzoo.ParallelEnv.
Any number of analytic envs at once. One packet-level user (env, evaluation, or oracle search with
packet-level candidates) at a time per process: ns-3's simulator is global.
"""
import json

from . import _rlpos
from .env import UavPositioningEnv, override_texts
from .parallel_env import ParallelUavEnv
from .spaces import GYMNASIUM, Box, Discrete, MultiDiscrete
from .torchscript_policy import save_torchscript_policy
from .vector_env import VectorEnv

__all__ = ["make", "make_vec", "parallel_env", "oracle", "evaluate", "save_torchscript_policy",
           "UavPositioningEnv",
           "VectorEnv", "ParallelUavEnv", "Discrete", "Box", "MultiDiscrete", "ENV_ID"]

ENV_ID = "rlpos/UavPositioning-v0"


def make(scenario, fidelity=None, seed=None, overrides=None):
    """The env of a scenario file; `overrides` are --set's, as {"path": value}."""
    return UavPositioningEnv(scenario, fidelity=fidelity, seed=seed, overrides=overrides)


def make_vec(scenario_or_list, num_envs=1, fidelity="analytic", seed=None, overrides=None,
             threads=None):
    """`num_envs` analytic envs stepped together in C++ (a gymnasium.vector.VectorEnv with
    gymnasium importable); a list of scenario files: env i gets list[i % len(list)], and all must
    share their spaces. `threads`: the stepping threads (None: min(cores, num_envs))."""
    return VectorEnv(scenario_or_list, num_envs=num_envs, fidelity=fidelity, seed=seed,
                     overrides=overrides, threads=threads)


def parallel_env(scenario, fidelity=None, seed=None, overrides=None):
    """Every UAV of the scenario as an agent, all moving at once in each step, with PettingZoo's
    ParallelEnv API (a pettingzoo.ParallelEnv where pettingzoo is importable); `overrides` are
    --set's, as {"path": value}. See ParallelUavEnv."""
    return ParallelUavEnv(scenario, fidelity=fidelity, seed=seed, overrides=overrides)


def oracle(scenario, overrides=None, grid_step=None, packet_candidates=3, packet_duration=2.0,
           top=10):
    """The oracle positioner: every point of the zone grid (the env's move step, 1 m for
    continuous actions, or `grid_step`) scored with the analytic model, the best
    `packet_candidates` re-scored at packet level over `packet_duration` s. Returns the best
    `top` (None: all) as dicts, best first: position, analytic_reward, packet_reward (None
    where not re-scored), n_los, throughput_mbps."""
    if top is not None and (not isinstance(top, int) or top < 1):
        raise ValueError("top: expected a positive integer or None, got %r" % (top,))
    return _rlpos.oracle(str(scenario), override_texts(overrides), float(grid_step or 0.0),
                         int(packet_candidates), float(packet_duration), top or 0)


def evaluate(scenario, position, run=1, duration=None, overrides=None):
    """Packet-level evaluation of a UAV position (rlpos-sim eval): a dict with the aggregate
    and per-UE throughput, delay and loss, nLoS, ... of RngRun `run` over the scenario's
    simulation.duration, or `duration` s. `position` is (x, y, z), or one (x, y, z) per UAV
    for a scenario of several UAVs (then the dict has "uavs", the metrics per UAV)."""
    texts = override_texts(overrides, **{"simulation.run": run, "simulation.duration": duration})
    placement = list(position)
    if placement and not hasattr(placement[0], "__len__"):
        placement = [placement]
    placement = [[float(v) for v in p] for p in placement]
    return json.loads(_rlpos.evaluate(str(scenario), texts, placement))


if GYMNASIUM:
    import gymnasium

    if ENV_ID not in gymnasium.envs.registry:
        gymnasium.register(id=ENV_ID, entry_point="rlpos.env:UavPositioningEnv")
