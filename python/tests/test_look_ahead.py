"""The look-ahead from Python: as the env's opponents it plays the games of its base agent when it
is never sure enough to differ; a review is the one the CLI prints for the same log, seat and
budget; it plays every decision of a real log legally and takes the wins its players took; the
outlook matches the closed form for a tenpai hand; bad input is a ValueError."""

import json
import math
import pathlib
import subprocess

import numpy as np
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


def test_the_look_ahead_plays_the_decisions_of_a_real_log():
    budget = "search:rollouts=32:seed=4"
    game = rinshan.tenhou.read(LOG, observation=(), search=budget)
    names = rinshan.make("red").spec.action_names
    wins = looked = 0
    for r in game["rounds"][:3]:
        chosen = r["search_action"]
        assert chosen.shape == r["action"].shape
        # Every choice is legal where it was asked, from the deciding seat's own view.
        assert r["legal_action_mask"][np.arange(len(chosen)), chosen].all()
        # Where the player won, taking the win is what the look-ahead does too.
        for a, c in zip(r["action"], chosen):
            if names[a] in ("tsumo", "ron"):
                wins += 1
                assert c == a
        looked += len(chosen)
    assert wins >= 1 and looked >= 100
    # The same log and settings give the same actions.
    again = rinshan.tenhou.read(LOG, observation=(), search=budget)
    for a, b in zip(game["rounds"], again["rounds"]):
        assert (a["search_action"] == b["search_action"]).all()
    # Without `search` the records are as they were.
    assert "search_action" not in rinshan.tenhou.read(LOG, observation=())["rounds"][0]
    with pytest.raises(ValueError, match="unknown search option"):
        rinshan.tenhou.read(LOG, search="search:depth=3")


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


def finals(env, seeds):
    """Plays every env's game to its end, the hero by the greedy agent; the final scores and how
    many steps were the hero's."""
    ts = env.reset(seeds=seeds)
    done = np.zeros(env.num_envs, dtype=bool)
    scores = np.zeros((env.num_envs, 4), dtype=np.int64)
    hero_steps = 0
    for _ in range(100_000):
        ts = env.step(env.agent_actions("greedy"))
        hero_steps += int((ts.info["hero"] & ~done).sum())
        idx = np.flatnonzero(ts.terminated & ~done)
        scores[idx] = ts.info["final_scores"][idx]
        done[idx] = True
        if done.all():
            return scores, hero_steps
    raise AssertionError("the games did not end")


def test_search_opponents_play_their_base_agents_games_when_never_sure():
    # A margin no estimate reaches: every own-turn decision is looked ahead at (play-outs run),
    # and the base agent's action is played each time, so the games are those of hero mode
    # against the base agent itself.
    seeds = [3, 4, 5]
    common = dict(mode="east", num_envs=3, auto_reset=False, hero_seats=[0, 1, 2], observation=())
    builtin, _ = finals(rinshan.make("red", opponents="defensive", **common), seeds)
    sure_never = "search:rollouts=4:margin=1000000:focus=all"
    searched, hero = finals(rinshan.make("red", opponents=sure_never, **common), seeds)
    assert (searched == builtin).all()
    assert hero > 0
    # The default look-ahead plays whole games too, three players as well.
    env = rinshan.make("sanma", opponents="search:rollouts=16", **{**common, "hero_seats": 2})
    scores, _ = finals(env, seeds)
    assert (scores[:, :3].sum(axis=1) == 105_000).all()
    with pytest.raises(ValueError, match="cannot restore states"):
        env.set_state(env.get_state())


def test_search_opponent_settings_are_checked():
    with pytest.raises(ValueError, match="unknown search option"):
        rinshan.make("red", opponents="search:depth=3", hero_seats=0)
    with pytest.raises(ValueError, match="needs a budget"):
        rinshan.make("red", opponents="search:rollouts=0", hero_seats=0)


def test_env_outlook_is_the_seat_to_acts_at_its_own_turn():
    env = rinshan.make("red", num_envs=2, seed=5)
    ts = env.reset()
    odds = env.outlook(1, trials=800, seed=2)
    # The dealer's first turn: 69 live tiles left, a quarter of them (rounded up) its draws.
    assert odds["draws"] == 18
    hand = [n for n in env.spec.action_names if n.startswith("discard_")]
    legal = {
        hand[a][len("discard_") :] for a in np.flatnonzero(ts.legal_action_mask[1][: len(hand)])
    }
    offered = {d["discard"] for d in odds["discards"]}
    assert {t.replace("0", "5") for t in legal} <= offered
    assert odds == env.outlook(1, trials=800, seed=2)
    with pytest.raises(ValueError, match="does not exist"):
        env.outlook(2)
    # At a claim prompt there is no discard to weigh.
    pass_id = env.spec.action_names.index("pass")
    for _ in range(2000):
        if ts.legal_action_mask[0][pass_id]:
            break
        ts = env.step(env.agent_actions("rule"))
    assert ts.legal_action_mask[0][pass_id], "no claim prompt in 2000 steps"
    assert env.outlook(0) is None
