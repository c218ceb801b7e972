"""A player's decisions in a logged game judged by the look-ahead (`rinshan review`)."""

from __future__ import annotations

import json
import os
from typing import Optional, Union

from . import _core


def review(
    log: Union[str, os.PathLike],
    *,
    seat: Optional[int] = None,
    player: Optional[str] = None,
    round: Optional[int] = None,
    search: str = "search:rollouts=1024",
) -> dict:
    """Reviews one player's decisions in the log at `log` (tenhou.net/6, MJAI or mjlog, plain or
    gzipped), chosen by `seat` (0 = East 1's dealer) or by the `player`'s name, as
    `rinshan review --json` does: for every decision with a choice, each legal action's value in
    expected final places with its standard error, the action played, the best other one and the
    loss against it, whether it is a mistake (the loss two standard errors above zero); totals per
    round and for the game (`"game"`: decisions, mistakes, agreement, loss, edge). `round` limits
    it to one round (an index into the log's rounds); `search` sets the judging look-ahead's
    budget and seed (`"search:rollouts=4096:seed=2"`). Raises ValueError for a log it cannot read
    or a seat or player the game does not have."""
    return json.loads(_core.review(os.fspath(log), seat, player, round, search))
