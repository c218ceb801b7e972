"""The whole pipeline, one command: for each seed of the config, collect -> bc -> ppo (->
finetune) -> evaluate, then a summary over seeds (summary.json, summary.md) and the plots.

python examples/train/run.py --config examples/train/configs/seed.toml
python examples/train/run.py --smoke          # a few minutes: checks that it runs and learns
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import sys
import time
from typing import Optional

import numpy as np
from bc import train_bc
from collect import collect
from common import config_arguments, load_config
from evaluate import arena
from ppo import train_ppo

HERE = pathlib.Path(__file__).resolve().parent
STAGES = ("bc", "ppo", "finetune")


def run_seed(
    cfg: dict, seed: int, out: pathlib.Path, bc_from: Optional[pathlib.Path] = None
) -> dict:
    times, result = {}, {"seed": seed}
    t = time.time()
    if bc_from is None:
        result["collect"] = collect(cfg, seed, out / "data")
    else:
        result["collect"] = {"dataset": str(bc_from)}
    times["collect"] = time.time() - t
    t = time.time()
    result["bc"] = train_bc(cfg, seed, bc_from or out / "data", out)
    times["bc"] = time.time() - t
    t = time.time()
    result["ppo"] = train_ppo(cfg, seed, out / "bc.pt", out)
    times["ppo"] = time.time() - t
    if "finetune" in cfg:
        t = time.time()
        result["finetune"] = train_ppo(
            cfg, seed, out / "bc.pt", out, table="finetune", start_from=out / "ppo.pt"
        )
        times["finetune"] = time.time() - t
    t = time.time()
    result["evaluate"] = []
    for i, m in enumerate(cfg["evaluate"]["matchups"]):
        names = [out / f"{x}.pt" if x in STAGES else x for x in (m["policy"], m["opponents"])]
        r = arena(
            str(names[0]),
            str(names[1]),
            int(m.get("games", cfg["evaluate"]["games"])),
            20_000 + 100 * seed + i,
            m.get("variant", cfg["run"]["variant"]),
            m.get("mode", cfg["run"]["mode"]),
        )
        r["policy"], r["opponents"] = m["policy"], m["opponents"]
        print(
            f"seed {seed}: {m['policy']} vs 3 {m['opponents']} ({r['variant']}, {r['mode']}): "
            f"{r['rank']:.3f} ± {r['ci95']:.3f}"
        )
        result["evaluate"].append(r)
    times["evaluate"] = time.time() - t
    result["seconds"] = {k: round(v, 1) for k, v in times.items()}
    (out / "result.json").write_text(json.dumps(result, indent=1))
    return result


def summarise(cfg: dict, results: list[dict]) -> dict:
    """Per matchup: each seed's rank and interval, and the mean over seeds (its interval from the
    pooled games: the seeds' intervals combined as independent estimates)."""
    rows = []
    for i in range(len(cfg["evaluate"]["matchups"])):
        per = [r["evaluate"][i] for r in results]
        mean = float(np.mean([p["rank"] for p in per]))
        ci = math.sqrt(sum(p["ci95"] ** 2 for p in per)) / len(per)
        rows.append(
            {
                **{k: per[0][k] for k in ("policy", "opponents", "variant", "mode")},
                "games_per_seed": per[0]["games"],
                "ranks": [p["rank"] for p in per],
                "ci95s": [p["ci95"] for p in per],
                "mean_rank": mean,
                "mean_ci95": ci,
            }
        )
    stages = ("collect", "bc", "ppo", "finetune", "evaluate")
    seconds = {s: [r["seconds"][s] for r in results if s in r["seconds"]] for s in stages}
    return {
        "name": cfg["run"]["name"],
        "seeds": [r["seed"] for r in results],
        "matchups": rows,
        "seconds": {k: v for k, v in seconds.items() if v},
        "ppo_env_steps": [r["ppo"]["env_steps"] for r in results],
        "ppo_decisions": [r["ppo"]["decisions"] for r in results],
        "finetune_env_steps": [r["finetune"]["env_steps"] for r in results if "finetune" in r],
        "bc_accuracy": [r["bc"]["val_accuracy"] for r in results],
    }


def markdown(s: dict) -> str:
    seeds = s["seeds"]
    head = "| policy | vs 3 | variant, mode | " + " | ".join(f"seed {x}" for x in seeds)
    lines = [head + " | mean |", "|---|---|---|" + "---|" * (len(seeds) + 1)]
    for m in s["matchups"]:
        cells = [f"{r:.3f} ± {c:.3f}" for r, c in zip(m["ranks"], m["ci95s"])]
        lines.append(
            f"| {m['policy']} | {m['opponents']} | {m['variant']}, {m['mode']} "
            f"({m['games_per_seed']} games) | "
            + " | ".join(cells)
            + f" | **{m['mean_rank']:.3f} ± {m['mean_ci95']:.3f}** |"
        )
    return "\n".join(lines) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    config_arguments(ap, required=False)
    ap.add_argument("--smoke", action="store_true", help="configs/smoke.toml: a short check")
    ap.add_argument("--out", help="run folder (default runs/<name>)")
    ap.add_argument("--seeds", help="comma-separated seeds instead of the config's")
    ap.add_argument(
        "--bc-from",
        type=pathlib.Path,
        help="behaviour cloning from this `rinshan dataset` folder of game logs, not self-play",
    )
    a = ap.parse_args()
    if a.smoke == bool(a.config):
        sys.exit("give --config FILE or --smoke")
    cfg = load_config(HERE / "configs" / "smoke.toml" if a.smoke else a.config, sets=a.set)
    out = pathlib.Path(a.out or pathlib.Path("runs") / cfg["run"]["name"])
    seeds = [int(x) for x in a.seeds.split(",")] if a.seeds else cfg["run"]["seeds"]
    start = time.time()
    results = [run_seed(cfg, seed, out / f"seed{seed}", a.bc_from) for seed in seeds]
    summary = summarise(cfg, results)
    summary["total_seconds"] = round(time.time() - start, 1)
    (out / "summary.json").write_text(json.dumps(summary, indent=1))
    (out / "summary.md").write_text(markdown(summary))
    try:
        from plots import plot_run
    except ImportError as e:  # matplotlib is optional for training itself
        print(f"no plots: {e}")
    else:
        plot_run(out)
    print(markdown(summary))
    print(f"total {summary['total_seconds']:.0f} s; results in {out}")


if __name__ == "__main__":
    main()
