"""Types of the Rust extension (python/src) that the package's modules wrap; checked against the
built module by mypy's stubtest in CI (.ci/python-tests). Users call the wrappers (`rinshan.make`,
`rinshan.score`, ...), not these."""

from collections.abc import Callable
from typing import Any, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "__version__",
    "Env",
    "MjaiPlayer",
    "Net",
    "shanten",
    "score",
    "tenhou_read",
    "replay",
    "convert_log",
    "fields",
    "packed_rows",
    "variant_info",
    "names",
    "STATE_CHECK_WORDS",
    "dataset_build",
    "dataset_records",
    "dataset_sources",
    "review",
    "outlook",
]

__version__: str
STATE_CHECK_WORDS: int

# pyo3 classes cannot be subclassed.
@final
class Env:
    def __new__(
        cls,
        variant: str,
        mode: str,
        num_envs: int,
        backend: str,
        num_threads: int | None,
        seed: int,
        forms: list[str],
        auto_reset: bool,
        opponents: str | None,
        hero_seats: list[int] | None,
        penalty: float | None,
        mjai_dialect: str = "app",
        mjai_timeout: float = 5.0,
        mjai_startup: float = 60.0,
    ) -> Env: ...
    @property
    def adapter(self) -> str | None: ...
    @property
    def closed(self) -> bool: ...
    @property
    def state_words(self) -> int: ...
    def agent_actions(self, agent: str) -> npt.NDArray[np.int64]: ...
    def buffers(self) -> dict[str, Any]: ...
    def close(self) -> None: ...
    def get_state(self) -> npt.NDArray[np.uint32]: ...
    def observe(self, form: str, seats: list[int]) -> npt.NDArray[np.uint8]: ...
    def outlook(self, i: int, trials: int, seed: int) -> str | None: ...
    def render(
        self, i: int, tiles: str, pov: int | None, reveal: bool, png: bool
    ) -> str | bytes: ...
    def reset(self, seed: int | None = None, seeds: list[int] | None = None) -> None: ...
    def set_state(self, state: npt.NDArray[np.uint32]) -> None: ...
    def step(self, actions: npt.NDArray[np.int64]) -> None: ...

@final
class MjaiPlayer:
    def __new__(cls, seat: int | None, forms: list[str]) -> MjaiPlayer: ...
    @property
    def seat(self) -> int | None: ...
    def respond(
        self, line: str, dialect: str, decide: Callable[..., Any]
    ) -> tuple[str | None, list[str]]: ...

@final
class Net:
    def __new__(cls, path: str) -> Net: ...
    @property
    def actions(self) -> list[str]: ...
    @property
    def analysis(self) -> list[str]: ...
    def logits(
        self,
        rows: npt.NDArray[np.uint8],
        scalars: npt.NDArray[np.int16],
        mask: npt.NDArray[np.bool_],
    ) -> npt.NDArray[np.float32]: ...

def convert_log(path: str, to: str) -> str: ...
def dataset_build(
    inputs: list[str],
    out: str,
    forms: list[str],
    seats: list[int] | None = None,
    players: list[str] | None = None,
    forced: bool = False,
    shard_size: int | None = None,
    threads: int | None = None,
    variant: str = "red",
    search: str | None = None,
) -> dict[str, Any]: ...
def dataset_records(
    inputs: list[str],
    forms: list[str],
    seats: list[int] | None = None,
    players: list[str] | None = None,
    forced: bool = False,
    variant: str = "red",
    search: str | None = None,
) -> list[Any]: ...
def dataset_sources(inputs: list[str]) -> list[tuple[str, bool]]: ...
def fields(form: str) -> tuple[int, list[tuple[str, int, str, list[int], str]]]: ...
def names() -> tuple[list[str], list[str], list[str], list[str]]: ...
def outlook(hand: str, seen: str, draws: int, trials: int, seed: int) -> str: ...
def packed_rows() -> list[tuple[str, int]]: ...
def replay(
    paths: list[str], backend: str = "cpu", variant: str | None = None
) -> dict[str, Any]: ...
def review(
    path: str, seat: int | None, player: str | None, round: int | None, search: str
) -> str: ...
def score(
    variant: str,
    hand: str,
    win: str,
    flags: list[str],
    round_wind: str,
    seat_wind: str | None,
    dora: str | None,
    ura: str | None,
    melds: list[str],
    honba: int,
    sticks: int,
) -> str: ...
def shanten(hand: str) -> dict[str, Any]: ...
def tenhou_read(path: str, forms: list[str], search: str | None = None) -> dict[str, Any]: ...
def variant_info(variant: str) -> tuple[list[str], list[str], int, int]: ...
