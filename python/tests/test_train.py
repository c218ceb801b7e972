"""The training example's smoke config end to end (examples/train/run.py --smoke): every stage runs,
the losses fall, the arena's numbers are sane. Strength is the full config's business
(docs/rl-validation.md). Under CI torch must be there: a skip would hide a broken pipeline."""

import importlib.util
import json
import os
import pathlib
import subprocess
import sys

import pytest

TRAIN = pathlib.Path(__file__).resolve().parents[2] / "examples" / "train"
HAVE = all(importlib.util.find_spec(m) for m in ("torch", "matplotlib"))

needs_torch = pytest.mark.skipif(
    not HAVE and not os.environ.get("CI"),
    reason="no torch/matplotlib (pip install -r examples/train/requirements.txt)",
)


def lines(path: pathlib.Path) -> list[dict]:
    return [json.loads(x) for x in path.read_text().splitlines()]


@needs_torch
def test_smoke_pipeline_runs_and_learns(tmp_path):
    out = tmp_path / "smoke"
    done = subprocess.run(
        [sys.executable, str(TRAIN / "run.py"), "--smoke", "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    seed = out / "seed0"
    for f in ("data/shard-000.npz", "bc.pt", "ppo.pt", "result.json", "bc.jsonl", "ppo.jsonl"):
        assert (seed / f).exists(), f
    for f in ("summary.json", "summary.md", "plots/rank.png", "plots/losses.png"):
        assert (out / f).stat().st_size > 0, f

    result = json.loads((seed / "result.json").read_text())
    # Cloning learns: the held-out loss ends well below where it started, and above chance.
    bc = result["bc"]
    assert bc["val_loss"] < 0.8 * bc["first_val_loss"]
    assert bc["val_accuracy"] > 0.5
    # PPO's losses fall: over each rollout, the last epoch's value and policy losses are below
    # the first epoch's (summed over the updates, which are few and noisy one by one).
    updates = [r for r in lines(seed / "ppo.jsonl") if r["kind"] == "update"]
    assert len(updates) == 8
    for key in ("value_by_epoch", "pg_by_epoch"):
        first = sum(r[key][0] for r in updates)
        last = sum(r[key][-1] for r in updates)
        assert last < first, (key, first, last)
    # The policy moves away from the clone, and stays a distribution.
    assert updates[-1]["kl"] > updates[0]["kl"] >= 0
    assert all(r["entropy"] > 0 for r in updates)
    assert updates[-1]["env_steps"] == 8 * 32 * 128
    # Before any update the learner is the BC net, and identical deterministic players split
    # every duplicate set's four places exactly.
    first = [r for r in lines(seed / "ppo.jsonl") if r["kind"] == "evaluate"][0]
    assert first["update"] == 0 and first["rank"] == 2.5 and first["ci95"] == 0
    for r in result["evaluate"]:
        assert r["illegal"] == 0 and 1 <= r["rank"] <= 4 and sum(r["places"]) == r["games"]
    # The no-red net plays the red variant through the canonical action space.
    assert result["evaluate"][2]["variant"] == "red"
