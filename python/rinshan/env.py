"""The batched environment: `make`, `Env`, `TimeStep` and `Spec`.

Outputs are numpy arrays allocated once per env and rewritten in place by every `reset` and
`step` (Rust fills them with the GIL released). The TimeStep returned is the same object each
time: copy what you keep past the next call (`ts.copy()`), e.g. before handing arrays to JAX
through dlpack, whose buffers must not change underneath it.
"""

from __future__ import annotations

import dataclasses
import functools
import json
from collections.abc import Sequence
from typing import Any, Optional, Union

import numpy as np

from . import _core

FORMS, AGENTS, VARIANTS, MODES = _core.names()
OBSERVATION_FORMS = ("planes", "tokens", "packed")


@dataclasses.dataclass(frozen=True)
class Field:
    """One array of an observation record."""

    name: str
    offset: int
    dtype: np.dtype
    shape: tuple
    doc: str


def fields(form: str) -> tuple[int, list[Field]]:
    """Bytes of one record of `form` and its fields (see docs/observation.md)."""
    size, rows = _core.fields(form)
    return size, [Field(n, o, np.dtype(d), tuple(s), doc) for n, o, d, s, doc in rows]


def split_record(raw: np.ndarray, form: str) -> dict[str, np.ndarray]:
    """Views of `raw` (N, bytes) uint8 records as the form's named arrays (no copy)."""
    size, fs = fields(form)
    if raw.ndim != 2 or raw.shape[1] != size or raw.dtype != np.uint8:
        raise ValueError(f"{form} records are (N, {size}) uint8, not {raw.shape} {raw.dtype}")
    n = raw.shape[0]
    out = {}
    for f in fs:
        nbytes = int(np.prod(f.shape)) * f.dtype.itemsize
        out[f.name] = raw[:, f.offset : f.offset + nbytes].view(f.dtype).reshape((n, *f.shape))
    return out


@functools.cache
def _packed_layout() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Planes rows held as bits and as counts, and their indices in `bits` and `counts`."""
    rows = _core.packed_rows()
    bit_rows = np.array([r for r, (kind, _) in enumerate(rows) if kind == "bits"], dtype=np.intp)
    bit_index = np.array([i for kind, i in rows if kind == "bits"], dtype=np.intp)
    count_rows = np.array(
        [r for r, (kind, _) in enumerate(rows) if kind == "counts"], dtype=np.intp
    )
    count_index = np.array([i for kind, i in rows if kind == "counts"], dtype=np.intp)
    return bit_rows, bit_index, count_rows, count_index


def unpack_planes(packed: dict) -> dict[str, np.ndarray]:
    """The planes form's arrays from the packed form's (`bits`, `counts`, `scalars`, any leading
    shape): `planes` (..., 64, 34) uint8, equal byte for byte to what the planes form holds, and
    the same `scalars`. On a device, do the same with its array library: bit t of `bits[..., i]`
    is cell t of planes row `bit_rows[i]`, and `counts[..., j, :]` is row `count_rows[j]`, as
    `packed_rows()` lists."""
    bits = np.asarray(packed["bits"])
    counts = np.asarray(packed["counts"])
    bit_rows, bit_index, count_rows, count_index = _packed_layout()
    if (
        bits.dtype != np.uint64
        or counts.dtype != np.uint8
        or bits.shape[-1:] != (len(bit_rows),)
        or counts.shape[-2:] != (len(count_rows), 34)
        or bits.shape[:-1] != counts.shape[:-2]
    ):
        raise ValueError(
            f"packed arrays are bits (..., 36) uint64 and counts (..., 28, 34) uint8, "
            f"not {bits.shape} {bits.dtype} and {counts.shape} {counts.dtype}"
        )
    lead = bits.shape[:-1]
    planes = np.empty((*lead, len(bit_rows) + len(count_rows), 34), dtype=np.uint8)
    shifts = np.arange(34, dtype=np.uint64)
    planes[..., bit_rows, :] = ((bits[..., bit_index, None] >> shifts) & np.uint64(1)).astype(
        np.uint8
    )
    planes[..., count_rows, :] = counts[..., count_index, :]
    return {"planes": planes, "scalars": packed["scalars"]}


def packed_rows() -> list[tuple[str, int]]:
    """Where each planes row (0..63, in order) is in the packed form: ("bits", i) or
    ("counts", i)."""
    return [(kind, int(i)) for kind, i in _core.packed_rows()]


@dataclasses.dataclass(frozen=True)
class Spec:
    """What an env's arrays hold: sizes, names, dtypes and field docs."""

    variant: str
    mode: str
    num_envs: int
    num_actions: int
    action_names: tuple
    yaku_names: tuple
    starting_points: int
    # Players at the table: 4, or 3 (sanma). Per-seat arrays keep four entries; the seats from
    # this number on take no part (their rewards and scores stay 0).
    num_players: int
    observation: tuple
    fields: dict

    def describe(self) -> str:
        """The spec as text: the env's size, actions and every observation field's doc."""
        lines = [
            f"rinshan {self.variant} ({self.mode}), {self.num_envs} envs, "
            f"{self.num_actions} actions"
        ]
        for form, fs in self.fields.items():
            lines.append(f"{form}:")
            for f in fs:
                lines.append(f"  {f.name:14} {str(f.dtype):6} {str(f.shape):12} {f.doc}")
        return "\n".join(lines)


@dataclasses.dataclass
class TimeStep:
    """One reset's or step's outcome for the whole batch (index 0 = env).

    `rewards`, `terminated` and `info["final_*"]` belong to the game that ended in this step; with
    auto-reset, `observation`, `legal_action_mask` and `current_player` are already the next
    game's (Pgx's same-step auto-reset).
    """

    observation: dict
    legal_action_mask: np.ndarray
    current_player: np.ndarray
    rewards: np.ndarray
    terminated: np.ndarray
    truncated: np.ndarray
    info: dict

    def copy(self) -> TimeStep:
        """A copy that later steps do not overwrite."""
        return TimeStep(
            observation={k: v.copy() for k, v in self.observation.items()},
            legal_action_mask=self.legal_action_mask.copy(),
            current_player=self.current_player.copy(),
            rewards=self.rewards.copy(),
            terminated=self.terminated.copy(),
            truncated=self.truncated.copy(),
            info={k: v.copy() for k, v in self.info.items()},
        )


def _forms(observation: Union[str, Sequence[str], None], analysis: bool) -> list[str]:
    if observation is None:
        observation = ()
    if isinstance(observation, str):
        observation = (observation,)
    forms = list(observation)
    for f in forms:
        if f not in OBSERVATION_FORMS:
            raise ValueError(
                f"unknown observation form {f!r}: choose from {OBSERVATION_FORMS} "
                "(analysis=True adds the analysis tier; the oracle comes from env.oracle())"
            )
    if len(set(forms)) != len(forms):
        raise ValueError(f"observation {tuple(forms)} names a form twice")
    if analysis:
        forms.append("analysis")
    return forms


class Env:
    """A batch of `num_envs` games stepped together (`rinshan.make` builds one).

    Every array the env returns is allocated once and rewritten in place by each `reset` and
    `step`; copy what you keep (`TimeStep.copy`).

    Args:
        variant: The rule set, one of `VARIANTS`: `red` (Tenhou, red fives), `no_red`, `mjsoul`,
            `mleague`, `wrc`, and the three-player `sanma` and `mjsoul_sanma`.
        mode: How long a game lasts, one of `MODES`: `half` (East and South rounds), `east`
            (East rounds), or `single` (one hand).
        num_envs: Games in the batch (B), at least 1.
        backend: `cpu` (rayon threads) or `gpu` (wgpu compute shaders, the same games bit for bit).
        num_threads: CPU threads; None uses every core.
        seed: The 64-bit seed that every game's wall derives from; the same seed plays the same
            games.
        observation: The observation forms to fill each step: `planes`, `tokens`, `packed`, a
            sequence of them, or None / `()` for none (docs/observation.md lists their fields).
        analysis: Also fill the analysis tier (shanten, waits, tiles left), for shaping and
            baselines.
        oracle: Allow `oracle()`, the information the seats cannot see (for critics).
        auto_reset: Start the next game in the step that ends one (Pgx's same-step auto-reset);
            False leaves a finished game until `reset`.
        opponents: None (the caller plays every seat), a built-in agent's name from `AGENTS`
            (`random`, `rule`, `greedy`, `defensive`), the look-ahead (`search`, or with its
            settings: `search:rollouts=512:seed=2`; CPU backend), a trained net's file
            (`net:PATH`, written by examples/train/export.py; CPU backend), or `mjai:COMMAND` for
            an outside MJAI bot; with `hero_seats` they play every other seat inside `step`.
        hero_seats: The seat the caller plays (0..3), or one per env; needs `opponents`.
        penalty: Points an illegal action costs (None: the rule set's own).
        mjai_dialect: `app` (mjai.app's: a JSON array of events per line) or `stdio` (Mortal's
            and mjai-manue's: one event per line), for `mjai:` opponents.
        mjai_timeout: Seconds an MJAI bot has for each answer before it faults.
        mjai_startup: Seconds an MJAI bot has to start.

    Raises:
        TypeError: `num_envs`, `seed`, `num_threads` or `hero_seats` of the wrong type.
        ValueError: An unknown variant, mode, backend, observation form or agent, a count or seed
            out of range, or `hero_seats` without `opponents`.
        RuntimeError: `backend="gpu"` with no GPU adapter, or an MJAI bot that does not start.

    Example:
        >>> import numpy as np, rinshan
        >>> env = rinshan.make("red", num_envs=8, seed=1)
        >>> ts = env.reset()
        >>> ts.legal_action_mask.shape
        (8, 87)
        >>> rng = np.random.default_rng(0)
        >>> actions = [rng.choice(np.flatnonzero(m)) for m in ts.legal_action_mask]
        >>> ts = env.step(np.array(actions))
        >>> env.close()
    """

    def __init__(
        self,
        variant: str = "red",
        mode: str = "half",
        num_envs: int = 4096,
        backend: str = "cpu",
        num_threads: Optional[int] = None,
        seed: int = 0,
        observation: Union[str, Sequence[str], None] = ("planes",),
        analysis: bool = False,
        oracle: bool = False,
        auto_reset: bool = True,
        opponents: Optional[str] = None,
        hero_seats: Union[int, Sequence[int], np.ndarray, None] = None,
        penalty: Optional[float] = None,
        mjai_dialect: str = "app",
        mjai_timeout: float = 5.0,
        mjai_startup: float = 60.0,
    ):
        if not isinstance(num_envs, (int, np.integer)) or isinstance(num_envs, bool):
            raise TypeError(f"num_envs must be an int, not {type(num_envs).__name__}")
        if num_envs < 1:
            raise ValueError(f"num_envs must be at least 1, not {num_envs}")
        for name, value in (("seed", seed), ("num_threads", num_threads)):
            if value is not None and (
                not isinstance(value, (int, np.integer)) or isinstance(value, bool)
            ):
                raise TypeError(f"{name} must be an int, not {type(value).__name__}")
        if seed is None:
            raise TypeError("seed must be an int, not NoneType")
        if num_threads is not None and num_threads < 1:
            raise ValueError(
                f"num_threads must be at least 1 (None = all cores), not {num_threads}"
            )
        if not 0 <= seed < 2**64:
            raise ValueError(f"seed must be in 0..2**64, not {seed}")
        forms = _forms(observation, analysis)
        seats = None
        if hero_seats is not None:
            seats = np.atleast_1d(np.asarray(hero_seats))
            if seats.dtype.kind not in "iu" or seats.ndim != 1:
                raise TypeError("hero_seats must be an int or a 1-D array of ints")
            if ((seats < 0) | (seats > 3)).any():
                raise ValueError("hero seats are 0..3")
            seats = [int(s) for s in seats]
        self._core = _core.Env(
            variant,
            mode,
            int(num_envs),
            backend,
            num_threads,
            int(seed),
            forms,
            bool(auto_reset),
            opponents,
            seats,
            penalty,
            mjai_dialect,
            float(mjai_timeout),
            float(mjai_startup),
        )
        self.num_envs = int(num_envs)
        self.oracle_enabled = oracle
        names, yaku, start, players = _core.variant_info(variant)
        self.spec = Spec(
            variant=variant,
            mode=mode,
            num_envs=self.num_envs,
            num_actions=len(names),
            action_names=tuple(names),
            yaku_names=tuple(yaku),
            starting_points=start,
            num_players=players,
            observation=tuple(forms),
            fields={f: fields(f)[1] for f in [*forms, *(["oracle"] if oracle else [])]},
        )
        buf = self._core.buffers()
        for a in buf.values():
            a.flags.writeable = False
        obs = {}
        for form in forms:
            for name, view in split_record(buf[f"raw_{form}"], form).items():
                # The scalars appear in both forms: one key, from the first form asked.
                obs.setdefault(name, view)
        info = {
            k: buf[k]
            for k in (
                "illegal",
                "hero",
                "episode_id",
                "events",
                "winners",
                "deal_in",
                "yaku",
                "rounds",
                "final_scores",
                "final_rank",
            )
        }
        env_id = np.arange(self.num_envs, dtype=np.int32)
        env_id.flags.writeable = False
        info["env_id"] = env_id
        self._ts = TimeStep(
            observation=obs,
            legal_action_mask=buf["legal_action_mask"],
            current_player=buf["current_player"],
            rewards=buf["rewards"],
            terminated=buf["terminated"],
            truncated=buf["truncated"],
            info=info,
        )

    # -- stepping --------------------------------------------------------------------------

    def reset(self, seed: Optional[int] = None, seeds: Optional[Sequence[int]] = None) -> TimeStep:
        """New games. Without arguments each reset deals new games from `make`'s seed; `seed`
        gives the same games every time; `seeds` gives each env's 64-bit seed (the same seed deals
        the same game, e.g. for duplicate play)."""
        if seeds is not None:
            s = np.asarray(seeds)
            if s.dtype.kind not in "iu" or s.shape != (self.num_envs,):
                raise ValueError(f"seeds must be {self.num_envs} integers")
            if (s < 0).any():
                raise ValueError("seeds must be non-negative")
            self._core.reset(None, [int(x) for x in s])
        else:
            if seed is not None and not 0 <= seed < 2**64:
                raise ValueError(f"seed must be in 0..2**64, not {seed}")
            self._core.reset(seed, None)
        return self._ts

    def step(self, actions: Any) -> TimeStep:
        """One decision per env (`actions`: (num_envs,) integers). An id outside 0..A-1 raises;
        an illegal id in range ends that env's game with the penalty (`info["illegal"]`)."""
        a = np.asarray(actions)
        if a.dtype.kind not in "iu":
            raise TypeError(f"actions must be integers, not {a.dtype}")
        if a.shape != (self.num_envs,):
            raise ValueError(f"actions has shape {a.shape}; this env needs ({self.num_envs},)")
        if a.dtype == np.uint64 and (a > np.iinfo(np.int64).max).any():
            raise ValueError("an action id is out of range")
        self._core.step(np.ascontiguousarray(a, dtype=np.int64))
        return self._ts

    @property
    def timestep(self) -> TimeStep:
        """The last reset's or step's outcome (the object they return)."""
        return self._ts

    # -- looking -----------------------------------------------------------------------------

    def observe(self, players: Any = None, form: str = "planes") -> dict:
        """`form` observations of any seat: `players` an int seat for every env, a (num_envs,)
        array of seats, or None for each env's current player. New arrays (not overwritten)."""
        if form not in OBSERVATION_FORMS + ("analysis",):
            raise ValueError(f"unknown observation form {form!r}")
        return split_record(self._core.observe(form, self._seats(players)), form)

    def observe_all(self, form: str = "planes") -> dict:
        """Every seat's observation: arrays of shape (num_envs, num_players, ...) (critics)."""
        per_seat = [self.observe(s, form) for s in range(self.spec.num_players)]
        return {k: np.stack([p[k] for p in per_seat], axis=1) for k in per_seat[0]}

    def oracle(self, players: Any = None) -> dict:
        """What `players` cannot see (other hands, the wall, ura dora...): for critics and
        analysis, never for acting. Needs `make(..., oracle=True)`."""
        if not self.oracle_enabled:
            raise RuntimeError("make the env with oracle=True to read the oracle")
        return split_record(self._core.observe("oracle", self._seats(players)), "oracle")

    def agent_actions(self, agent: str) -> np.ndarray:
        """What the built-in `agent` would play for each env's current player."""
        return self._core.agent_actions(agent)

    def _seats(self, players: Any) -> list:
        if players is None:
            return [4] * self.num_envs
        p = np.asarray(players)
        if p.dtype.kind not in "iu":
            raise TypeError(f"players must be seats (ints), not {p.dtype}")
        if p.ndim == 0:
            p = np.full(self.num_envs, int(p))
        if p.shape != (self.num_envs,):
            raise ValueError(f"players must be one seat or {self.num_envs} seats, not {p.shape}")
        last = self.spec.num_players - 1
        if ((p < 0) | (p > last)).any():
            raise ValueError(f"seats are 0..{last}")
        return [int(x) for x in p]

    # -- saving ------------------------------------------------------------------------------

    def render(
        self,
        i: int = 0,
        tiles: str = "en",
        pov: Any = None,
        reveal: bool = False,
        png: bool = False,
    ) -> Any:
        """Env `i`'s table as SVG text (or PNG bytes with `png=True`): `pov` (default: the seat to
        act) at the bottom with its hand face up, the others face down unless `reveal`; `tiles` is
        `ja`, `en` or `ascii`. In a notebook: `IPython.display.SVG(env.render(0))`."""
        if not isinstance(i, (int, np.integer)) or isinstance(i, bool) or i < 0:
            raise TypeError(f"i must be an env index (an int >= 0), not {i!r}")
        if pov is not None and (not isinstance(pov, (int, np.integer)) or isinstance(pov, bool)):
            raise TypeError(f"pov must be a seat (0..3) or None, not {pov!r}")
        if pov is not None and not 0 <= pov <= 3:
            raise ValueError(f"pov {pov}: seats are 0..3")
        return self._core.render(
            int(i), str(tiles), None if pov is None else int(pov), bool(reveal), bool(png)
        )

    def outlook(self, i: int = 0, trials: int = 2000, seed: int = 0) -> Optional[dict]:
        """Env `i`'s win odds per discard for the seat to act at its own turn, from what that seat
        sees (its share of the live wall left as its draws), drawing alone: the fields of
        `rinshan.outlook` (`{"draws", "discards": [...]}`, best first). None at a decision
        without a discard (a claim prompt, a finished game).

        >>> import rinshan
        >>> env = rinshan.make("red", num_envs=1, seed=3)
        >>> _ = env.reset()
        >>> odds = env.outlook(0, trials=500)
        >>> odds["draws"], len(odds["discards"]) > 0
        (18, True)
        """
        if not isinstance(i, (int, np.integer)) or isinstance(i, bool) or i < 0:
            raise TypeError(f"i must be an env index (an int >= 0), not {i!r}")
        text = self._core.outlook(int(i), int(trials), int(seed))
        return None if text is None else json.loads(text)

    def get_state(self) -> np.ndarray:
        """Every game as (num_envs, W) uint32 words (pickle-able), for `set_state`."""
        return self._core.get_state()

    def set_state(self, state: np.ndarray) -> TimeStep:
        """Restores games from `get_state` of an env of this variant and size; an edited state is
        refused. Returns the TimeStep as of the save."""
        s = np.asarray(state)
        if s.dtype != np.uint32:
            raise TypeError(f"a state is uint32 words, not {s.dtype}")
        self._core.set_state(np.ascontiguousarray(s))
        return self._ts

    def close(self) -> None:
        """Frees the games; later calls raise."""
        self._core.close()

    @property
    def closed(self) -> bool:
        """Whether `close` was called."""
        return self._core.closed

    def __enter__(self) -> Env:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __repr__(self) -> str:
        return (
            f"rinshan.Env({self.spec.variant!r}, mode={self.spec.mode!r}, num_envs={self.num_envs})"
        )


def make(variant: str = "red", **kwargs: Any) -> Env:
    """A batch of games to step together.

    Args:
        variant: The rule set, one of `VARIANTS` (`red` is Tenhou's with red fives).
        **kwargs: `Env`'s other arguments: `mode`, `num_envs`, `backend`, `num_threads`, `seed`,
            `observation`, `analysis`, `oracle`, `auto_reset`, `opponents`, `hero_seats`,
            `penalty`, `mjai_dialect`, `mjai_timeout`, `mjai_startup`.

    Returns:
        The `Env`, its games not yet dealt: call `reset` first.

    Raises:
        TypeError: An argument of the wrong type, or one `Env` does not take.
        ValueError: An unknown name (variant, mode, backend, form, agent) or a value out of range.
        RuntimeError: The GPU backend with no adapter, or an MJAI bot that does not start.

    Example:
        >>> import rinshan
        >>> env = rinshan.make("sanma", num_envs=2, opponents="defensive", hero_seats=0)
        >>> env.spec.num_players, env.spec.num_actions
        (3, 82)
        >>> ts = env.reset(seed=7)
        >>> ts = env.step(env.agent_actions("rule"))
        >>> env.close()
    """
    return Env(variant, **kwargs)
