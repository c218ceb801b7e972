"""MJAI logs from Python: the same games and decision records as their tenhou.net/6 form."""

import gzip
import subprocess

import numpy as np
import pytest

import rinshan


def test_an_mjai_log_gives_the_records_of_its_tenhou_form(log_path, tmp_path):
    mjai_text = rinshan.mjai.convert(log_path, to="mjai")
    assert mjai_text.splitlines()[0].startswith('{"type":"start_game"')
    path = tmp_path / "game.mjson.gz"
    path.write_bytes(gzip.compress(mjai_text.encode()))
    # Back to tenhou.net/6: the real file's own lines.
    with open(log_path, encoding="utf-8") as f:
        original = [line for line in f.read().splitlines() if line.strip()]
    assert rinshan.mjai.convert(path, to="tenhou").splitlines() == original
    want = rinshan.tenhou.read(log_path, observation=("planes",))
    got = rinshan.mjai.read(path, observation=("planes",))
    assert len(got["rounds"]) == len(want["rounds"]) > 0
    for a, b in zip(got["rounds"], want["rounds"]):
        assert "error" not in a
        assert a["action"].tolist() == b["action"].tolist()
        assert (a["legal_action_mask"] == b["legal_action_mask"]).all()
        for name, values in b["observation"].items():
            assert np.array_equal(a["observation"][name], values), name


def test_selfplay_exports_mjai_that_reads_as_the_same_games(cli, tmp_path):
    args = "selfplay --agents rule,greedy,defensive,random --batch 2 --games 2 --seed 3 --threads 1"
    for fmt in ("tenhou", "mjai"):
        out = tmp_path / fmt
        subprocess.run(
            [cli, *args.split(), "--export", str(out), "--export-format", fmt],
            check=True,
            capture_output=True,
        )
    tenhou_games = sorted((tmp_path / "tenhou").glob("game-*.json"))
    mjai_games = sorted((tmp_path / "mjai").glob("game-*.mjson"))
    assert len(tenhou_games) == len(mjai_games) == 2
    for t, m in zip(tenhou_games, mjai_games):
        assert rinshan.mjai.convert(m, to="tenhou") == t.read_text(encoding="utf-8")
    report = rinshan.replay([str(tmp_path / "mjai")])
    assert report["all_agree"], report


def test_bad_mjai_is_a_value_error(tmp_path):
    bad = tmp_path / "bad.mjson"
    bad.write_text('{"type":"start_game"}\n{"type":"start_kyoku","bakaze":"X"}\n')
    with pytest.raises(ValueError, match="bad.mjson: line 2"):
        rinshan.mjai.read(bad)
    with pytest.raises(ValueError, match="'tenhou' or 'mjai'"):
        rinshan.mjai.convert(bad, to="xml")
