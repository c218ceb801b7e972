"""The look-ahead's judgements from Python: a review is the one the CLI prints for the same log,
seat and budget; the outlook matches the closed form for a tenpai hand; bad input is a
ValueError."""

import json
import math
import pathlib
import subprocess

import pytest

import rinshan

LOG = (
    pathlib.Path(__file__).resolve().parents[2]
    / "tests/data/tenhou/2019060813gm-00a9-0000-08bb0ec3.json"
)


def test_a_review_is_the_one_the_cli_prints(cli):
    budget = "search:rollouts=32:seed=4"
    ours = rinshan.review(LOG, player="Aさん", round=0, search=budget)
    out = subprocess.run(
        [cli, "review", str(LOG), "--seat", "0", "--round", "0", "--search", budget, "--json"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    assert ours == json.loads(out)
    assert ours["seat"] == 0 and ours["game"]["decisions"] == len(ours["decisions"]) >= 10
    for d in ours["decisions"]:
        assert d["played"] in [c["action"] for c in d["candidates"]]


def test_review_errors_are_value_errors():
    with pytest.raises(ValueError, match="no player `nobody`"):
        rinshan.review(LOG, player="nobody")
    with pytest.raises(ValueError, match="needs a budget"):
        rinshan.review(LOG, seat=0, search="search:rollouts=0")
    with pytest.raises(ValueError, match="not both"):
        rinshan.review(LOG, seat=0, player="Aさん")
    with pytest.raises(ValueError, match="seats 0..3"):
        rinshan.review(LOG, seat=7)


def test_outlook_matches_the_closed_form():
    # Tenpai on 3p/6p after the 9s: 8 winning tiles among the 122 unseen, 12 draws.
    odds = rinshan.outlook("123456789m1145p9s", draws=12, trials=6000, seed=3)
    best = odds["discards"][0]
    assert (best["discard"], best["shanten"], best["trials"]) == ("9s", 0, 6000)
    exact = 1 - math.comb(114, 12) / math.comb(122, 12)
    assert abs(best["win"][11] - exact) < 4 * math.sqrt(exact * (1 - exact) / 6000)
    # Seeing the four 3p and three 6p leaves one winning tile.
    fewer = rinshan.outlook("123456789m1145p9s", seen="3333666p", draws=12, trials=6000)
    assert fewer["discards"][0]["win"][11] < best["win"][11] / 3


def test_outlook_errors_are_value_errors():
    with pytest.raises(ValueError, match="3k\\+2"):
        rinshan.outlook("123m")
    with pytest.raises(ValueError, match="only 4"):
        rinshan.outlook("123456789m1145p9s", seen="99999s")
    with pytest.raises(ValueError, match="at least 1"):
        rinshan.outlook("123456789m1145p9s", trials=0)
