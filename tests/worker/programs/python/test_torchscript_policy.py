"""rlpos.save_torchscript_policy: a policy trained in PyTorch, exported as a policy folder,
flies in `rlpos-sim position --positioner rl` exactly as its greedy rollout in Python does."""
import json
import os
import subprocess

import numpy as np
import pytest
import torch
from torch import nn

import rlpos
from conftest import BIN, closed_after

SHORT = {"env.episode_duration": 5}  # 50 steps of 0.1 s


class Policy(nn.Module):
    """Logits of B's moves from the env's own observation (normalised inside the module)."""

    def __init__(self, low, high, moves):
        super().__init__()
        self.register_buffer("low", torch.as_tensor(low))
        self.register_buffer("span", torch.as_tensor(high - low))
        self.net = nn.Sequential(nn.Linear(len(low), 16), nn.Tanh(), nn.Linear(16, moves))

    def forward(self, x):
        return self.net(2 * (x - self.low) / self.span - 1)


def masked_logits(policy, observation, info):
    logits = policy(torch.as_tensor(observation)[None])[0]
    return torch.where(torch.as_tensor(info["action_mask"]) > 0, logits,
                       torch.tensor(float("-inf")))


def train(env, policy, episodes):
    """REINFORCE, `episodes` x 50 steps: enough to be a policy of its own, not a good one."""
    optimizer = torch.optim.Adam(policy.parameters(), lr=0.02)
    for _ in range(episodes):
        observation, info = env.reset()
        log_probs, rewards, done = [], [], False
        while not done:
            dist = torch.distributions.Categorical(logits=masked_logits(policy, observation, info))
            action = dist.sample()
            log_probs.append(dist.log_prob(action))
            observation, reward, terminated, truncated, info = env.step(int(action))
            rewards.append(reward)
            done = terminated or truncated
        returns = torch.tensor(np.cumsum(rewards[::-1])[::-1].copy(), dtype=torch.float32)
        loss = -(torch.stack(log_probs) * (returns - returns.mean())).sum()
        optimizer.zero_grad()
        loss.backward()
        optimizer.step()


def greedy_flight(env, policy, run):
    observation, info = env.reset(seed=run)
    path, done = [info["position"]], False
    with torch.no_grad():
        while not done:
            action = int(torch.argmax(masked_logits(policy, observation, info)))
            observation, _, terminated, truncated, info = env.step(action)
            path.append(info["position"])
            done = terminated or truncated
    return path


def position(scenario, policy_dir):
    done = subprocess.run([os.path.join(BIN, "rlpos-sim"), "position", "--scenario", scenario,
                           "--positioner", "rl", "--policy", str(policy_dir), "--json"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return tuple(json.loads(done.stdout)["position"])


@pytest.fixture
def env(scenario_b):
    yield from closed_after(rlpos.make(scenario_b, fidelity="analytic", seed=11, overrides=SHORT))


def policy_for(env):
    torch.manual_seed(3)
    low, high = env.observation_space.low, env.observation_space.high
    return Policy(low, high, env.action_space.n)


def test_position_flies_the_moves_of_the_python_greedy_rollout(env, scenario_b, tmp_path):
    policy = policy_for(env)
    train(env, policy, episodes=6)
    manifest = rlpos.save_torchscript_policy(policy, env, tmp_path / "policy", eval_run=7)
    assert manifest["eval_run"] == 7
    path = greedy_flight(env, policy, run=7)
    assert len(set(path)) > 1, path  # it moves: the comparison below is about moves
    assert position(scenario_b, tmp_path / "policy") == path[-1]


def test_the_folder_holds_the_envs_scenario_and_spaces(env, tmp_path):
    manifest = rlpos.save_torchscript_policy(policy_for(env), env, tmp_path / "policy")
    folder = tmp_path / "policy"
    assert sorted(os.listdir(folder)) == ["model.pt", "policy.json", "scenario.json"]
    assert json.loads((folder / "policy.json").read_text()) == manifest == {
        "format": "torchscript", "format_version": 1, "action_space": "discrete",
        "observation_dim": 4, "action_count": 7, "eval_run": 1}  # B's simulation.run
    scenario = json.loads((folder / "scenario.json").read_text())
    assert scenario == env.scenario
    assert scenario["env"]["fidelity"] == "analytic" and scenario["env"]["episode_duration"] == 5
    assert [p for p in os.listdir(tmp_path)] == ["policy"]  # nothing partial left beside it


def test_a_module_that_does_not_fit_the_env_is_refused_and_nothing_written(env, tmp_path):
    wide = nn.Linear(4, 8)
    with pytest.raises(ValueError, match=r"returns \(1, 8\), expected \[1, 7\] float logits"):
        rlpos.save_torchscript_policy(wide, env, tmp_path / "policy")
    assert os.listdir(tmp_path) == []
    rlpos.save_torchscript_policy(policy_for(env), env, tmp_path / "policy")
    with pytest.raises(FileExistsError, match="already exists"):
        rlpos.save_torchscript_policy(policy_for(env), env, tmp_path / "policy")
    with pytest.raises(ValueError, match="eval_run"):
        rlpos.save_torchscript_policy(policy_for(env), env, tmp_path / "other", eval_run=0)


def test_a_continuous_env_is_refused(scenario_b, tmp_path):
    env = rlpos.make(scenario_b, fidelity="analytic", overrides={
        "env.action_space": "continuous", "agent.algorithm": "sac"})
    try:
        with pytest.raises(ValueError, match="discrete actions"):
            rlpos.save_torchscript_policy(nn.Linear(4, 3), env, tmp_path / "policy")
    finally:
        env.close()


class Unscriptable(nn.Module):
    """A forward TorchScript cannot compile (a Python callable attribute): it is traced."""

    def __init__(self, inner):
        super().__init__()
        self.inner = inner
        self.shift = lambda x: x - 1.0

    def forward(self, x):
        return self.inner(self.shift(x))


def test_a_module_that_does_not_script_is_traced(env, tmp_path):
    module = Unscriptable(policy_for(env))
    with pytest.raises(Exception):
        torch.jit.script(module)
    rlpos.save_torchscript_policy(module, env, tmp_path / "policy")
    loaded = torch.jit.load(str(tmp_path / "policy" / "model.pt"))
    x = torch.rand(3, 4) * 50
    with torch.no_grad():
        assert torch.equal(loaded(x), module(x))
