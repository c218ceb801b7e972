"""Training data from game logs (tenhou.net/6 JSON, MJAI, mjlog XML; plain, gzipped or in tar
archives): build a dataset folder once and open it as a map-style dataset, or replay logs straight
into arrays.

    rinshan.dataset.build(["logs/"], "data/", observation="planes")   # or `rinshan dataset`
    ds = rinshan.dataset.Dataset("data/")
    loader = torch.utils.data.DataLoader(ds, batch_size=1024, shuffle=True,
                                         collate_fn=rinshan.dataset.collate)

A row is one decision: the deciding seat's observation (its fields by name), `legal_action_mask`,
`action` (the env's action ids), `seat`, `round`, `game` (index over the whole dataset), and the
game's end for rank-aware losses: `rank` and `score` of the row's seat, `ranks` and `scores` of
all four. Shards are memory-mapped: nothing is read until a row is asked for.
"""

from __future__ import annotations

import json
import pathlib
from collections.abc import Iterator, Sequence
from typing import Any, Optional, Union

import numpy as np

from . import _core

FORMAT = "rinshan-dataset"
VERSION = 1

Paths = Union[str, pathlib.Path, Sequence[Union[str, pathlib.Path]]]


def _paths(inputs: Paths) -> list[str]:
    if isinstance(inputs, (str, pathlib.Path)):
        return [str(inputs)]
    return [str(p) for p in inputs]


def _forms(observation: Union[str, Sequence[str], None]) -> list[str]:
    if observation is None or observation == "none":
        return []
    if isinstance(observation, str):
        return [observation]
    return list(observation)


def build(
    inputs: Paths,
    out: Union[str, pathlib.Path],
    observation: Union[str, Sequence[str], None] = "planes",
    seats: Optional[Sequence[int]] = None,
    players: Optional[Sequence[str]] = None,
    forced: bool = False,
    shard_size: Optional[int] = None,
    threads: Optional[int] = None,
    variant: str = "red",
    search: Optional[str] = None,
) -> dict:
    """Builds (or resumes) the dataset folder `out` from `inputs` (files, folders, glob patterns,
    tar archives): what `rinshan dataset` does (`shard_size` logs per shard, default 128).
    `variant` is the rule set the logs are replayed in (`"sanma"` for three-player logs); logs of
    other rules are skipped, and a game that comes in two logs (two formats, two copies) is kept
    from the first. With `search` (`"search:rollouts=1024"`, the look-ahead's settings) every row
    also gets the look-ahead's action (`search_action`) and its value of each action
    (`search_value`, NaN for actions it did not play out). Returns the summary (`skipped` lists
    each log left out with its reason, `duplicates` each one left out as the same game as an
    earlier log, as `(input, same_as)`)."""
    return _core.dataset_build(
        _paths(inputs),
        str(out),
        _forms(observation),
        None if seats is None else [int(s) for s in seats],
        None if players is None else [str(p) for p in players],
        bool(forced),
        None if shard_size is None else int(shard_size),
        threads,
        str(variant),
        None if search is None else str(search),
    )


def iterate(
    inputs: Paths,
    observation: Union[str, Sequence[str], None] = "planes",
    seats: Optional[Sequence[int]] = None,
    players: Optional[Sequence[str]] = None,
    forced: bool = False,
    chunk: int = 64,
    variant: str = "red",
    search: Optional[str] = None,
) -> Iterator[dict]:
    """Each log of `inputs` replayed into rows without writing a dataset: one dict per log with
    `name` and either `skipped` (the reason) or the arrays of its rows (`observation` holds each
    form's raw records; `scores` and `ranks` the game's end; with `search`, the look-ahead's
    `search_action` and `search_value` as in `build`). Logs are replayed `chunk` files at a
    time; a tar archive is read whole."""
    forms = _forms(observation)
    pending: list[str] = []

    def flush():
        records = _core.dataset_records(
            pending,
            forms,
            None if seats is None else [int(s) for s in seats],
            None if players is None else [str(p) for p in players],
            bool(forced),
            str(variant),
            None if search is None else str(search),
        )
        pending.clear()
        return records

    for path, is_archive in _core.dataset_sources(_paths(inputs)):
        pending.append(path)
        if len(pending) >= chunk or is_archive:
            yield from flush()
    if pending:
        yield from flush()


class Dataset:
    """A dataset folder as a map-style dataset (PyTorch's `Dataset` protocol: `len` and
    indexing). `ds[i]` is one row as a dict of arrays; `ds[idx]` with an integer array, a slice or
    a list (also `__getitems__`, which DataLoader uses) is a batch, gathered shard by shard. Only
    the asked `fields` are read (default: all)."""

    def __init__(self, path: Union[str, pathlib.Path], fields: Optional[Sequence[str]] = None):
        self.path = pathlib.Path(path)
        manifest_path = self.path / "manifest.json"
        try:
            self.manifest = json.loads(manifest_path.read_text())
        except FileNotFoundError:
            raise FileNotFoundError(
                f"{manifest_path}: no dataset manifest (build one first)"
            ) from None
        except json.JSONDecodeError as e:
            raise ValueError(f"{manifest_path}: not a dataset manifest: {e}") from None
        m = self.manifest
        if m.get("format") != FORMAT or m.get("version") != VERSION:
            raise ValueError(
                f"{manifest_path}: a {m.get('format')} version {m.get('version')} manifest; "
                f"this package reads {FORMAT} version {VERSION}"
            )
        self.actions: list[str] = m["actions"]
        self.num_actions = len(self.actions)
        # Each observation field: (form, offset, dtype, shape).
        self._fields: dict[str, tuple[str, int, np.dtype, tuple]] = {}
        for form in m["forms"]:
            for f in form["fields"]:
                self._fields.setdefault(
                    f["name"], (form["name"], f["offset"], np.dtype(f["dtype"]), tuple(f["shape"]))
                )
        rows = [a["name"] for a in m["arrays"] if a["per"] == "row" and a["name"] != "game"]
        self.field_names = [*self._fields, *rows, "game", "rank", "score", "ranks", "scores"]
        wanted = list(fields) if fields is not None else self.field_names
        unknown = [f for f in wanted if f not in self.field_names]
        if unknown:
            raise KeyError(f"{unknown}: not fields of this dataset ({', '.join(self.field_names)})")
        self.fields = wanted
        self.shards = [s for s in m["shards"] if s["rows"] > 0]
        self._arrays: list[dict[str, np.ndarray]] = [{} for _ in self.shards]
        counts = np.array([s["rows"] for s in self.shards], dtype=np.int64)
        self.offsets = np.concatenate([[0], np.cumsum(counts)])
        game_counts = np.array([len(s["games"]) for s in self.shards], dtype=np.int64)
        self.game_offsets = np.concatenate([[0], np.cumsum(game_counts)])

    def __len__(self) -> int:
        return int(self.offsets[-1])

    @property
    def games(self) -> list[str]:
        """The kept games' names, in order: a row's `game` indexes this list."""
        return [g for s in self.shards for g in s["games"]]

    @property
    def skipped(self) -> list[dict]:
        """Each log left out, with the reason."""
        return [k for s in self.manifest["shards"] for k in s["skipped"]]

    def _array(self, shard: int, name: str) -> np.ndarray:
        a = self._arrays[shard].get(name)
        if a is None:
            a = np.load(self.path / self.shards[shard]["name"] / f"{name}.npy", mmap_mode="r")
            self._arrays[shard][name] = a
        return a

    def _shard_rows(self, shard: int, local: np.ndarray) -> dict[str, np.ndarray]:
        out: dict[str, np.ndarray] = {}
        records: dict[str, np.ndarray] = {}
        game = None
        for name in self.fields:
            if name in self._fields:
                form, offset, dtype, shape = self._fields[name]
                if form not in records:
                    records[form] = np.asarray(self._array(shard, form)[local])
                nbytes = int(np.prod(shape)) * dtype.itemsize
                raw = np.ascontiguousarray(records[form][:, offset : offset + nbytes])
                out[name] = raw.view(dtype).reshape((len(local), *shape))
            elif name in ("rank", "score", "ranks", "scores"):
                if game is None:
                    game = np.asarray(self._array(shard, "game")[local]).astype(np.int64)
                table = self._array(shard, "ranks" if name.startswith("rank") else "scores")
                per_game = np.asarray(table)[game]
                if name in ("rank", "score"):
                    seat = np.asarray(self._array(shard, "seat")[local]).astype(np.int64)
                    out[name] = per_game[np.arange(len(local)), seat]
                else:
                    out[name] = per_game
            elif name == "game":
                out[name] = np.asarray(self._array(shard, "game")[local]).astype(np.int64) + int(
                    self.game_offsets[shard]
                )
            else:
                out[name] = np.asarray(self._array(shard, name)[local])
        return out

    def _gather(self, idx: np.ndarray) -> dict[str, np.ndarray]:
        n = len(self)
        if idx.ndim != 1:
            raise IndexError(f"row indices must be one-dimensional, not shape {idx.shape}")
        if idx.size and (idx.min() < -n or idx.max() >= n):
            raise IndexError(f"row index out of range for a dataset of {n} rows")
        idx = np.where(idx < 0, idx + n, idx)
        shard_of = np.searchsorted(self.offsets, idx, side="right") - 1
        parts: list[tuple[np.ndarray, dict]] = []
        for shard in np.unique(shard_of):
            where = np.nonzero(shard_of == shard)[0]
            local = idx[where] - self.offsets[shard]
            parts.append((where, self._shard_rows(int(shard), local)))
        if not parts and self.shards:
            # No rows asked: empty arrays of the right dtypes and shapes.
            none = np.zeros(0, dtype=np.int64)
            parts.append((none, self._shard_rows(0, none)))
        out: dict[str, np.ndarray] = {}
        for name in self.fields:
            if not parts:
                continue  # a dataset without rows
            first = parts[0][1][name]
            col = np.empty((len(idx), *first.shape[1:]), dtype=first.dtype)
            for where, rows in parts:
                col[where] = rows[name]
            out[name] = col
        return out

    def __getitem__(self, key: Any) -> dict[str, np.ndarray]:
        if isinstance(key, (int, np.integer)):
            batch = self._gather(np.array([int(key)], dtype=np.int64))
            return {k: v[0] for k, v in batch.items()}
        if isinstance(key, slice):
            return self._gather(np.arange(len(self), dtype=np.int64)[key])
        key = np.asarray(key)
        if key.dtype == np.bool_:
            if key.shape != (len(self),):
                raise IndexError(f"a boolean row mask needs shape ({len(self)},), not {key.shape}")
            return self._gather(np.nonzero(key)[0])
        return self._gather(key.astype(np.int64))

    def __getitems__(self, keys: Sequence[int]) -> dict[str, np.ndarray]:
        return self._gather(np.asarray(keys, dtype=np.int64))

    def check(self) -> int:
        """Checks every row's action is legal under its own mask (a row that is not is a bug of
        the builder's); returns the rows checked."""
        for shard in range(len(self.shards)):
            mask = self._array(shard, "legal_action_mask")
            action = np.asarray(self._array(shard, "action")).astype(np.int64)
            if mask.shape != (len(action), self.num_actions):
                raise ValueError(f"{self.shards[shard]['name']}: mask shape {mask.shape}")
            bad = np.nonzero(~np.asarray(mask)[np.arange(len(action)), action])[0]
            if bad.size:
                r = int(bad[0])
                raise ValueError(
                    f"{self.shards[shard]['name']} row {r}: "
                    f"action {action[r]} is not legal under its mask"
                )
        return len(self)

    def __repr__(self) -> str:
        return f"Dataset({str(self.path)!r}, {len(self)} rows, {len(self.games)} games)"


def collate(batch: Any) -> dict:
    """A DataLoader `collate_fn`: a batch from `__getitems__` (a dict of arrays) as PyTorch
    tensors, without a copy where numpy and PyTorch share the dtype."""
    import torch

    if isinstance(batch, list):
        batch = {k: np.stack([row[k] for row in batch]) for k in batch[0]}
    return {k: torch.from_numpy(np.ascontiguousarray(v)) for k, v in batch.items()}
