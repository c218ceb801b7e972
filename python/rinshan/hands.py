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


def outlook(
    hand: str, *, seen: str = "", draws: int = 12, trials: int = 10_000, seed: int = 1
) -> dict:
    """Win odds per discard, drawing alone from the tiles the seat cannot see, as
    `rinshan outlook --json` gives them: `{"draws", "discards": [{"discard", "shanten", "tenpai",
    "win", "trials"}]}`, best first, where `tenpai[k]` and `win[k]` are the chances of being tenpai
    and of having won within `k + 1` draws. `seen` holds the tiles the seat sees elsewhere
    (rivers, melds, dora indicators), which it cannot draw. Each chance `p` has the standard error
    `sqrt(p * (1 - p) / trials)`; other seats' wins and an open hand's yaku are not counted.

    >>> odds = outlook("123456789m1145p9s", draws=12, trials=2000)
    >>> best = odds["discards"][0]
    >>> best["discard"], best["shanten"], len(best["win"])
    ('9s', 0, 12)
    """
    return json.loads(_core.outlook(hand, seen, draws, trials, seed))
