"""rinshan: vectorized four-player Riichi Mahjong for reinforcement learning.

    env = rinshan.make("red", num_envs=4096)
    ts = env.reset()
    ts = env.step(actions)        # one action id per env

See docs/env.md ("Python") for the whole API.
"""

from . import dataset, mjai, tenhou
from ._core import Net, __version__
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
from .hands import outlook, score, shanten
from .review import review
from .tenhou import replay

__all__ = [
    "__version__",
    "AGENTS",
    "FORMS",
    "MODES",
    "Net",
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
    "outlook",
    "packed_rows",
    "replay",
    "review",
    "score",
    "shanten",
    "tenhou",
    "unpack_planes",
]
