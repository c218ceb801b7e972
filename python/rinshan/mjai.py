"""MJAI logs (one JSON event per line, the format of Mortal, akochan and mjai.app): read as
decision records with observations, and converted to and from tenhou.net/6 JSON."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Union

from . import _core, tenhou


def read(path: Union[str, Path], observation: Union[str, Sequence[str]] = ("planes",)) -> dict:
    """Every decision of an MJAI log (plain or gzipped), replayed through the red variant: the
    same records as `rinshan.tenhou.read` (each decision's seat, action id, legal mask and the
    deciding seat's observation), so MJAI data feeds the same learning code."""
    return tenhou.read(str(path), observation)


def convert(path: Union[str, Path], to: str = "mjai") -> str:
    """The text of the log at `path` (either format, plain or gzipped) as `to`: "mjai" or
    "tenhou". Raises ValueError for a log that cannot be read."""
    return _core.convert_log(str(path), to)
