"""Spaces shared by the wrappers: the planes observation and the action mask."""

from __future__ import annotations

import numpy as np
from gymnasium import spaces

from ..env import fields


def planes_space(num_actions: int):
    """A Dict space of the planes form's fields and the legal mask (`action_mask`, int8)."""
    parts = {}
    for f in fields("planes")[1]:
        info = np.iinfo(f.dtype)
        parts[f.name] = spaces.Box(int(info.min), int(info.max), f.shape, f.dtype)
    parts["action_mask"] = spaces.Box(0, 1, (num_actions,), np.int8)
    return spaces.Dict(parts)
