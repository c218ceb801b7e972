"""rinshan: vectorized four-player Riichi Mahjong for reinforcement learning.

    env = rinshan.make("red", num_envs=4096)
    ts = env.reset()
    ts = env.step(actions)        # one action id per env

See the README's "Python" section.
"""

from . import dataset, mjai, tenhou
from .env import (
    AGENTS,
    FORMS,
    MODES,
    VARIANTS,
    Env,
    Field,
    Spec,
    TimeStep,
    fields,
    make,
    packed_rows,
    unpack_planes,
)
from .evaluate import Evaluation, evaluate
from .hands import score, shanten
from .tenhou import replay

__all__ = [
    "AGENTS",
    "FORMS",
    "MODES",
    "VARIANTS",
    "Env",
    "Evaluation",
    "Field",
    "Spec",
    "TimeStep",
    "dataset",
    "evaluate",
    "fields",
    "make",
    "mjai",
    "packed_rows",
    "replay",
    "score",
    "shanten",
    "tenhou",
    "unpack_planes",
]
