"""The budget curve's script (examples/search/budget.py): it plays each budget once, keeps the
arena's report, reads the look-ahead's figures from it, and draws the figure."""

import json
import pathlib
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = REPO / "examples" / "search" / "budget.py"


def run(*args):
    return subprocess.run(
        [sys.executable, str(SCRIPT), *args], check=True, capture_output=True, text=True
    ).stdout


def test_budget_curve_plays_each_budget_once_and_draws_it(cli, tmp_path):
    cache, out = tmp_path / "cache", tmp_path / "budget.png"
    common = ["--rollouts", "4,16", "--games", "8", "--games-at", "16=4", "--mode", "single"]
    common += ["--cache", str(cache), "--out", str(out), "--threads", "1"]
    printed = run("--rinshan", cli, *common)
    assert out.stat().st_size > 0
    reports = sorted(cache.glob("*.json"))
    assert [p.name for p in reports] == [
        "search-r16-g4-s1-red-single.json",
        "search-r4-g8-s1-red-single.json",
    ]
    rows = [line for line in printed.splitlines() if line.startswith("| 4 ") or "| 16 " in line]
    assert len(rows) == 2
    for rollouts, games, report in ((4, 8, reports[1]), (16, 4, reports[0])):
        data = json.loads(report.read_text())
        mine = next(s for s in data["standings"] if s["agent"] == f"search:rollouts={rollouts}")
        row = next(r for r in rows if r.startswith(f"| {rollouts} |"))
        assert f"| {games} | {mine['mean_rank']:.3f}" in row
        search = next(s for s in data["search"] if s["agent"] == f"search:rollouts={rollouts}")
        assert 0 < search["searched"] <= search["decisions"]
        assert search["rollouts"] >= search["searched"]
    # A second run reads the reports kept: it plays nothing (the binary it is given is absent).
    again = run("--rinshan", str(tmp_path / "absent"), *common)
    assert again == printed
