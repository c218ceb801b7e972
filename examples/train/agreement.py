"""Top-1 agreement of a cloned net with the decisions of a log dataset (`rinshan dataset`): the
share of rows where the net's most likely legal action is the action the log took, overall and by
kind of decision. Give it a dataset of held-out games (games the net never trained on), or with
`--held-out SEED` the rows bc.py held out of its training dataset. On a dataset built with
`--search` it also reports how the net stands to the look-ahead's choices (`look_ahead`).

python examples/train/agreement.py runs/x/bc.pt data/held-out
python examples/train/agreement.py runs/x/bc.pt runs/x/data --held-out 0
"""

from __future__ import annotations

import argparse
import json
import pathlib

import numpy as np
import torch
from collect import Rows, held_out
from common import load_net, set_threads


def agreement(
    net_path: pathlib.Path, data: pathlib.Path, held_out_seed: int | None = None, batch: int = 8192
) -> dict:
    net = load_net(net_path)
    net.eval()
    d = Rows(data, net.analysis, actions=net.actions)
    idx = np.arange(len(d)) if held_out_seed is None else held_out(len(d), held_out_seed)[0]
    n = len(idx)
    chosen = np.empty(n, dtype=np.int64)
    taken = np.empty(n, dtype=np.int64)
    with torch.no_grad():
        for i in range(0, n, batch):
            planes, scalars, mask, action = d.take(idx[i : i + batch])
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
    report = {
        "net": str(net_path),
        "data": str(data),
        "held_out": held_out_seed,
        "rows": n,
        "agreement": float(same.mean()) if n else None,
        "by_kind": by_kind,
    }
    if d.has("search_action"):
        report["look_ahead"] = look_ahead(chosen, taken, d.labels("search_action", idx))
    return report


def look_ahead(chosen: np.ndarray, taken: np.ndarray, searched: np.ndarray) -> dict:
    """How the net's choices stand to the look-ahead's: agreement with its choice on every row,
    and on the rows where it chose otherwise than the log, whose side the net takes. Where the
    two agree a net cannot tell them apart; these rows are what a distilled net learns."""
    differ = searched != taken
    return {
        "agreement": float((chosen == searched).mean()) if len(chosen) else None,
        "differ": int(differ.sum()),
        "takes_look_ahead": float((chosen == searched)[differ].mean()) if differ.any() else None,
        "takes_log": float((chosen == taken)[differ].mean()) if differ.any() else None,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("net", type=pathlib.Path, help="a checkpoint (bc.pt)")
    ap.add_argument(
        "data",
        type=pathlib.Path,
        help="a `rinshan dataset` folder of held-out games, or with --held-out the net's own",
    )
    ap.add_argument(
        "--held-out",
        type=int,
        metavar="SEED",
        help="only the rows bc.py held out of this dataset with this seed (its --seed)",
    )
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    set_threads({"run": {"threads": a.threads}})
    print(json.dumps(agreement(a.net, a.data, a.held_out), indent=1))


if __name__ == "__main__":
    main()
