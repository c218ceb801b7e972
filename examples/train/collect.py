"""Behaviour-cloning data: a built-in agent (`[collect] agent`: `rule`, `defensive`, ...) plays
every seat and each decision with a real choice (two or more legal actions) is written as numpy
shards:
planes (N, R, 34) uint8 (the analysis rows under the 64 planes when `[run] analysis`), scalars
(N, 48) int16, mask (N, A) bool and action (N,) int64 in the nets' action ids (common.ACTIONS).

python examples/train/collect.py --config configs/seed.toml --seed 0 --out runs/x/data
"""

from __future__ import annotations

import argparse
import pathlib
import time

import numpy as np
from common import ACTIONS, Log, Space, config_arguments, load_config, rows

import rinshan

# The config tables collecting reads.
TABLES = ("run", "collect")


def collect(cfg: dict, seed: int, out: pathlib.Path) -> dict:
    """Writes `[collect] samples` decisions, or each `[[collect.mix]]` entry's `samples` in its own
    variant and mode (so one net learns both, e.g. single no-red hands and red half games)."""
    c = cfg["collect"]
    parts = c.get("mix") or [{"samples": c["samples"]}]
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("shard-*.npz"):
        old.unlink()
    log = Log(out / "collect.jsonl")
    totals = {"samples": 0, "shards": 0, "env_steps": 0, "games": 0}
    start = time.time()
    for k, part in enumerate(parts):
        variant = part.get("variant", cfg["run"]["variant"])
        mode = part.get("mode", cfg["run"]["mode"])
        got = _collect_part(cfg, variant, mode, int(part["samples"]), seed + k, out, totals)
        log.write(variant=variant, mode=mode, **got)
    totals.update(agent=c["agent"], seconds=round(time.time() - start, 1))
    log.write(**totals)
    log.close()
    return totals


def _collect_part(cfg, variant, mode, samples, seed, out, totals) -> dict:
    c = cfg["collect"]
    agent, shard = c["agent"], int(c["shard_size"])
    analysis = bool(cfg["run"].get("analysis", False))
    env = rinshan.make(
        variant,
        mode=mode,
        num_envs=int(c["num_envs"]),
        seed=seed,
        num_threads=int(cfg["run"].get("env_threads", 1)),
        analysis=analysis,
    )
    space = Space(variant)
    ts = env.reset()
    buf: dict[str, list] = {"planes": [], "scalars": [], "mask": [], "action": []}
    held = written = steps = games = 0
    while written < samples:
        actions = env.agent_actions(agent)
        choice = ts.legal_action_mask.sum(axis=1) > 1
        buf["planes"].append(rows(ts.observation, analysis)[choice])
        buf["scalars"].append(ts.observation["scalars"][choice].copy())
        buf["mask"].append(space.mask(ts.legal_action_mask[choice]))
        buf["action"].append(space.columns[actions[choice]])
        held += int(choice.sum())
        ts = env.step(actions)
        steps += env.num_envs
        games += int(ts.terminated.sum())
        if held >= shard or written + held >= samples:
            arrays = {k: np.concatenate(v)[: samples - written] for k, v in buf.items()}
            np.savez(out / f"shard-{totals['shards']:03}.npz", **arrays)
            totals["shards"] += 1
            written += len(arrays["action"])
            held = 0
            buf = {k: [] for k in buf}
    env.close()
    totals["samples"] += written
    totals["env_steps"] += steps
    totals["games"] += games
    return {"samples": written, "env_steps": steps, "games": games}


# What a row may teach: the move played, the look-ahead's choice, or its values (a distribution).
TARGETS = ("action", "search_action", "search_value")


def value_targets(values: np.ndarray, chosen: np.ndarray, temperature: float) -> np.ndarray:
    """The distribution a row's look-ahead values teach: softmax(value / temperature) over the
    actions it played out (a value is minus an expected place, so `temperature` is in places);
    a row it did not look at teaches its label `chosen` alone, as imitation of the choice does."""
    n, width = values.shape
    out = np.zeros((n, width), np.float32)
    finite = ~np.isnan(values)
    looked = finite.any(1)
    out[np.flatnonzero(~looked), chosen[~looked]] = 1.0
    v = np.where(finite[looked], values[looked], -np.inf) / temperature
    e = np.exp(v - v.max(1, keepdims=True))
    out[looked] = e / e.sum(1, keepdims=True)
    return out


def gather(files: list[pathlib.Path]) -> dict[str, np.ndarray]:
    """The shards' arrays end to end, written into arrays allocated once: concatenating loaded
    shards would hold every row twice, and a few million rows of planes no longer fit twice."""
    sizes = []
    for f in files:
        with np.load(f) as z:
            sizes.append(len(z["action"]))
    out: dict[str, np.ndarray] = {}
    at = 0
    for f, n in zip(files, sizes, strict=True):
        with np.load(f) as z:
            for k in z.files:
                a = z[k]
                if k not in out:
                    out[k] = np.empty((sum(sizes), *a.shape[1:]), a.dtype)
                out[k][at : at + n] = a
        at += n
    return out


# Held-out rows at most (a tenth of the rows up to this): enough to measure a net on, and a
# dataset of millions of rows is not read whole for them.
VALIDATION_ROWS = 65536


def held_out(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """bc.py's split of `n` rows for its `seed`: the held-out rows (sorted) and the training rows,
    so that agreement.py can score a net on the rows it did not learn from."""
    order = np.random.default_rng(seed).permutation(n)
    n_val = max(1, min(n // 10, VALIDATION_ROWS))
    return np.sort(order[:n_val]), order[n_val:]


class Rows:
    """Training rows fetched by index: `take(idx)` gives (planes, scalars, mask, target), the
    planes with the analysis rows under them when the net reads those, actions in the ids of the
    net's layout `actions`. The target is an action per row, or with `target = "search_value"` a
    distribution over the actions per row (`value_targets`). collect.py's shards are held in
    memory; a dataset folder built from logs (`rinshan dataset`) stays memory-mapped, so a
    dataset larger than memory trains too."""

    def __init__(
        self,
        folder: pathlib.Path,
        analysis: bool = False,
        target: str = "action",
        temperature: float = 0.05,
        actions: tuple[str, ...] = ACTIONS,
    ):
        if target not in TARGETS:
            raise SystemExit(f"[bc] target = {target!r}: write one of {', '.join(TARGETS)}")
        if not temperature > 0:
            raise SystemExit(f"temperature {temperature}: it must be above 0")
        self.analysis = analysis
        self.target = target
        self.temperature = temperature
        self._folder = folder
        self._columns: dict[str, rinshan.dataset.Dataset] = {}
        if (folder / "manifest.json").exists():
            self._dataset = open_dataset(folder, analysis, target)
            try:
                self._space = Space(actions=actions, names=self._dataset.actions)
            except ValueError as e:
                raise SystemExit(f"{folder}: {e}") from None
            self._arrays = None
            self._len = len(self._dataset)
            return
        if target != "action":
            raise SystemExit(
                f"{folder}: collect.py's shards hold the agent's actions only; "
                f"`{target}` labels come from `rinshan dataset --search`"
            )
        files = sorted(folder.glob("shard-*.npz"))
        if not files:
            raise SystemExit(f"{folder}: no shard-*.npz (run collect.py first)")
        self._arrays = gather(files)
        self._len = len(self._arrays["action"])

    def __len__(self) -> int:
        return self._len

    @property
    def shape(self) -> tuple[int, int]:
        """(plane rows, actions) of a row."""
        planes, _, mask, _ = self.take(np.arange(min(1, self._len)))
        return planes.shape[1], mask.shape[1]

    def take(self, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        if self._arrays is not None:
            d = self._arrays
            return d["planes"][idx], d["scalars"][idx], d["mask"][idx], d["action"][idx]
        d = self._dataset[idx]
        cols = self._space.columns
        if self.target == "search_value":
            chosen = cols[d["search_action"]]
            target = value_targets(self._space.values(d["search_value"]), chosen, self.temperature)
        else:
            target = cols[d[self.target]]
        mask = self._space.mask(d["legal_action_mask"])
        return rows(d, self.analysis), d["scalars"], mask, target

    def has(self, name: str) -> bool:
        """Whether the rows carry the array `name` (`search_action` in a dataset built with
        `--search`)."""
        if self._arrays is not None:
            return name in self._arrays
        return name in self._dataset.field_names

    def labels(self, name: str, idx: np.ndarray) -> np.ndarray:
        """The action array `name` (`action`, `search_action`) at rows `idx`, in the net's action
        ids, without the observations."""
        if not self.has(name):
            raise SystemExit(f"{self._folder}: the rows hold no `{name}`")
        if self._arrays is not None:
            return self._arrays[name][idx]
        return self._space.columns[self._column(name)[idx][name]]

    def scalars(self, idx: np.ndarray) -> np.ndarray:
        if self._arrays is not None:
            return self._arrays["scalars"][idx]
        return self._column("scalars")[idx]["scalars"]

    def _column(self, name: str) -> rinshan.dataset.Dataset:
        """The dataset folder opened for the one field `name`, so that reading it reads nothing
        else (opened once)."""
        if name not in self._columns:
            self._columns[name] = rinshan.dataset.Dataset(self._folder, fields=[name])
        return self._columns[name]


def open_dataset(
    folder: pathlib.Path, analysis: bool, target: str = "action"
) -> rinshan.dataset.Dataset:
    """A log dataset (`rinshan dataset logs/ -o DIR --observe planes[,analysis]`) with the fields
    a net reads and what `target` needs: the action it learns, or the look-ahead's choice
    (`search_action`) or values and choice (`search_value`) of a dataset built with `--search`;
    `Rows` brings its action ids (its variant's) to the net's."""
    names = ["planes", "scalars", "legal_action_mask"]
    names += ["search_action", "search_value"] if target == "search_value" else [target]
    if analysis:
        names += ["discard_shanten", "discard_ukeire", "improving"]
    try:
        ds = rinshan.dataset.Dataset(folder, fields=names)
    except KeyError as e:
        forms = "planes,analysis" if analysis else "planes"
        search = " --search search:..." if target.startswith("search_") else ""
        raise SystemExit(f"{folder}: {e} (build it with --observe {forms}{search})") from None
    return ds


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    config_arguments(ap)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--out", required=True, help="folder for the shards")
    a = ap.parse_args()
    print(collect(load_config(a.config, TABLES, a.set), a.seed, pathlib.Path(a.out)))


if __name__ == "__main__":
    main()
