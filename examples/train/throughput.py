"""Where a training step's time goes: a few PPO updates of a config's stage, without evaluations,
and the split of their wall time (env, observation, oracle, inference, bookkeeping, learning).

python examples/train/throughput.py --config examples/train/configs/seed.toml --updates 4
python examples/train/throughput.py --config ... --bc runs/seed/seed0/bc.pt --table finetune

Without `--bc` the nets are untrained ones of the config's `[bc]` shape: a step costs the same
whatever the weights, and the games differ only in who wins them.
"""

from __future__ import annotations

import argparse
import copy
import json
import pathlib
import tempfile

from common import load_config, new_net, save
from ppo import train_ppo


def untrained(cfg: dict, path: pathlib.Path) -> pathlib.Path:
    save(new_net(cfg), path)
    return path


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--config", required=True)
    ap.add_argument("--table", default="ppo", help="the stage to time: ppo or finetune")
    ap.add_argument("--updates", type=int, default=4)
    ap.add_argument("--bc", help="a BC checkpoint (default: an untrained net of its shape)")
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args()
    cfg = copy.deepcopy(load_config(a.config, ("run", "bc", a.table)))
    c = cfg[a.table]
    c["updates"], c["evaluate_games"], c["print_every"] = a.updates, 0, 10**9
    c.pop("evaluate_every", None)
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp)
        bc = pathlib.Path(a.bc) if a.bc else untrained(cfg, out / "bc.pt")
        start = None if a.table == "ppo" else bc
        r = train_ppo(cfg, a.seed, bc, out, table=a.table, start_from=start)
    total = sum(r["split"].values())
    print(f"{a.table}: {r['env_steps']} env steps in {total:.1f} s: {r['steps_per_s']:.0f} steps/s")
    for part, s in r["split"].items():
        print(f"  {part:12s} {s:8.2f} s  {100 * s / total:5.1f}%")
    print(json.dumps({k: r[k] for k in ("env_steps", "steps_per_s", "split")}))


if __name__ == "__main__":
    main()
