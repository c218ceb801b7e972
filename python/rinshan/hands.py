"""The hand calculator (`rinshan shanten`, `rinshan score`)."""

from __future__ import annotations

import json
from collections.abc import Sequence
from typing import Optional

from . import _core

FLAGS = (
    "tsumo",
    "riichi",
    "double_riichi",
    "ippatsu",
    "haitei",
    "houtei",
    "rinshan",
    "chankan",
    "tenhou",
    "chiihou",
    "dealer",
)


def shanten(hand: str) -> dict:
    """Shanten of a concealed hand in notation, e.g. `shanten("123m456p789s1122z")`:
    `{"shanten", "normal", "chiitoitsu", "kokushi"}` (-1 = complete)."""
    return _core.shanten(hand)


def score(
    hand: str,
    win: str,
    *,
    variant: str = "red",
    round_wind: str = "E",
    seat_wind: Optional[str] = None,
    dora: Optional[str] = None,
    ura: Optional[str] = None,
    melds: Sequence[str] = (),
    honba: int = 0,
    sticks: int = 0,
    **flags: bool,
) -> dict:
    """Scores a winning hand as `rinshan score --json` does, e.g.
    `score("234567m234p4566s", "6s", tsumo=True, riichi=True)`. Flags: tsumo, riichi,
    double_riichi, ippatsu, haitei, houtei, rinshan, chankan, tenhou, chiihou, dealer; melds like
    "chi:123m", "pon:555z", "kan:2222p", "ankan:1111s", "kakan:3333m"."""
    unknown = [f for f in flags if f not in FLAGS]
    if unknown:
        raise TypeError(f"unknown flag(s) {unknown}: choose from {FLAGS}")
    on = [f for f, v in flags.items() if v]
    return json.loads(
        _core.score(
            variant, hand, win, on, round_wind, seat_wind, dora, ura, list(melds), honba, sticks
        )
    )
