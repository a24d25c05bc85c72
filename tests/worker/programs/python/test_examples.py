"""The examples in scripts/examples run and do what they say."""
import os
import re
import subprocess
import sys

import pytest

from conftest import BIN, SOURCE


def run_example(name, *args):
    env = dict(os.environ)
    done = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "examples", name),
                           *args], capture_output=True, text=True, env=env, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_ppo_torch_reaches_nine_tenths_of_the_oracle_in_b():
    pytest.importorskip("torch")
    out = run_example("ppo_torch.py")
    share = float(re.search(r"\(([\d.]+) %\); trained in", out).group(1))
    assert share >= 90.0, out


def test_ppo_torch_exports_a_policy_that_rlpos_sim_flies_to_the_same_place(tmp_path):
    out = run_example("ppo_torch.py", "--episodes", "1", "--export", str(tmp_path / "policy"),
                      "--rlpos-sim", os.path.join(BIN, "rlpos-sim"))
    python = re.search(r"greedy final position (\([^)]*\))", out).group(1)
    cli = re.search(r"rlpos-sim position --policy \S+: (\([^)]*\))", out).group(1)
    assert python == cli, out


def test_score_policy_evaluates_at_packet_level():
    out = run_example("score_policy.py", "--runs", "1", "--duration", "2")
    rows = {line.split()[0]: line for line in out.splitlines()[2:]}
    assert set(rows) == {"baseline", "policy"}, out
    assert " 4/4 " in rows["policy"] and " 1/4 " in rows["baseline"], out
