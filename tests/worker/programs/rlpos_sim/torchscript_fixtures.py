"""TorchScript modules for rlpos-sim's TorchScript policy tests, written as OUT/<name>.pt.

  torchscript_fixtures.py OUT A

Each takes float32 [B, D] observations, for any D. In `prefer_*` the logits are constant preferences over
scenario B's moves (up, down, forward, backward, left, right, stay); the others are wrong in one
way each."""
import os
import sys

import torch
from torch import nn


class Constant(nn.Module):
    """Logits `values` whatever the observation, in the shape [B, len(values)]."""

    def __init__(self, values):
        super().__init__()
        self.register_buffer("values", torch.tensor(values, dtype=torch.float32))

    def forward(self, x):
        return x[:, :1] * 0.0 + self.values


class NanAwayFromZero(Constant):
    """Finite logits on the zero observation (the load check), NaN on any other."""

    def forward(self, x):
        zero = x[:, :1] * 0.0
        away = x.abs().sum(1, keepdim=True) > 0
        return torch.where(away, zero + float("nan"), zero) + self.values


class Pair(Constant):
    def forward(self, x):
        return (x[:, :1] * 0.0 + self.values, self.values)


def main():
    out, a = sys.argv[1], int(sys.argv[2])
    os.makedirs(out, exist_ok=True)
    ranks = lambda *order: [float(len(order) - order.index(i)) if i in order else 0.0  # noqa
                            for i in range(a)]
    up, right, stay = 0, 5, 6
    modules = {
        "prefer_stay": Constant(ranks(stay)),
        "prefer_up_right_stay": Constant(ranks(up, right, stay)),
        "wide": Constant([0.0] * (a + 1)),
        "nan": Constant([float("nan")] * a),
        "nan_in_flight": NanAwayFromZero(ranks(stay)),
        "pair": Pair([0.0] * a),
    }
    for name, module in modules.items():
        torch.jit.script(module).save(os.path.join(out, name + ".pt"))


if __name__ == "__main__":
    main()
