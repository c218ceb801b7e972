"""Plots of a run folder (matplotlib, PNG): rank against steps and the loss curves of every seed.

python examples/train/plots.py runs/seed      # writes runs/seed/plots/*.png
"""

from __future__ import annotations

import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path: pathlib.Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []


def evaluations(path: pathlib.Path) -> list[dict]:
    return [r for r in read(path) if r.get("kind") == "evaluate"]


# A curve's x: rows learnt for behaviour cloning, env steps for PPO.
X_AXES = {
    "bc": ("samples", "rows learnt (millions)"),
    "rl": ("env_steps", "env steps (millions; hero mode: the learner's)"),
}


def plot_run(run: pathlib.Path) -> list[pathlib.Path]:
    seeds = sorted(p for p in run.glob("seed*") if p.is_dir())
    out = run / "plots"
    out.mkdir(exist_ok=True)
    written = []

    stages = [s for s in ("ppo", "finetune") if any((d / f"{s}.jsonl").exists() for d in seeds)]
    # Behaviour cloning's curve where it evaluated along the way (`[bc] evaluate_games`).
    curves = [s for s in ("bc", *stages) if any(evaluations(d / f"{s}.jsonl") for d in seeds)]
    columns = max(1, len(curves))
    fig, axes = plt.subplots(1, columns, figsize=(6 * columns, 4), squeeze=False)
    for ax, stage in zip(axes[0], curves):
        even = 2.5  # four players, unless the log says otherwise
        x_key, x_label = X_AXES["bc" if stage == "bc" else "rl"]
        for d in seeds:
            ev = evaluations(d / f"{stage}.jsonl")
            if ev:
                x = [r[x_key] / 1e6 for r in ev]
                y = [r["rank"] for r in ev]
                ci = [r["ci95"] for r in ev]
                ax.errorbar(x, y, yerr=ci, marker="o", capsize=3, label=d.name)
                even = ev[0].get("even", even)
        ax.axhline(even, color="grey", linestyle="--", linewidth=1, label=f"even ({even:g})")
        ax.set_xlabel(x_label)
        ax.set_ylabel("average rank (95% CI)")
        ax.set_title(f"{stage}: rank against the stage's opponents")
        ax.invert_yaxis()
        ax.legend()
    fig.tight_layout()
    written.append(out / "rank.png")
    fig.savefig(written[-1], dpi=100)
    plt.close(fig)

    fig, axes = plt.subplots(2, 3, figsize=(18, 8))
    (bc_loss, bc_acc, explained), (value, kl, entropy) = axes
    for d in seeds:
        bc = [r for r in read(d / "bc.jsonl") if r.get("train_loss") is not None]
        if bc:
            x = [r["samples"] / 1e6 for r in bc]
            bc_loss.plot(x, [r["train_loss"] for r in bc], label=f"{d.name} train")
            bc_loss.plot(x, [r["val_loss"] for r in bc], "--", label=f"{d.name} held out")
            bc_acc.plot(x, [r["val_accuracy"] for r in bc], label=d.name)
        for stage in stages:
            up = [r for r in read(d / f"{stage}.jsonl") if r.get("kind") == "update"]
            if not up:
                continue
            x = [r["env_steps"] / 1e6 for r in up]
            for ax, key in ((explained, "explained_variance"), (value, "value"), (kl, "kl")):
                ax.plot(x, [r.get(key) for r in up], label=f"{d.name} {stage}")
            entropy.plot(x, [r["entropy"] for r in up], label=f"{d.name} {stage}")
    bc_loss.set(xlabel="samples (millions)", ylabel="cross-entropy", title="BC loss")
    bc_acc.set(xlabel="samples (millions)", title="BC held-out accuracy")
    steps = "env steps (millions; hero mode: the learner's)"
    explained.set(xlabel=steps, title="critic: share of the return's variance explained")
    value.set(xlabel=steps, title="critic loss (reward units squared / 2)")
    kl.set(xlabel=steps, title="KL(learner || BC)")
    entropy.set(xlabel=steps, title="policy entropy (nats)")
    for ax in axes.flat:
        # A run without a stage (BC alone, PPO from a given clone) leaves its panels empty.
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    fig.tight_layout()
    written.append(out / "losses.png")
    fig.savefig(written[-1], dpi=90)
    plt.close(fig)
    return written


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    for p in plot_run(pathlib.Path(sys.argv[1])):
        print(p)
