"""The look-ahead's strength against its budget: the curve of docs/strength.md.

python examples/search/budget.py          # docs/img/search-budget.png: hours on 2 cores
python examples/search/budget.py --rollouts 8,32 --games 8 --mode east --out /tmp/b.png

Each budget is one duplicate `rinshan arena` run of `search:rollouts=N` against three `defensive`
(red half games unless told otherwise). Its JSON report is kept in --cache under a name made of
its settings, so a rerun plays only the budgets missing there and an interrupted run loses one
budget at most. The strength at a budget in play-outs does not depend on the machine (the
decisions are the same for a seed); the milliseconds per decision do: the plot's x axis is the
machine the runs were made on.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import subprocess
import sys

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[2]


def arena(args: argparse.Namespace, rollouts: int, games: int) -> dict:
    """The arena's report for one budget, from the cache or played (and cached)."""
    name = f"search-r{rollouts}-g{games}-s{args.seed}"
    if args.variant != "red" or args.mode != "half":
        name += f"-{args.variant}-{args.mode}"
    path = args.cache / f"{name}.json"
    if path.exists():
        return json.loads(path.read_text())
    seats = 3 if "sanma" in args.variant else 4
    agents = ",".join([f"search:rollouts={rollouts}"] + ["defensive"] * (seats - 1))
    cmd = [args.rinshan, "arena", "--agents", agents, "--games", str(games)]
    cmd += ["--seed", str(args.seed), "--variant", args.variant, "--mode", args.mode, "--json"]
    if args.threads:
        cmd += ["--threads", str(args.threads)]
    print(" ".join(cmd), file=sys.stderr, flush=True)
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    args.cache.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    tmp.write_text(out)
    tmp.replace(path)
    return json.loads(out)


def point(rollouts: int, report: dict) -> dict:
    """One budget's figures: the look-ahead's standing and its decision times."""
    # The one look-ahead seat, named by its settings as the arena prints them (the defaults
    # left out: `search:rollouts=256` is `search`).
    standing = next(s for s in report["standings"] if s["agent"].split(":")[0] == "search")
    search = report["search"][0]
    return {
        "rollouts": rollouts,
        "games": standing["games"],
        "rank": standing["mean_rank"],
        "ci95": standing["rank_ci95"],
        "ms": search["ms_per_decision"],
        "median_ms": search["median_ms"],
        "p99_ms": search["p99_ms"],
        "searched": search["searched"] / max(search["decisions"], 1),
        "changed": search["changed"] / max(search["searched"], 1),
    }


def table(points: list[dict]) -> str:
    rows = [
        "| play-outs | games | avg rank (95%) | ms per decision (mean / median / p99) "
        "| looked ahead at | changed |",
        "|---|---|---|---|---|---|",
    ]
    for p in points:
        ci = f" ± {p['ci95']:.3f}" if p["ci95"] is not None else ""
        rows.append(
            f"| {p['rollouts']} | {p['games']} | {p['rank']:.3f}{ci} "
            f"| {p['ms']:.1f} / {p['median_ms']:.1f} / {p['p99_ms']:.0f} "
            f"| {100 * p['searched']:.0f}% | {100 * p['changed']:.1f}% |"
        )
    return "\n".join(rows)


def plot(points: list[dict], args: argparse.Namespace) -> None:
    fig, (strength, time) = plt.subplots(1, 2, figsize=(12, 4.5))
    x = [p["ms"] for p in points]
    y = [p["rank"] for p in points]
    ci = [p["ci95"] or 0.0 for p in points]
    strength.errorbar(x, y, yerr=ci, marker="o", capsize=3, label="search vs 3 defensive")
    for p in points:
        strength.annotate(
            f"{p['rollouts']}", (p["ms"], p["rank"]), textcoords="offset points", xytext=(6, 6)
        )
    even = 2.0 if "sanma" in args.variant else 2.5
    strength.axhline(even, color="grey", linestyle="--", linewidth=1, label=f"even ({even})")
    strength.set_xscale("log")
    # Over a decade or two, matplotlib labels the minor ticks too, and they run together.
    strength.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    strength.set_xlabel("ms per decision, mean over all decisions (one core each)")
    strength.set_ylabel("average rank (95% CI over wall sets)")
    strength.set_title(f"strength against budget ({args.variant}, {args.mode}; labels: play-outs)")
    strength.invert_yaxis()
    strength.legend()
    r = [p["rollouts"] for p in points]
    time.plot(r, [p["ms"] for p in points], marker="o", label="mean")
    time.plot(r, [p["p99_ms"] for p in points], marker="s", label="99th percentile")
    time.set_xscale("log")
    time.set_yscale("log")
    time.set_xlabel("play-outs per decision looked ahead at")
    time.set_ylabel("ms per decision")
    time.set_title("decision time")
    time.legend()
    fig.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out, dpi=100)
    plt.close(fig)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    default_cli = os.environ.get("RINSHAN_CLI", str(REPO / "target" / "release" / "rinshan"))
    ap.add_argument("--rinshan", default=default_cli, help="the rinshan binary")
    ap.add_argument("--rollouts", default="64,256,1024,4096")
    ap.add_argument("--games", type=int, default=200, help="games per budget")
    ap.add_argument(
        "--games-at",
        default="4096=60",
        help="fewer games at the dearest budgets, e.g. 4096=60 (comma-separated)",
    )
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--variant", default="red")
    ap.add_argument("--mode", default="half")
    ap.add_argument("--threads", type=int, default=0, help="arena threads (0: all cores)")
    ap.add_argument("--cache", type=pathlib.Path, default=REPO / "target" / "budget-curve")
    ap.add_argument("--out", type=pathlib.Path, default=REPO / "docs" / "img" / "search-budget.png")
    args = ap.parse_args(argv)
    games_at = dict(
        (int(k), int(v)) for k, v in (kv.split("=") for kv in args.games_at.split(",") if kv)
    )
    points = []
    for r in (int(x) for x in args.rollouts.split(",")):
        points.append(point(r, arena(args, r, games_at.get(r, args.games))))
    print(table(points))
    plot(points, args)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
