"""Where a training step's time goes: a few PPO updates of a config's stage, without evaluations,
and the split of their wall time (env, observation, oracle, inference, bookkeeping, learning).

python examples/train/throughput.py --config examples/train/configs/seed.toml --updates 4
python examples/train/throughput.py --config ... --bc runs/seed/seed0/bc.pt --table finetune

Every timed update trains both nets (the config's critic-only warmup is left out). Without `--bc`
the nets are untrained ones of the config's `[bc]` shape: a row costs the same whatever the
weights, but untrained players play other games (how many of the steps are the learner's, how
many have a choice), so figures worth quoting take a trained net.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import tempfile

from common import config_arguments, load_config, new_net, save
from ppo import train_ppo


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    config_arguments(ap)
    ap.add_argument("--table", default="ppo", help="the stage to time: ppo or finetune")
    ap.add_argument("--updates", type=int, default=4)
    ap.add_argument("--bc", help="a BC checkpoint (default: an untrained net of its shape)")
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args()
    cfg = load_config(a.config, ("run", "bc", a.table), a.set)
    c = cfg[a.table]
    c["updates"], c["evaluate_games"], c["print_every"] = a.updates, 0, 10**9
    # Every timed update a full one: the first updates' critic-only warmup skips the policy's
    # backward pass and would flatter the speed.
    c["critic_warmup"] = 0
    c.pop("evaluate_every", None)
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp)
        bc = pathlib.Path(a.bc) if a.bc else out / "bc.pt"
        if not a.bc:
            save(new_net(cfg), bc)
        start = None if a.table == "ppo" else bc
        r = train_ppo(cfg, a.seed, bc, out, table=a.table, start_from=start)
    total = sum(r["split"].values())
    print(f"{a.table}: {r['env_steps']} env steps in {total:.1f} s: {r['steps_per_s']:.0f} steps/s")
    for part, s in r["split"].items():
        print(f"  {part:12s} {s:8.2f} s  {100 * s / total:5.1f}%")
    print(json.dumps({k: r[k] for k in ("env_steps", "steps_per_s", "split")}))


if __name__ == "__main__":
    main()
