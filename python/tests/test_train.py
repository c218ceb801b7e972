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
    # The clone's rank curve: at the start, every 50 steps and at the last step.
    ev = [r for r in lines(seed / "bc.jsonl") if r.get("kind") == "evaluate"]
    assert [r["step"] for r in ev] == [*range(0, bc["steps"], 50), bc["steps"]]
    assert all(1 <= r["rank"] <= 4 and r["ci95"] > 0 and r["even"] == 2.5 for r in ev)
    # Its clock is learning's: it grows, and leaves the evaluations' own time out.
    assert all(a["train_s"] <= b["train_s"] for a, b in zip(ev, ev[1:]))
    assert ev[-1]["train_s"] < ev[-1]["wall_s"]
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
    # Each update says where its time went, and every part of the loop took some.
    for r in updates:
        assert set(r["split"]) == {
            "env",
            "observation",
            "oracle",
            "inference",
            "bookkeeping",
            "learning",
        }
        assert all(v > 0 for v in r["split"].values()), r["split"]
        assert abs(r["split"]["learning"] - r["train_s"]) < 0.01
    # Before any update the learner is the BC net, and identical deterministic players split
    # every duplicate set's four places exactly.
    first = [r for r in lines(seed / "ppo.jsonl") if r["kind"] == "evaluate"][0]
    assert first["update"] == 0 and first["rank"] == 2.5 and first["ci95"] == 0
    for r in result["evaluate"]:
        assert r["illegal"] == 0 and 1 <= r["rank"] <= 4 and sum(r["places"]) == r["games"]
    # The no-red net plays the red variant through the nets' action layout.
    assert result["evaluate"][2]["variant"] == "red"


@needs_torch
def test_tile_head_is_one_layer_over_each_tile_and_the_context():
    """The net computes the tile head's first layer in two halves (the context's once per
    position); it must be the layer over each tile's column and the context side by side."""
    import torch

    sys.path.insert(0, str(TRAIN))
    from common import ACTIONS, DRAWN_ROW, PLANES, SCALARS, Net

    torch.manual_seed(0)
    net = Net(len(ACTIONS), hidden=32, analysis=True, tile_head=True, tile_hidden=16)
    b = 64
    planes = torch.randint(0, 5, (b, net.row_scale.shape[0], PLANES[1]), dtype=torch.uint8)
    scalars = torch.randint(0, 30, (b, SCALARS), dtype=torch.int16)
    mask = torch.rand(b, len(ACTIONS)) < 0.5
    with torch.no_grad():
        got = net(planes, scalars, mask)
        x = planes.float() * net.row_scale
        g = net.features(planes, scalars)
        columns = x.transpose(1, 2)
        context = net.tile_context(g)[:, None, :].expand(-1, PLANES[1], -1)
        per_tile = net.tile_head(torch.cat([columns, context], dim=2)).squeeze(2)
        drawn = planes[:, DRAWN_ROW].argmax(dim=1, keepdim=True)
        per_tile = torch.cat([per_tile, per_tile.gather(1, drawn)], dim=1)
        want = net.head(g) + per_tile[:, net.discard_column] * net.is_discard
        want = want.masked_fill(~mask, -1e9)
    assert torch.allclose(got, want, atol=1e-5), (got - want).abs().max()


@needs_torch
def test_average_is_the_mean_of_the_parameters_of_nets_from_one_start(tmp_path):
    import torch

    sys.path.insert(0, str(TRAIN))
    from average import average
    from common import ACTIONS, PLANES, SCALARS, Net, load_net, save

    torch.manual_seed(0)
    shape = dict(hidden=16, analysis=True, tile_head=True, tile_hidden=8)
    a, b = Net(len(ACTIONS), **shape), Net(len(ACTIONS), **shape)
    for net in (a, b):
        net.scalar_mean.fill_(3.0)  # the start's normalisation, shared
    save(a, tmp_path / "a.pt")
    save(b, tmp_path / "b.pt")
    done = subprocess.run(
        [
            sys.executable,
            str(TRAIN / "average.py"),
            str(tmp_path / "mean.pt"),
            str(tmp_path / "a.pt"),
            str(tmp_path / "b.pt"),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    mean = load_net(tmp_path / "mean.pt")
    sa, sb = a.state_dict(), b.state_dict()
    for name, t in mean.state_dict().items():
        assert torch.allclose(t.float(), (sa[name].float() + sb[name].float()) / 2), name
    assert torch.equal(mean.discard_column, a.discard_column)

    # A net averaged with itself is the same function.
    planes = torch.randint(0, 5, (8, a.row_scale.shape[0], PLANES[1]), dtype=torch.uint8)
    scalars = torch.randint(0, 30, (8, SCALARS), dtype=torch.int16)
    legal = torch.ones(8, len(ACTIONS), dtype=torch.bool)
    with torch.no_grad():
        assert torch.allclose(average([a, a])(planes, scalars, legal), a(planes, scalars, legal))

    with pytest.raises(ValueError, match="another shape"):
        average([a, Net(len(ACTIONS), **{**shape, "hidden": 32})])
    other = Net(len(ACTIONS), **shape)
    with pytest.raises(ValueError, match="not trained from one start"):
        average([a, other])


@needs_torch
@pytest.mark.parametrize("bc_in_rust", ["false", "true"])
def test_throughput_reports_the_split_of_a_few_updates(bc_in_rust):
    """With `bc_in_rust` the BC seats are the env's `net:PATH` opponents: the same loop."""
    done = subprocess.run(
        [
            sys.executable,
            str(TRAIN / "throughput.py"),
            "--config",
            str(TRAIN / "configs" / "smoke.toml"),
            "--updates",
            "2",
            "--set",
            f"ppo.bc_in_rust={bc_in_rust}",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report["steps_per_s"] > 0
    assert set(report["split"]) >= {"env", "inference", "learning"}
    assert report["env_steps"] == 2 * 32 * 128
