"""Datasets from logs (rinshan.dataset, `rinshan dataset`): rows checked against the per-round
records of rinshan.tenhou.read (each round replayed alone), every action legal under its own mask,
the CLI and the package making the same bytes, batches through PyTorch's DataLoader, and bad
input reported."""

import gzip
import importlib.util
import json
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import rinshan
from rinshan.dataset import Dataset, build, iterate
from rinshan.env import split_record

REPO = pathlib.Path(__file__).resolve().parents[2]
TENHOU = sorted((REPO / "tests" / "data" / "tenhou").glob("*.json"))
# Tenhou's log names carry the game's `GO type`: bit 0x10 is a three-player game.
MJLOGS = sorted((REPO / "tests" / "data" / "mjlog").glob("*.xml"))
MJLOG = [p for p in MJLOGS if int(p.name.split("-")[1], 16) & 0x10 == 0]
SANMA = [p for p in MJLOGS if p not in MJLOG]
TRAIN = REPO / "examples" / "train"
HAVE_TORCH = importlib.util.find_spec("torch") is not None
needs_torch = pytest.mark.skipif(not HAVE_TORCH and not os.environ.get("CI"), reason="no torch")


def train(*args) -> subprocess.CompletedProcess:
    """Runs one of the training example's scripts (`bc.py`, `agreement.py`) with `args`."""
    return subprocess.run(
        [sys.executable, *map(str, args)], capture_output=True, text=True, timeout=300, cwd=TRAIN
    )


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    logs = tmp_path_factory.mktemp("logs")
    for p in TENHOU[:4] + MJLOG[:2]:
        (logs / p.name).write_bytes(p.read_bytes())
    out = tmp_path_factory.mktemp("data") / "ds"
    summary = build([logs], out, observation=["planes", "tokens"], shard_size=2, threads=2)
    return logs, out, summary


def test_rows_are_each_rounds_decisions_with_a_real_choice(built):
    logs, out, summary = built
    assert summary["inputs"] == 6 and summary["games"] == 6 and summary["skipped"] == []
    ds = Dataset(out)
    assert len(ds) == summary["rows"] == summary["total_rows"] > 1000
    assert ds.check() == len(ds)
    names = ds.games
    rows = ds[:]
    for g, name in enumerate(names):
        game = rinshan.tenhou.read(name, observation=["planes", "tokens"])
        want = {"planes": [], "events": [], "mask": [], "action": [], "seat": [], "round": []}
        for r, rnd in enumerate(game["rounds"]):
            assert "error" not in rnd, rnd.get("error")
            choice = rnd["legal_action_mask"].sum(axis=1) > 1
            want["planes"].append(rnd["observation"]["planes"][choice])
            want["events"].append(rnd["observation"]["events"][choice])
            want["mask"].append(rnd["legal_action_mask"][choice])
            want["action"].append(rnd["action"][choice])
            want["seat"].append(rnd["seat"][choice])
            want["round"].append(np.full(choice.sum(), r))
        mine = rows["game"] == g
        np.testing.assert_array_equal(rows["planes"][mine], np.concatenate(want["planes"]))
        np.testing.assert_array_equal(rows["events"][mine], np.concatenate(want["events"]))
        np.testing.assert_array_equal(rows["legal_action_mask"][mine], np.concatenate(want["mask"]))
        np.testing.assert_array_equal(rows["action"][mine], np.concatenate(want["action"]))
        np.testing.assert_array_equal(rows["seat"][mine], np.concatenate(want["seat"]))
        np.testing.assert_array_equal(rows["round"][mine], np.concatenate(want["round"]))
        # The game's end: final points sum to the starting points, places follow them.
        scores, ranks = rows["scores"][mine][0], rows["ranks"][mine][0]
        assert scores.sum() == 100_000 and sorted(ranks) == [0, 1, 2, 3]
        for a in range(4):
            for b in range(4):
                assert ranks[a] > ranks[b] or scores[a] >= scores[b]
        seat = rows["seat"][mine]
        np.testing.assert_array_equal(rows["rank"][mine], ranks[seat])
        np.testing.assert_array_equal(rows["score"][mine], scores[seat])


def test_indexing_single_rows_slices_and_arrays(built):
    _, out, _ = built
    ds = Dataset(out, fields=["planes", "action", "rank"])
    n = len(ds)
    every = ds[:]
    idx = np.array([n - 1, 0, 7, n // 2, 7])
    picked = ds[idx]
    for k in ("planes", "action", "rank"):
        np.testing.assert_array_equal(picked[k], every[k][idx])
    one = ds[-1]
    np.testing.assert_array_equal(one["planes"], every["planes"][-1])
    assert set(one) == {"planes", "action", "rank"}
    np.testing.assert_array_equal(ds.__getitems__([3, 1])["action"], every["action"][[3, 1]])
    with pytest.raises(IndexError):
        ds[n]
    # A boolean mask selects rows, as numpy's does (not rows 0 and 1 by its values).
    riichi = every["action"] == ds.actions.index("riichi")
    assert 0 < riichi.sum() < n
    np.testing.assert_array_equal(ds[riichi]["planes"], every["planes"][riichi])
    with pytest.raises(IndexError, match="boolean row mask"):
        ds[riichi[:-1]]
    with pytest.raises(KeyError, match="not fields"):
        Dataset(out, fields=["nothing"])


def test_iterate_gives_the_datasets_rows_without_writing(built):
    logs, out, _ = built
    rows = Dataset(out)[:]
    got = list(iterate(logs, observation="planes", chunk=4))
    assert [g["name"] for g in got] == Dataset(out).games
    actions = np.concatenate([g["action"] for g in got])
    np.testing.assert_array_equal(actions, rows["action"])
    raw = np.concatenate([g["observation"]["planes"] for g in got])
    np.testing.assert_array_equal(split_record(raw, "planes")["planes"], rows["planes"])
    only = list(iterate(TENHOU[0], observation=None, players=["nobody"]))
    assert len(only) == 1 and len(only[0]["action"]) == 0


def test_the_cli_writes_the_same_bytes_and_resumes(built, cli, tmp_path):
    logs, out, summary = built
    mine = tmp_path / "cli"
    cmd = [
        cli,
        "dataset",
        str(logs),
        "-o",
        str(mine),
        "--observe",
        "planes,tokens",
        "--shard-size",
        "2",
    ]
    done = subprocess.run([*cmd, "--threads", "1", "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    assert report["rows"] == summary["rows"] and report["skipped"] == []
    for f in sorted(out.rglob("*")):
        if f.is_file():
            assert (mine / f.relative_to(out)).read_bytes() == f.read_bytes(), f
    again = subprocess.run([*cmd, "--json"], capture_output=True, text=True)
    assert again.returncode == 0, again.stderr
    assert json.loads(again.stdout)["shards_resumed"] == 3
    other = subprocess.run([*cmd[:-2], "--shard-size", "3"], capture_output=True, text=True)
    assert other.returncode == 2 and "other options" in other.stderr


def test_bad_logs_are_skipped_and_named(tmp_path):
    logs = tmp_path / "logs"
    logs.mkdir()
    (logs / "a.json").write_bytes(TENHOU[0].read_bytes())
    (logs / "b.json.gz").write_bytes(gzip.compress(TENHOU[1].read_bytes())[:200])
    (logs / "c.mjson").write_text('{"type":"start_game"}\n{"type":"nonsense"}\n')
    summary = build(logs, tmp_path / "ds", observation=None)
    assert summary["games"] == 1
    skipped = dict(summary["skipped"])
    assert set(skipped) == {str(logs / "b.json.gz"), str(logs / "c.mjson")}
    assert all(name in reason for name, reason in skipped.items())
    ds = Dataset(tmp_path / "ds")
    assert [s["input"] for s in ds.skipped] == sorted(skipped)
    with pytest.raises(ValueError, match="oracle"):
        build(logs, tmp_path / "ds2", observation="oracle")
    with pytest.raises(FileNotFoundError, match="manifest"):
        Dataset(logs)
    with pytest.raises(ValueError, match="seats are 0..3"):
        build(logs, tmp_path / "ds3", seats=[4])


@needs_torch
def test_a_dataloader_shuffles_across_shards(built):
    import torch

    _, out, _ = built
    ds = Dataset(out, fields=["planes", "legal_action_mask", "action"])
    loader = torch.utils.data.DataLoader(
        ds, batch_size=256, shuffle=True, collate_fn=rinshan.dataset.collate
    )
    seen = 0
    for batch in loader:
        assert (
            batch["planes"].dtype == torch.uint8 and batch["legal_action_mask"].dtype == torch.bool
        )
        legal = batch["legal_action_mask"][
            torch.arange(len(batch["action"])), batch["action"].long()
        ]
        assert bool(legal.all())
        seen += len(batch["action"])
    assert seen == len(ds)


@needs_torch
def test_behaviour_cloning_from_a_log_dataset(built, tmp_path):
    """The training example's path from logs: bc.py with the from-logs config (only its [run] and
    [bc] tables) streams the memory-mapped rows, and agreement.py scores the clone on them."""
    logs, _, _ = built
    data = tmp_path / "ds"
    build(logs, data, observation=["planes", "analysis"])
    out = tmp_path / "out"
    config = TRAIN / "configs" / "from_logs.toml"

    def script(*args):
        done = train(*args)
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout

    trained = script("bc.py", "--config", config, "--data", data, "--out", out)
    rows = len(Dataset(data))
    assert f"'samples': {rows}," in trained and (out / "bc.pt").exists()
    report = json.loads(script("agreement.py", out / "bc.pt", data))
    assert report["rows"] == rows
    kinds = report["by_kind"]
    assert sum(k["rows"] for k in kinds.values()) == rows
    # Every row counted once: the overall figure is the kinds' figures weighted by their rows.
    weighted = sum(k["rows"] * k["agreement"] for k in kinds.values()) / rows
    assert abs(weighted - report["agreement"]) < 1e-9
    assert {"discard", "pass"} <= set(kinds) and 0.0 < report["agreement"] <= 1.0


def test_a_three_player_log_makes_a_sanma_dataset(tmp_path, cli):
    # A red dataset leaves the sanma game out; a sanma one keeps its rows, mask 82 wide.
    red = build(SANMA, tmp_path / "red", observation=None)
    assert red["games"] == 0 and "played under sanma" in red["skipped"][0][1]
    out = tmp_path / "sanma"
    summary = build(SANMA, out, observation="planes", variant="sanma")
    assert summary["games"] == 1 and summary["skipped"] == []
    ds = Dataset(out)
    assert ds.manifest["variant"] == "sanma" and ds.num_actions == 82
    rows = ds[:]
    game = rinshan.tenhou.read(SANMA[0], observation="planes")
    assert game["variant"] == "sanma"
    want = [rnd["action"][rnd["legal_action_mask"].sum(axis=1) > 1] for rnd in game["rounds"]]
    np.testing.assert_array_equal(rows["action"], np.concatenate(want))
    assert set(np.unique(rows["seat"])) == {0, 1, 2}
    (only,) = list(iterate(SANMA, observation=None, variant="sanma"))
    assert only["ranks"] == list(rows["ranks"][0]) and only["ranks"][3] == 3
    assert rows["scores"][0][:3].sum() == 105_000 and sorted(rows["ranks"][0][:3]) == [0, 1, 2]
    # The CLI makes the same bytes.
    mine = tmp_path / "cli"
    cmd = [cli, "dataset", str(SANMA[0]), "-o", str(mine), "--observe", "planes"]
    done = subprocess.run([*cmd, "--variant", "sanma", "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    for f in sorted(out.rglob("*")):
        if f.is_file():
            assert (mine / f.relative_to(out)).read_bytes() == f.read_bytes(), f
    with pytest.raises(ValueError, match="variant"):
        build(SANMA, tmp_path / "bad", variant="nine-player")
    if HAVE_TORCH:
        # The training example reads it in the nets' layout, kita included, the same actions.
        sys.path.insert(0, str(TRAIN))
        from collect import Rows
        from common import ACTIONS

        _, _, mask, action = Rows(out).take(np.arange(len(ds)))
        assert mask.shape == (len(ds), len(ACTIONS))
        assert [ACTIONS[a] for a in action] == [ds.actions[a] for a in rows["action"]]
        for m, want in zip(mask, rows["legal_action_mask"]):
            assert sorted(ACTIONS[a] for a in np.flatnonzero(m)) == sorted(
                ds.actions[a] for a in np.flatnonzero(want)
            )
        assert mask[:, ACTIONS.index("kita")].any()


def test_a_game_in_two_formats_is_kept_once(tmp_path):
    # tests/data/mjlog holds each four-player game as mjlog XML and as tenhou.net/6 JSON.
    logs = tmp_path / "logs"
    logs.mkdir()
    for p in MJLOG[:2]:
        for twin in (p, p.with_suffix(".json")):
            (logs / twin.name).write_bytes(twin.read_bytes())
    summary = build([logs], tmp_path / "ds", observation=None)
    assert summary["inputs"] == 4 and summary["games"] == 2, summary
    assert [(pathlib.Path(a).name, pathlib.Path(b).name) for a, b in summary["duplicates"]] == [
        (p.name, p.with_suffix(".json").name) for p in MJLOG[:2]
    ]
    assert summary["skipped"] == []


def test_look_ahead_labels_are_tenhou_reads_and_distil_through_bc(tmp_path):
    """`search=` labels each row with the look-ahead's action, the one rinshan.tenhou.read gives
    at the same decision, and its values of the actions it played out; bc.py learns those labels
    (`[bc] target = "search_action"`), starting from a trained net (`[bc] init`)."""
    spec = "search:rollouts=8:focus=all"
    data = tmp_path / "ds"
    build(TENHOU[0], data, observation=["planes", "analysis"], forced=True, search=spec)
    ds = Dataset(data)
    rows = ds[:]
    read = rinshan.tenhou.read(TENHOU[0], search=spec)
    want = np.concatenate([r["search_action"] for r in read["rounds"]])
    np.testing.assert_array_equal(rows["search_action"], want)
    values = rows["search_value"]
    assert values.shape == rows["legal_action_mask"].shape and values.dtype == np.float32
    valued = ~np.isnan(values).all(1)
    assert 0 < valued.sum() < len(ds)
    # Values only for legal actions, the label's among them, each minus an expected place.
    assert not (~np.isnan(values) & ~rows["legal_action_mask"]).any()
    assert not np.isnan(values[valued, rows["search_action"][valued]]).any()
    assert np.nanmin(values) >= -3 and np.nanmax(values) <= 0
    assert (
        next(iterate(TENHOU[0], observation=None, forced=True, search=spec))["search_action"].shape
        == want.shape
    )
    with pytest.raises(ValueError, match="rollouts"):
        build(TENHOU[0], tmp_path / "bad", search="search:rollouts=x")
    if not HAVE_TORCH:
        return
    config = TRAIN / "configs" / "from_logs.toml"

    def bc(*sets):
        args = ["bc.py", "--config", config, "--data", data, "--out", tmp_path / "out"]
        for s in sets:
            args += ["--set", s]
        return train(*args)

    first = bc()
    assert first.returncode == 0, first.stderr
    start = tmp_path / "start.pt"
    (tmp_path / "out" / "bc.pt").rename(start)
    distilled = bc('bc.target="search_action"', f'bc.init="{start}"')
    assert distilled.returncode == 0, distilled.stderr
    assert f"'samples': {len(ds)}," in distilled.stdout
    # agreement.py scores the distilled net on the rows bc.py held out (bc.py's seed, 0): its
    # agreement with the look-ahead there is bc.py's last validation accuracy, to the last digit.
    scored = train("agreement.py", tmp_path / "out" / "bc.pt", data, "--held-out", "0")
    assert scored.returncode == 0, scored.stderr
    report = json.loads(scored.stdout)
    assert report["held_out"] == 0 and report["rows"] == max(1, len(ds) // 10)
    accuracy = re.search(r"'val_accuracy': ([0-9.e-]+)", distilled.stdout)
    assert accuracy and report["look_ahead"]["agreement"] == float(accuracy.group(1))
    la = report["look_ahead"]
    assert (rows["search_action"] != rows["action"]).any() and 0 < la["differ"] <= report["rows"]
    assert la["takes_look_ahead"] + la["takes_log"] <= 1.0
    valued = bc('bc.target="search_value"', "bc.temperature=0.02", f'bc.init="{start}"')
    assert valued.returncode == 0, valued.stderr
    assert f"'samples': {len(ds)}," in valued.stdout
    cold = bc('bc.target="search_value"', "bc.temperature=0")
    assert cold.returncode != 0 and "temperature" in cold.stderr
    plain = tmp_path / "plain"
    build(TENHOU[0], plain, observation=["planes", "analysis"])
    refused = train(
        "bc.py",
        "--config",
        config,
        "--data",
        plain,
        "--out",
        tmp_path / "x",
        "--set",
        'bc.target="search_action"',
    )
    assert refused.returncode != 0 and "--search" in refused.stderr


@needs_torch
def test_values_teach_their_softmax_where_the_look_ahead_played_out():
    """bc.py's `search_value` target: softmax(value / temperature) over the actions played out,
    nothing on the rest; a row the look-ahead left alone teaches its label alone."""
    sys.path.insert(0, str(TRAIN))
    from collect import value_targets

    nan = np.nan
    values = np.array([[nan, -1.0, -1.1, nan], [nan] * 4, [-2.0, nan, nan, nan]], np.float32)
    got = value_targets(values, np.array([1, 3, 0]), 0.1)
    p = 1 / (1 + np.exp(-1.0))  # two actions 0.1 places apart at temperature 0.1
    np.testing.assert_allclose(got[0], [0, p, 1 - p, 0], rtol=1e-6)
    np.testing.assert_array_equal(got[1:], [[0, 0, 0, 1], [1, 0, 0, 0]])
    sharp = value_targets(values[:1], np.array([2]), 1e-4)
    np.testing.assert_allclose(sharp[0], [0, 1, 0, 0], atol=1e-6)
