"""MJAI, the protocol of Mortal, akochan and mjai.app: logs (one JSON event per line) read as
decision records with observations and converted to and from tenhou.net/6 JSON, and `Bot`, a
Python policy playing as an MJAI bot."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path
from typing import IO, Optional, Union

import numpy as np

from . import _core, tenhou
from .env import split_record


def read(path: Union[str, Path], observation: Union[str, Sequence[str]] = ("planes",)) -> dict:
    """Every decision of an MJAI log (plain or gzipped), replayed through the red variant: the
    same records as `rinshan.tenhou.read` (each decision's seat, action id, legal mask and the
    deciding seat's observation), so MJAI data feeds the same learning code."""
    return tenhou.read(str(path), observation)


def convert(path: Union[str, Path], to: str = "mjai") -> str:
    """The text of the log at `path` (either format, plain or gzipped) as `to`: "mjai" or
    "tenhou". Raises ValueError for a log that cannot be read."""
    return _core.convert_log(str(path), to)


class Bot:
    """A policy as an MJAI bot: subclass it and define `act`.

    The bot reads the host's lines, rebuilds the engine's state of its seat's decisions from what
    the seat has seen, and answers with the reaction of the action id `act` returns, given the
    same observation a `rinshan.make(...)` env gives that seat (a dict of arrays, the forms of
    `observation`) and the legal mask (a bool array over the red variant's action ids).

    `dialect` is "app" (mjai.app: a JSON array of events per line, one reaction per line) or
    "stdio" (Mortal: one event per line, a reaction when the seat can act). `seat` is the seat
    (0-3 from East 1's dealer); mjai.app passes it as the script's argument, and without it the
    `start_game` event's `id` names it. Problems (an unreadable line, a failing `act`, an
    illegal action id) go to stderr and are answered with a legal fallback: the bot always
    answers. An mjai.app submission is a `bot.py` that calls `start()`: see examples/mjai/bot.py.
    """

    #: Observation forms `act` receives.
    observation: Sequence[str] = ("planes",)
    #: The red variant's action names, by id (what `act` returns indexes).
    action_names: tuple = tuple(_core.variant_info("red")[0])

    def __init__(self, seat: Optional[int] = None, dialect: str = "app"):
        forms = [self.observation] if isinstance(self.observation, str) else list(self.observation)
        self._player = _core.MjaiPlayer(seat, forms)
        self._forms = forms
        self.dialect = dialect

    @property
    def seat(self) -> Optional[int]:
        """The bot's seat, once known."""
        return self._player.seat

    def act(self, observation: dict, legal_mask: np.ndarray) -> int:
        """The action id to play at this decision."""
        raise NotImplementedError(
            "subclass rinshan.mjai.Bot and define act(observation, legal_mask)"
        )

    def _decide(self, raw: dict, mask: np.ndarray) -> int:
        obs = {}
        for form in self._forms:
            for k, v in split_record(raw[form][None, :], form).items():
                obs.setdefault(k, v[0])
        action = int(self.act(obs, mask))
        if not (0 <= action < mask.shape[0]) or not mask[action]:
            raise ValueError(f"act returned {action}, not a legal action id")
        return action

    def react(self, line: str) -> Optional[str]:
        """The reply to one line from the host (None where the dialect expects none)."""
        reply, messages = self._player.respond(line, self.dialect, self._decide)
        for m in messages:
            print(f"rinshan.mjai.Bot: {m}", file=sys.stderr, flush=True)
        return reply

    def start(self, stdin: IO[str] = sys.stdin, stdout: IO[str] = sys.stdout) -> None:
        """Answers the host until its input ends."""
        for line in stdin:
            if not line.strip():
                continue
            reply = self.react(line)
            if reply is not None:
                stdout.write(reply + "\n")
                stdout.flush()
