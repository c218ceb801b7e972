"""MJAI bots as the env's opponents (`opponents="mjai:COMMAND"`): the bot plays every seat but
the hero's, asked inside `step`. `rinshan mjai-bot --agent defensive` plays exactly as the built-in
defensive agent, so games against it through MJAI are the games of hero mode against the built-in
agent; a failing bot loses its game by the penalty with a warning; bad settings raise."""

import pathlib
import warnings

import numpy as np
import pytest

import rinshan

ROOT = pathlib.Path(__file__).resolve().parents[2]
SIMPLE = ROOT / "tests" / "data" / "mjai" / "bots" / "simple_bot.py"


def finals(env, seeds):
    """Plays every env's game to its end, the hero by the greedy agent; the final scores."""
    ts = env.reset(seeds=seeds)
    done = np.zeros(env.num_envs, dtype=bool)
    scores = np.zeros((env.num_envs, 4), dtype=np.int64)
    for _ in range(100_000):
        ts = env.step(env.agent_actions("greedy"))
        idx = np.flatnonzero(ts.terminated & ~done)
        scores[idx] = ts.info["final_scores"][idx]
        done[idx] = True
        if done.all():
            return scores
    raise AssertionError("the games did not end")


@pytest.mark.parametrize("dialect", ["app", "stdio"])
def test_a_bot_opponent_plays_the_games_of_the_built_in_agent(cli, dialect):
    seeds = [3, 4, 5, 6]
    hero = [0, 1, 2, 3]
    common = dict(mode="east", num_envs=4, auto_reset=False, hero_seats=hero, observation=())
    builtin = finals(rinshan.make("red", opponents="defensive", **common), seeds)
    bot = f"mjai:{cli} mjai-bot --agent defensive --dialect {dialect}"
    env = rinshan.make("red", opponents=bot, mjai_dialect=dialect, **common)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mjai = finals(env, seeds)
    env.close()
    np.testing.assert_array_equal(mjai, builtin)


def test_evaluate_takes_a_bot_as_opponents(cli):
    bot = f"mjai:{cli} mjai-bot --agent defensive"
    kw = dict(games=4, mode="east", seed=2, observation=())
    assert str(rinshan.evaluate("greedy", opponents=bot, **kw)) == str(
        rinshan.evaluate("greedy", opponents="defensive", **kw)
    )


def test_a_bot_opponent_sits_at_three_player_tables():
    # The stdlib bot at the two seats beside each env's hero: every game plays to its end with
    # no failure (a warning would raise here), and the fourth place stays empty.
    env = rinshan.make(
        "sanma",
        mode="east",
        num_envs=3,
        auto_reset=False,
        hero_seats=[0, 1, 2],
        observation=(),
        opponents=f"mjai:python3 {SIMPLE} --dialect stdio",
        mjai_dialect="stdio",
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scores = finals(env, [7, 8, 9])
    env.close()
    assert (scores[:, 3] == 0).all() and (scores.sum(axis=1) == 105_000).all()


def dying_bot_env():
    """Two east games against a bot that fails at its third decision."""
    return rinshan.make(
        "red",
        mode="east",
        num_envs=2,
        observation=(),
        auto_reset=False,
        opponents=f"mjai:python3 {SIMPLE} --dialect app --mode die",
    )


def test_a_failing_bot_loses_its_game_with_a_warning():
    env = dying_bot_env()
    ts = env.reset(seeds=[1, 2])
    lost = np.zeros(2, dtype=bool)
    with pytest.warns(RuntimeWarning, match="dying on purpose"):
        for _ in range(10_000):
            ts = env.step(np.argmax(ts.legal_action_mask, axis=1))
            lost |= ts.info["illegal"]
            if ts.terminated.all():
                break
    # Each game ended at its bot's third decision, by the penalty.
    assert ts.terminated.all() and lost.all()
    env.close()


def test_a_failure_raised_as_an_error_still_takes_the_step():
    # Where warnings are errors the step raises, but only after the step is taken: the failing
    # bot's game ends by the penalty, as it does when the warning is only shown.
    env = dying_bot_env()
    ts = env.reset(seeds=[1, 2])
    lost = np.zeros(2, dtype=bool)
    raised = 0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for _ in range(10_000):
            try:
                ts = env.step(np.argmax(ts.legal_action_mask, axis=1))
            except RuntimeWarning as e:
                assert "dying on purpose" in str(e)
                raised += 1
                ts = env.timestep
                # The step that raised was taken: the failing bot's illegal action is in it.
                assert ts.info["illegal"].any()
            lost |= ts.info["illegal"]
            if ts.terminated.all():
                break
    assert raised >= 1 and ts.terminated.all() and lost.all()
    env.close()


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(opponents="mjai:"), "needs the bot's command line"),
        (dict(opponents="mjai:x", variant="no-red"), "Tenhou's rules"),
        (dict(opponents="mjai:x", mode="single"), "east or half"),
        (dict(opponents="mjai:x", num_envs=300), "at most 256 envs"),
        (dict(opponents="mjai:x", mjai_dialect="tcp"), "unknown MJAI dialect"),
        (dict(opponents="mjai:x", mjai_timeout=0), "mjai_timeout 0"),
    ],
)
def test_bad_settings_raise(kwargs, words):
    kw = dict(variant="red", num_envs=2, observation=())
    kw.update(kwargs)
    with pytest.raises(ValueError, match=words):
        rinshan.make(kw.pop("variant"), **kw)


def test_a_bot_opponent_env_restores_no_state():
    env = rinshan.make(
        "red", num_envs=1, observation=(), opponents=f"mjai:python3 {SIMPLE} --dialect app"
    )
    env.reset()
    with pytest.raises(ValueError, match="cannot restore states"):
        env.set_state(env.get_state())
    env.close()
