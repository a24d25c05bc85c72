#!/usr/bin/env python3
"""A short PPO in PyTorch on the rlpos env (analytic fidelity), in the single-file style of
CleanRL: 10 episodes of 1,000 steps on scenario B, then the greedy flight's final position
against the oracle's. With --export DIR, the policy is also written as a TorchScript policy
folder, and rlpos-sim flies it (position --positioner rl --policy DIR) to the same place.

  build/bin/rlpos-python scripts/examples/ppo_torch.py [--scenario FILE] [--seed N]
      [--export DIR]
"""
import argparse
import json
import os
import subprocess
import time

try:
    import numpy as np
    import rlpos
    import torch
    from torch import nn
except ImportError as error:  # a python3 other than the binding's (pyenv, conda) comes first
    raise SystemExit(f"{error}: run this with build/bin/rlpos-python, the Python rlpos is built for")

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = os.path.join(HERE, "..", "..", "campaigns", "scenarios", "b.json")


def mlp(inputs, outputs):
    return nn.Sequential(nn.Linear(inputs, 32), nn.ReLU(), nn.Linear(32, 32), nn.ReLU(),
                         nn.Linear(32, outputs))


class Exported(nn.Module):
    """The actor on the env's own observations, as a TorchScript policy folder takes them: the
    scaling onto [-1, 1] moves inside the module; the action mask stays rlpos-sim's."""

    def __init__(self, actor, low, high):
        super().__init__()
        self.actor = actor
        self.register_buffer("low", torch.as_tensor(low))
        self.register_buffer("high", torch.as_tensor(high))

    def forward(self, x):
        return self.actor(2 * (x - self.low) / (self.high - self.low) - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=DEFAULT_SCENARIO)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--episodes", type=int, default=10)
    parser.add_argument("--export", metavar="DIR",
                        help="write the policy as a TorchScript policy folder and fly it with "
                             "rlpos-sim")
    parser.add_argument("--rlpos-sim", default=os.path.join(HERE, "..", "..", "build", "bin",
                                                            "rlpos-sim"))
    args = parser.parse_args()
    torch.manual_seed(args.seed)
    rng = np.random.default_rng(args.seed)
    # Hyperparameters: rlpos's own PPO defaults (docs/agents.md, PPO and SAC).
    lr, gamma, lam, clip, ent_coef, vf_coef = 1e-3, 0.9, 0.95, 0.2, 0.01, 0.5
    rollout, epochs, minibatches = 256, 10, 4

    # The oracle's best analytic placement, the target the policy is scored against.
    best = rlpos.oracle(args.scenario, overrides={"env.fidelity": "analytic"},
                        packet_candidates=0, top=1)[0]
    env = rlpos.make(args.scenario, fidelity="analytic", seed=args.seed * 1000 + 1)
    low, high = env.observation_space.low, env.observation_space.high
    scale = lambda o: torch.as_tensor(2 * (o - low) / (high - low) - 1)  # noqa: E731
    n = env.action_space.n
    actor, critic = mlp(len(low), n), mlp(len(low), 1)
    optimizer = torch.optim.Adam(list(actor.parameters()) + list(critic.parameters()), lr=lr,
                                 eps=1e-5)

    all_moves = np.ones(n, np.int8)
    mask_of = lambda info: torch.as_tensor(info.get("action_mask", all_moves))  # noqa: E731

    def logits_of(obs, mask):
        return actor(obs) + torch.where(mask > 0, 0.0, -1e9)

    started = time.monotonic()
    buffer, returns_seen = [], []
    for episode in range(args.episodes):
        obs, info = env.reset()
        obs, mask, done, total = scale(obs), mask_of(info), False, 0.0
        while not done:
            with torch.no_grad():
                probs = torch.softmax(logits_of(obs, mask), -1).numpy().astype(np.float64)
            action = int(rng.choice(n, p=probs / probs.sum()))
            next_obs, reward, terminated, truncated, info = env.step(action)
            done, total = terminated or truncated, total + reward
            returns_seen.append(reward)
            buffer.append((obs, mask, action, np.log(probs[action]), reward, scale(next_obs),
                           terminated, done))
            obs, mask = scale(next_obs), mask_of(info)
            if len(buffer) == rollout:
                learn(buffer, actor, critic, optimizer, logits_of, np.mean(returns_seen),
                      np.std(returns_seen) + 1e-8, gamma, lam, clip, ent_coef, vf_coef, epochs,
                      minibatches, rng)
                buffer = []
        print("episode %d: mean reward %.3f, final %s" % (episode + 1, total / env.steps_per_episode,
                                                          info["position"]))
    train_s = time.monotonic() - started

    # The greedy flight, on the run a policy folder's replay flies (the scenario's).
    run = env.scenario["simulation"]["run"]
    obs, info = env.reset(seed=run)
    done = False
    while not done:
        with torch.no_grad():
            action = int(torch.argmax(logits_of(scale(obs), mask_of(info))))
        obs, reward, terminated, truncated, info = env.step(action)
        done = terminated or truncated
    if args.export:
        rlpos.save_torchscript_policy(Exported(actor, low, high), env, args.export, eval_run=run)
    env.close()
    print("greedy final position %s: reward %.4f, oracle %s: %.4f (%.1f %%); trained in %.1f s"
          % (info["position"], reward, best["position"], best["analytic_reward"],
             100 * reward / best["analytic_reward"], train_s))
    if args.export:
        placed = json.loads(subprocess.run(
            [args.rlpos_sim, "position", "--scenario", args.scenario, "--positioner", "rl",
             "--policy", args.export, "--json"], check=True, capture_output=True,
            text=True).stdout)
        print("rlpos-sim position --policy %s: %s, reward %.4f" % (
            args.export, tuple(placed["position"]), placed["reward"]))


def learn(buffer, actor, critic, optimizer, logits_of, mean, std, gamma, lam, clip, ent_coef,
          vf_coef, epochs, minibatches, rng):
    obs = torch.stack([b[0] for b in buffer])
    masks = torch.stack([b[1] for b in buffer])
    actions = torch.tensor([b[2] for b in buffer])
    old_log_probs = torch.tensor([b[3] for b in buffer], dtype=torch.float32)
    rewards = [(b[4] - mean) / std for b in buffer]
    with torch.no_grad():
        values = critic(obs).squeeze(1)
        next_values = critic(torch.stack([b[5] for b in buffer])).squeeze(1)
    advantages, carried = torch.zeros(len(buffer)), 0.0
    for t in reversed(range(len(buffer))):  # GAE; a truncated episode bootstraps from V
        bootstrap = 0.0 if buffer[t][6] else gamma * float(next_values[t])
        delta = rewards[t] + bootstrap - float(values[t])
        carried = delta + (0.0 if buffer[t][7] or t == len(buffer) - 1 else gamma * lam * carried)
        advantages[t] = carried
    returns = advantages + values
    size = len(buffer) // minibatches
    for _ in range(epochs):
        order = rng.permutation(len(buffer))
        for start in range(0, len(buffer) - size + 1, size):
            i = torch.as_tensor(order[start:start + size])
            log_p = torch.log_softmax(logits_of(obs[i], masks[i]), -1)
            ratio = torch.exp(log_p.gather(1, actions[i, None]).squeeze(1) - old_log_probs[i])
            adv = (advantages[i] - advantages[i].mean()) / (advantages[i].std() + 1e-8)
            policy_loss = torch.max(-adv * ratio, -adv * ratio.clamp(1 - clip, 1 + clip)).mean()
            entropy = -(log_p.exp() * log_p).sum(1).mean()
            value_loss = 0.5 * (critic(obs[i]).squeeze(1) - returns[i]).pow(2).mean()
            loss = policy_loss - ent_coef * entropy + vf_coef * value_loss
            optimizer.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(list(actor.parameters()) + list(critic.parameters()), 0.5)
            optimizer.step()


if __name__ == "__main__":
    main()
