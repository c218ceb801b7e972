"""The mean of policy nets trained from one start: a net whose weights are the mean of theirs.

python examples/train/average.py runs/sla/ppo/mean.pt runs/sla/ppo/seed*/ppo.pt

Runs fine-tuned from the same net (PPO with different seeds, say) tend to stay in one basin of the
loss, where the mean of their weights often plays as well as each or better, with less of any one
run's noise (Wortsman et al., 2022, "Model soups"; docs/rl-validation.md measures it in sanma).
Nets from different starts have no such relation: their mean is not a net that plays. So the nets
must share their shape and the buffers their start fixed (the scalars' normalisation, the discard
columns), and only parameters are averaged.
"""

from __future__ import annotations

import argparse
import pathlib

import torch
from common import Net, load_net, save


def average(nets: list[Net]) -> Net:
    """A new net of the same shape whose parameters are the mean of `nets`' (a ValueError if they
    differ in shape or in a buffer)."""
    if not nets:
        raise ValueError("no nets to average")
    first = nets[0]
    parameters = {name for name, _ in first.named_parameters()}
    states = [n.state_dict() for n in nets]
    for i, net in enumerate(nets[1:], start=1):
        if net.config != first.config:
            raise ValueError(
                f"net {i} has another shape than net 0: {net.config} != {first.config}"
            )
        for name, t in states[i].items():
            if name not in parameters and not torch.equal(t, states[0][name]):
                raise ValueError(
                    f"net {i}'s buffer {name} differs from net 0's: "
                    "they were not trained from one start"
                )
    mean = {
        name: (torch.stack([s[name] for s in states]).mean(dim=0) if name in parameters else t)
        for name, t in states[0].items()
    }
    out = Net(**first.config)
    out.load_state_dict(mean)
    out.eval()
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="the checkpoint to write (export.py reads it)")
    ap.add_argument("checkpoints", nargs="+", help="policy checkpoints of bc.py or ppo.py")
    a = ap.parse_args()
    net = average([load_net(p) for p in a.checkpoints])
    save(net, pathlib.Path(a.out), averaged=a.checkpoints)
    print(f"wrote {a.out}: the mean of {len(a.checkpoints)} nets")


if __name__ == "__main__":
    main()
