"""Policies trained in PyTorch, exported as a policy folder that `rlpos-sim position --positioner
rl --policy DIR` flies (docs/positioners.md, "TorchScript policy folders")."""
import json
import math
import os
import shutil
import tempfile

import numpy as np

from .spaces import Discrete

FORMAT = "torchscript"
FORMAT_VERSION = 1
_MAX_RUN = 2**63 - 1


def save_torchscript_policy(module, env, directory, eval_run=None):
    """Writes `directory` (which must not exist) as a TorchScript policy folder for `env`:
    model.pt (`module` scripted, or traced on a zero observation where it does not script),
    policy.json (the manifest) and scenario.json (the env's own scenario, every field explicit).

    `module`: a torch.nn.Module whose forward takes float32 observations [B, D] exactly as `env`
    gives them (clipped to the observation space, not normalised) and returns logits [B, A] for
    the A discrete moves; the greedy move is the argmax among those the action mask allows.
    `env`: an rlpos.make env with discrete actions (continuous ones are not supported).
    `eval_run`: the RngRun of the greedy flight `position` makes (None: the scenario's
    simulation.run); a Python rollout from env.reset(seed=eval_run) flies the same moves.
    Returns the manifest as a dict."""
    import torch

    if not isinstance(env.action_space, Discrete):
        raise ValueError("env: a TorchScript policy folder (format_version 1) takes discrete "
                         "actions; this env's are continuous")
    scenario = env.scenario
    if eval_run is None:
        eval_run = scenario["simulation"]["run"]
    if isinstance(eval_run, (bool, np.bool_)) or not isinstance(eval_run, (int, np.integer)) \
            or not 1 <= int(eval_run) <= _MAX_RUN:
        raise ValueError("eval_run: expected an integer in [1, 2**63 - 1], got %r" % (eval_run,))
    directory = os.fspath(directory)
    if os.path.lexists(directory):
        raise FileExistsError("%s: already exists; a policy folder is written whole, into a "
                              "new directory" % directory)
    dim, count = int(env.observation_space.shape[0]), int(env.action_space.n)
    scripted = _script(module, dim)
    _check_logits(scripted, dim, count)
    manifest = {"format": FORMAT, "format_version": FORMAT_VERSION, "action_space": "discrete",
                "observation_dim": dim, "action_count": count, "eval_run": int(eval_run)}
    # Written beside the target and renamed into place: no half-written folder is ever seen.
    parent = os.path.dirname(os.path.abspath(directory))
    partial = tempfile.mkdtemp(prefix=".partial-", dir=parent)
    try:
        scripted.save(os.path.join(partial, "model.pt"))
        with open(os.path.join(partial, "policy.json"), "w") as f:
            json.dump(manifest, f, indent=2)
            f.write("\n")
        with open(os.path.join(partial, "scenario.json"), "w") as f:
            json.dump(scenario, f, indent=2)
            f.write("\n")
        os.rename(partial, directory)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise
    return manifest


def _script(module, dim):
    import torch

    if isinstance(module, torch.jit.ScriptModule):
        return module
    was_training = module.training
    module.eval()
    try:
        try:
            return torch.jit.script(module)
        except Exception:  # Python TorchScript cannot compile: record one forward instead
            with torch.no_grad():
                return torch.jit.trace(module, torch.zeros(1, dim, dtype=torch.float32))
    finally:
        module.train(was_training)


def _check_logits(scripted, dim, count):
    """What `position` checks before flying, checked here first: [1, A] finite float logits."""
    import torch

    with torch.no_grad():
        out = scripted(torch.zeros(1, dim, dtype=torch.float32))
    if not isinstance(out, torch.Tensor) or not out.is_floating_point() \
            or tuple(out.shape) != (1, count):
        shape = tuple(out.shape) if isinstance(out, torch.Tensor) else type(out).__name__
        raise ValueError("module: forward on float32 [1, %d] returns %s, expected [1, %d] float "
                         "logits" % (dim, shape, count))
    if any(math.isnan(v) for v in out.flatten().tolist()):
        raise ValueError("module: forward on a zero observation returns NaN logits")
