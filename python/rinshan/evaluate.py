"""Duplicate evaluation of a policy against the other seats' opponents (three, or two in a
three-player variant): built-in agents or another policy."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Callable, Union

import numpy as np

from . import _core
from .env import Env, TimeStep

Policy = Union[str, Callable[[TimeStep], np.ndarray]]


@dataclasses.dataclass
class Evaluation:
    """A policy's results over duplicate games (each wall set played from every seat)."""

    games: int
    average_rank: float
    """Mean final place, 1 (first) to 4."""
    ci95: float
    """Half-width of the 95% interval of `average_rank`, over wall sets (Student's t with one
    degree of freedom fewer than the sets: wide for a few sets, as it should be). NaN with one
    wall set, which gives no interval: play at least two sets (games = 2 x seats)."""
    rank_counts: list
    """Games finished first, second, third and fourth."""
    average_score: float
    illegal: int
    """Games the policy ended with an illegal action (each counted as a last place)."""
    opponent_faults: int = 0
    """Games an MJAI opponent lost by failing (the policy placed among the others by score)."""

    def __str__(self) -> str:
        interval = (
            f" ± {self.ci95:.3f}"
            if math.isfinite(self.ci95)
            else " (one wall set: n too small for an interval)"
        )
        return (
            f"average rank {self.average_rank:.3f}{interval} over {self.games} games "
            f"(places {self.rank_counts}, average score {self.average_score:.0f}, "
            f"illegal {self.illegal}"
            + (f", opponent faults {self.opponent_faults}" if self.opponent_faults else "")
            + ")"
        )


def evaluate(
    policy: Policy,
    opponents: Policy = "rule",
    games: int = 1000,
    seed: int = 0,
    variant: str = "red",
    mode: str = "half",
    observation: Sequence[str] = ("planes",),
    analysis: bool = False,
    num_threads=None,
) -> Evaluation:
    """Plays `policy` against `opponents` in the other seats over `games` games (rounded up to a
    multiple of the seats, 4 or 3): each set of walls is played once with the policy in each seat.

    `policy` and `opponents` are each a built-in agent's name or a function from the TimeStep
    (observation of each env's current player and its legal mask) to one action per env; only the
    rows of envs where that side is to act are used. Built-in opponents play inside `step` (hero
    mode); `"mjai:COMMAND"` seats an MJAI bot (one process per seat and game, asked inside
    `step`; keep `games` to a few hundred); a function as opponents is called for every decision
    the policy does not make.
    """
    if games < 1:
        raise ValueError("games must be at least 1")
    players = _core.variant_info(variant)[3]
    sets = math.ceil(games / players)
    n = sets * players
    builtin = isinstance(opponents, str)
    hero = np.tile(np.arange(players), sets)
    env = Env(
        variant,
        mode=mode,
        num_envs=n,
        observation=observation,
        analysis=analysis,
        auto_reset=False,
        opponents=opponents if builtin else None,
        hero_seats=hero if builtin else None,
        seed=seed,
        num_threads=num_threads,
    )
    set_seeds = np.random.SeedSequence(seed).generate_state(sets, np.uint64)
    ts = env.reset(seeds=np.repeat(set_seeds, players))
    rank = np.full(n, -1)
    score = np.zeros(n)
    illegal = np.zeros(n, dtype=bool)
    finished = np.zeros(n, dtype=bool)
    bot_faults = np.zeros(n, dtype=bool)
    while not finished.all():
        actions = _act(policy, env, ts)
        # In hero mode the env says which decisions are the policy's (a bot's are played inside
        # `step`); otherwise the seat tells whose.
        own = ts.info["hero"].copy() if builtin else ts.current_player == hero
        actor = ts.current_player.copy()
        if not builtin and not own.all():
            actions = np.where(own, actions, _act(opponents, env, ts))
        ts = env.step(actions)
        idx = np.nonzero(ts.terminated & ~finished)[0]
        finished[idx] = True
        rank[idx] = ts.info["final_rank"][idx, hero[idx]]
        score[idx] = ts.info["final_scores"][idx, hero[idx]]
        bad = ts.info["illegal"][idx]
        theirs = idx[bad & ~own[idx]]
        if len(theirs) and not (builtin and opponents.startswith("mjai:")):
            env.close()
            raise ValueError("the opponents function played an illegal action")
        for i in theirs:
            # A failed bot places last, the others in their order of the moment.
            scores = ts.info["final_scores"][i]
            others = [q for q in range(players) if q not in (hero[i], actor[i])]
            rank[i] = sum(scores[q] > scores[hero[i]] for q in others)
            bot_faults[i] = True
        illegal[idx] = bad & own[idx]
    env.close()
    # A game the policy ended with an illegal action counts as a last place.
    places = np.where(illegal, players, rank + 1)
    per_set = places.reshape(sets, players).mean(axis=1)
    # The sets' spread is estimated from the sets themselves: with few of them the normal 1.96
    # understates the interval (by 3x at two sets), and one set estimates no spread at all.
    ci = t975(sets - 1) * per_set.std(ddof=1) / math.sqrt(sets) if sets > 1 else math.nan
    return Evaluation(
        games=n,
        average_rank=float(places.mean()),
        ci95=float(ci),
        rank_counts=[int((places == k).sum()) for k in range(1, players + 1)],
        average_score=float(score.mean()),
        illegal=int(illegal.sum()),
        opponent_faults=int(bot_faults.sum()),
    )


# Student's t 0.975 quantiles for 1..30 degrees of freedom (any statistics table).
_T975 = (
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
    2.201, 2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
    2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042,
)  # fmt: skip


def t975(df: int) -> float:
    """The 0.975 quantile of Student's t with `df` degrees of freedom (a 95% interval's
    multiplier): the table to 30, then the Cornish-Fisher expansion about the normal's 1.96,
    within 1e-4 of the exact value there. Without scipy, which the package does not need."""
    if df < 1:
        raise ValueError("a t quantile needs at least one degree of freedom")
    if df <= len(_T975):
        return _T975[df - 1]
    z = 1.959963984540054
    return z + (z**3 + z) / (4 * df) + (5 * z**5 + 16 * z**3 + 3 * z) / (96 * df**2)


def _act(policy: Policy, env: Env, ts: TimeStep) -> np.ndarray:
    if isinstance(policy, str):
        return env.agent_actions(policy)
    return np.asarray(policy(ts))
