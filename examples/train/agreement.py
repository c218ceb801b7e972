"""Top-1 agreement of a cloned net with the decisions of a log dataset (`rinshan dataset`): the
share of rows where the net's most likely legal action is the action the log took, overall and by
kind of decision. Give it a dataset of held-out games (games the net never trained on).

python examples/train/agreement.py runs/x/bc.pt data/held-out
"""

from __future__ import annotations

import argparse
import json
import pathlib

import numpy as np
import torch
from collect import Rows
from common import load_net, set_threads


def agreement(net_path: pathlib.Path, data: pathlib.Path, batch: int = 8192) -> dict:
    net = load_net(net_path)
    net.eval()
    d = Rows(data, net.analysis, actions=net.actions)
    n = len(d)
    chosen = np.empty(n, dtype=np.int64)
    taken = np.empty(n, dtype=np.int64)
    with torch.no_grad():
        for i in range(0, n, batch):
            planes, scalars, mask, action = d.take(np.arange(i, min(i + batch, n)))
            logits = net(
                torch.from_numpy(planes), torch.from_numpy(scalars), torch.from_numpy(mask)
            )
            chosen[i : i + len(action)] = logits.argmax(1).numpy()
            taken[i : i + len(action)] = action
    # The kind of a decision is its action name's first word (discard, riichi, pon, pass, ...),
    # counted by the action the log took.
    kind = np.array([name.split("_")[0] for name in net.actions])[taken]
    same = chosen == taken
    by_kind = {
        k: {"rows": int((kind == k).sum()), "agreement": float(same[kind == k].mean())}
        for k in sorted(set(kind))
    }
    return {
        "net": str(net_path),
        "data": str(data),
        "rows": n,
        "agreement": float(same.mean()) if n else None,
        "by_kind": by_kind,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("net", type=pathlib.Path, help="a checkpoint (bc.pt)")
    ap.add_argument("data", type=pathlib.Path, help="a `rinshan dataset` folder of held-out games")
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    set_threads({"run": {"threads": a.threads}})
    print(json.dumps(agreement(a.net, a.data), indent=1))


if __name__ == "__main__":
    main()
