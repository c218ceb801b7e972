"""Duplicate evaluation of a policy against three opponents: built-in agents or another policy."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Callable, Union

import numpy as np

from .env import Env, TimeStep

Policy = Union[str, Callable[[TimeStep], np.ndarray]]


@dataclasses.dataclass
class Evaluation:
    """A policy's results over duplicate games (each wall set played from all four seats)."""

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

    def __str__(self) -> str:
        return (
            f"average rank {self.average_rank:.3f} ± {self.ci95:.3f} over {self.games} games "
            f"(places {self.rank_counts}, average score {self.average_score:.0f}, "
            f"illegal {self.illegal})"
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
    """Plays `policy` against three `opponents` over `games` games (rounded up to a multiple of
    4): each set of walls is played four times with the policy in each seat.

    `policy` and `opponents` are each a built-in agent's name or a function from the TimeStep
    (observation of each env's current player and its legal mask) to one action per env; only the
    rows of envs where that side is to act are used. Built-in opponents play inside `step` (hero
    mode); a function as opponents is called for every decision the policy does not make.
    """
    if games < 1:
        raise ValueError("games must be at least 1")
    sets = math.ceil(games / 4)
    n = sets * 4
    builtin = isinstance(opponents, str)
    hero = np.tile(np.arange(4), sets)
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
    ts = env.reset(seeds=np.repeat(set_seeds, 4))
    rank = np.full(n, -1)
    score = np.zeros(n)
    illegal = np.zeros(n, dtype=bool)
    finished = np.zeros(n, dtype=bool)
    while not finished.all():
        actions = _act(policy, env, ts)
        # In hero mode every decision returned is the policy's; otherwise the seat tells whose.
        own = np.ones(n, dtype=bool) if builtin else ts.current_player == hero
        if not builtin and not own.all():
            actions = np.where(own, actions, _act(opponents, env, ts))
        ts = env.step(actions)
        idx = np.nonzero(ts.terminated & ~finished)[0]
        finished[idx] = True
        rank[idx] = ts.info["final_rank"][idx, hero[idx]]
        score[idx] = ts.info["final_scores"][idx, hero[idx]]
        bad = ts.info["illegal"][idx]
        if (bad & ~own[idx]).any():
            env.close()
            raise ValueError("the opponents function played an illegal action")
        illegal[idx] = bad
    env.close()
    # A game the policy ended with an illegal action counts as a last place.
    places = np.where(illegal, 4, rank + 1)
    per_set = places.reshape(sets, 4).mean(axis=1)
    ci = 1.96 * per_set.std(ddof=1) / math.sqrt(sets) if sets > 1 else float("inf")
    return Evaluation(
        games=n,
        average_rank=float(places.mean()),
        ci95=float(ci),
        rank_counts=[int((places == k).sum()) for k in range(1, 5)],
        average_score=float(score.mean()),
        illegal=int(illegal.sum()),
    )


def _act(policy: Policy, env: Env, ts: TimeStep) -> np.ndarray:
    if isinstance(policy, str):
        return env.agent_actions(policy)
    return np.asarray(policy(ts))
