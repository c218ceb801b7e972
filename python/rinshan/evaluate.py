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
    """Half-width of the 95% interval of `average_rank`, over wall sets."""
    rank_counts: list
    """Games finished first, second, third and fourth."""
    average_score: float
    illegal: int
    """Games the policy ended with an illegal action (each counted as a last place)."""
    opponent_faults: int = 0
    """Games an MJAI opponent lost by failing (the policy placed among the others by score)."""

    def __str__(self) -> str:
        return (
            f"average rank {self.average_rank:.3f} ± {self.ci95:.3f} over {self.games} games "
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
    ci = 1.96 * per_set.std(ddof=1) / math.sqrt(sets) if sets > 1 else float("inf")
    return Evaluation(
        games=n,
        average_rank=float(places.mean()),
        ci95=float(ci),
        rank_counts=[int((places == k).sum()) for k in range(1, players + 1)],
        average_score=float(score.mean()),
        illegal=int(illegal.sum()),
        opponent_faults=int(bot_faults.sum()),
    )


def _act(policy: Policy, env: Env, ts: TimeStep) -> np.ndarray:
    if isinstance(policy, str):
        return env.agent_actions(policy)
    return np.asarray(policy(ts))
