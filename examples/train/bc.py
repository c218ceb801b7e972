"""Behaviour cloning: the network learns the collected agent's choices (cross-entropy over the
legal actions), with a held-out tenth to measure accuracy.

python examples/train/bc.py --config configs/seed.toml --data runs/x/data --out runs/x

`--data` may also be a dataset folder built from game logs (`rinshan dataset logs/ -o DIR`).
With `[bc] target = "search_action"` the net learns the look-ahead's choices of a dataset built
with `--search` (distillation); with `"search_value"` it learns the distribution its values give
(softmax of value / `[bc] temperature`, in places; default 0.05) where it looked, its choice
elsewhere. `[bc] init = "PATH"` starts from a trained checkpoint instead of a new net (its input
statistics kept).

With `[bc] evaluate_games = N` (and `evaluate_every` steps, `opponents`), the net plays N games
against `opponents` in the run's variant and mode, on the same walls each time, at the start, every
`evaluate_every` steps and at the end: the points of a rank curve (`kind = "evaluate"` in bc.jsonl).
"""

from __future__ import annotations

import argparse
import pathlib
import time

import numpy as np
import torch
from collect import Rows, held_out
from common import (
    Log,
    config_arguments,
    load_config,
    load_net,
    new_net,
    rank_point,
    save,
    seed_everything,
    set_threads,
    setting,
)

# Rows the scalars' mean and spread are taken from: enough for them, and a dataset of millions of
# rows is not read whole for them.
SCALAR_ROWS = 1 << 20


# The config tables behaviour cloning reads.
TABLES = ("run", "bc")


def train_bc(cfg: dict, seed: int, data: pathlib.Path, out: pathlib.Path) -> dict:
    c = cfg["bc"]
    seed_everything(seed)
    set_threads(cfg)
    analysis = bool(cfg["run"].get("analysis", False))
    target = str(c.get("target", "action"))
    init = c.get("init")
    net = load_net(init) if init else new_net(cfg)
    net.train()
    d = Rows(data, analysis, target, float(c.get("temperature", 0.05)), net.actions)
    n = len(d)
    if n == 0:
        raise SystemExit(f"{data}: no rows to learn from")
    val, train = held_out(n, seed)
    n_val = len(val)
    want = (net.row_scale.shape[0], net.config["num_actions"])
    if d.shape != want:
        raise SystemExit(
            f"{data}: shards hold {d.shape[0]} rows and {d.shape[1]} actions, "
            f"this config's net reads {want[0]} and writes {want[1]} (collect them again)"
        )
    if not init:
        sample = train
        if len(train) > SCALAR_ROWS:
            sample = np.random.default_rng(seed + 2).choice(train, SCALAR_ROWS, replace=False)
        s = torch.tensor(d.scalars(np.sort(sample)), dtype=torch.float32)
        net.scalar_mean.copy_(s.mean(0))
        net.scalar_std.copy_(s.std(0).clamp(min=1.0))
        del s
    opt = torch.optim.Adam(net.parameters(), lr=float(c["lr"]))
    batch, epochs = int(c["batch"]), float(c["epochs"])
    total = int(epochs * len(train) / batch)
    sched = torch.optim.lr_scheduler.CosineAnnealingLR(opt, max(total, 1))
    log = Log(out / "bc.jsonl")
    start = time.time()

    def rows(idx):
        return tuple(torch.from_numpy(x) for x in d.take(idx))

    # A target is an action per row, or a distribution per row (the look-ahead's values), and
    # cross-entropy takes either; a masked logit meets a zero probability, never a NaN.
    def chosen(target):
        return target if target.dim() == 1 else target.argmax(1)

    def validate() -> tuple[float, float]:
        net.eval()
        loss = correct = 0.0
        with torch.no_grad():
            for i in range(0, n_val, 8192):
                p, sc, m, a = rows(val[i : i + 8192])
                logits = net(p, sc, m)
                loss += torch.nn.functional.cross_entropy(logits, a, reduction="sum").item()
                correct += (logits.argmax(1) == chosen(a)).sum().item()
        net.train()
        return loss / n_val, correct / n_val

    games = int(c.get("evaluate_games", 0))
    if games > 0 and "opponents" not in c:
        raise SystemExit("[bc] evaluate_games needs [bc] opponents, an agent's name (defensive)")
    evaluate_every = int(c.get("evaluate_every", 0)) or total
    variant, mode = setting(cfg, "bc")
    evaluations, evaluation_s = [], 0.0

    # Rank against training time: the seconds learning took, the evaluations' own left out.
    def evaluate(step: int) -> None:
        nonlocal evaluation_s
        if games <= 0:
            return
        t = time.time()
        point = rank_point(net, variant, mode, analysis, c["opponents"], games, 10_000 + seed)
        evaluation_s += time.time() - t
        train_s = round(time.time() - start - evaluation_s, 1)
        row = {"step": step, "samples": step * batch, "train_s": train_s, **point}
        evaluations.append(row)
        log.write(kind="evaluate", **row)
        print(f"bc step {step}: average rank {point['rank']:.3f} ± {point['ci95']:.3f}")

    val_loss, acc = validate()
    log.write(step=0, samples=0, train_loss=None, val_loss=val_loss, val_accuracy=acc)
    evaluate(0)
    first_loss = val_loss
    rng = np.random.default_rng(seed + 1)
    step, running = 0, []
    every = max(1, total // 40)
    while step < total:
        perm = train[rng.permutation(len(train))]
        for i in range(0, len(perm) - batch + 1, batch):
            p, sc, m, a = rows(np.sort(perm[i : i + batch]))
            loss = torch.nn.functional.cross_entropy(net(p, sc, m), a)
            opt.zero_grad()
            loss.backward()
            opt.step()
            sched.step()
            running.append(loss.item())
            step += 1
            if step % every == 0 or step == total:
                val_loss, acc = validate()
                log.write(
                    step=step,
                    samples=step * batch,
                    train_loss=float(np.mean(running)),
                    val_loss=val_loss,
                    val_accuracy=acc,
                )
                print(f"bc step {step}/{total} loss {np.mean(running):.4f} val acc {acc:.3f}")
                running = []
            if step % evaluate_every == 0 or step == total:
                evaluate(step)
            if step >= total:
                break
    seconds = round(time.time() - start, 1)
    save(net, out / "bc.pt", seed=seed, samples=n)
    log.close()
    return {
        "samples": n,
        "steps": step,
        "first_val_loss": first_loss,
        "val_loss": val_loss,
        "val_accuracy": acc,
        "seconds": seconds,
        "evaluations": evaluations,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    config_arguments(ap)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument(
        "--data", required=True, help="collect.py's shards, or a `rinshan dataset` folder"
    )
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    print(
        train_bc(
            load_config(a.config, TABLES, a.set), a.seed, pathlib.Path(a.data), pathlib.Path(a.out)
        )
    )


if __name__ == "__main__":
    main()
