"""Game logs (tenhou.net/6 JSON, or MJAI: the reader tells them apart) as records for supervised
learning, and replay checks."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Optional, Union

from . import _core
from .env import split_record


def read(
    path: str,
    observation: Union[str, Sequence[str]] = ("planes",),
    search: Optional[str] = None,
) -> dict:
    """Every decision of every round of the log at `path`, replayed under its rule set (`red` for
    Tenhou's logs; a log rinshan wrote for another rule set names it).

    Returns `{"path", "rule", "red_fives", "variant", "names", "rounds"}`; each round has `kyoku`,
    `honba`, `sticks`, `scores`, and per decision (claim prompts included) `seat`, `action` (the id
    the player chose, in the variant's action layout), `what` (the log's move), `legal_action_mask`
    and `observation` (the deciding seat's view, one dict of arrays per decision axis). A round
    that cannot be replayed has `error` instead of the decisions.

    With `search` (`"search"`, or with its settings: `"search:rollouts=1024:seed=2"`), each round
    also has `search_action`: at every decision, the action the look-ahead agent plays there from
    the deciding seat's view (what it saw and drew, never the log's hidden tiles), its base agent's
    where it does not look ahead. The same log and settings give the same actions. Raises
    ValueError for settings it cannot read.
    """
    forms = [observation] if isinstance(observation, str) else list(observation)
    game = _core.tenhou_read(str(path), forms, search)
    for r in game["rounds"]:
        if "observation" in r:
            merged = {}
            for form, raw in r["observation"].items():
                for k, v in split_record(raw, form).items():
                    merged.setdefault(k, v)
            r["observation"] = merged
    return game


def replay(
    paths: Union[str, Sequence[str]], backend: str = "cpu", variant: Optional[str] = None
) -> dict:
    """Replays logs (files or folders) and compares every round with the log: counts of what
    agrees (`all_agree`) and every mismatch as text. Each log is played under the rule set it
    names (red unless rinshan wrote it or an MJAI `start_game` names one), or under `variant`
    when given (e.g. Mahjong Soul games converted to tenhou.net/6: `variant="mjsoul"`). Wins
    whose log gives no yaku (libriichi's MJAI) count in `wins_yaku_not_logged`, not
    `wins_matching`."""
    if isinstance(paths, str):
        paths = [paths]
    return _core.replay([str(p) for p in paths], backend, variant)
