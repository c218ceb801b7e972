"""What the training stages share: the config, the network, and turning a TimeStep into tensors.

A config is one TOML file (configs/*.toml); every stage reads its own table and `[run]`.
"""

from __future__ import annotations

import contextlib
import functools
import json
import pathlib
import random
import sys
import time

import numpy as np
import tomllib
import torch
from torch import nn
from torch.nn import functional as F

import rinshan

# The planes form's shapes, as the package declares them: (rows, 34 tile types) and (scalars,).
_SHAPES = {f.name: f.shape for f in rinshan.fields("planes")[1]}
PLANES, (SCALARS,) = _SHAPES["planes"], _SHAPES["scalars"]
# The analysis tier's rows the net may read besides the planes, and the scale that brings each
# near 1 (plane counts are small integers: 0..4, river places up to 24).
ANALYSIS = ("discard_shanten", "discard_ukeire", "improving")
PLANE_SCALE = 0.25
ANALYSIS_SCALE = (0.25, 1 / 16, 1 / 16)
MASKED = -1e9


@functools.cache
def _spec(variant: str):
    return rinshan.make(variant, num_envs=1).spec


def action_names(variant: str) -> tuple[str, ...]:
    """A variant's action names, by id."""
    return tuple(_spec(variant).action_names)


def seats(variant: str) -> int:
    """How many play a variant: 4, or 3 (sanma)."""
    return int(_spec(variant).num_players)


# The nets' action layout: red's actions (every four-player kind), then those only other variants
# have (three players' kita), so that one net can play every variant. Nets saved before kita was
# added have red's layout (`Net.actions` reads them so).
RED = "red"
ACTIONS = tuple(dict.fromkeys(a for v in (RED, *rinshan.VARIANTS) for a in action_names(v)))


class Space:
    """One layout's action ids against a net's (`actions`, by default the nets' `ACTIONS`): a
    variant's env, or a dataset's rows (`names`)."""

    def __init__(
        self,
        variant: str | None = None,
        actions: tuple[str, ...] | list[str] = ACTIONS,
        names: tuple[str, ...] | list[str] | None = None,
    ):
        names = list(names if names is not None else action_names(variant or RED))
        actions = list(actions)
        missing = [a for a in names if a not in actions]
        if missing:
            what = variant or "the data"
            raise ValueError(f"{what}: actions {missing} are not in the net's layout")
        self.actions = actions
        self.size = len(actions)
        self.columns = np.array([actions.index(a) for a in names])
        self.back = np.full(self.size, -1)
        self.back[self.columns] = np.arange(len(names))

    def discard_columns(self) -> np.ndarray:
        """Per action of the net's, the tile type it discards (a red five is its type's five;
        34 = the drawn tile, for tsumogiri), -1 when it is not a discard."""
        cols = np.full(self.size, -1)
        for i, name in enumerate(self.actions):
            if name == "tsumogiri":
                cols[i] = 34
            elif name.startswith("discard_"):
                number, suit = int(name[-2]), "mpsz".index(name[-1])
                cols[i] = suit * 9 + (number or 5) - 1
        return cols

    def mask(self, m: np.ndarray) -> np.ndarray:
        out = np.zeros((m.shape[0], self.size), bool)
        out[:, self.columns] = m
        return out

    def values(self, v: np.ndarray) -> np.ndarray:
        """Per-action values (NaN: none) in the net's columns."""
        out = np.full((v.shape[0], self.size), np.nan, v.dtype)
        out[:, self.columns] = v
        return out

    def to_env(self, actions: np.ndarray) -> np.ndarray:
        return self.back[actions]


def config_arguments(ap, required: bool = True) -> None:
    """`--config FILE` and any number of `--set TABLE.KEY=VALUE` on an argument parser."""
    ap.add_argument("--config", required=required, help="a TOML config (configs/*.toml)")
    ap.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="TABLE.KEY=VALUE",
        help="one setting instead of the config's, the value written as in TOML "
        "(--set bc.hidden=128); repeatable",
    )


def load_config(
    path: str | pathlib.Path,
    tables: tuple[str, ...] = ("run", "collect", "bc", "ppo", "evaluate"),
    sets: list[str] | tuple[str, ...] = (),
) -> dict:
    """A training config, with `sets` (`TABLE.KEY=VALUE`) applied; each of `tables` (default:
    the whole pipeline's) must be in it."""
    with open(path, "rb") as f:
        cfg = tomllib.load(f)
    for item in sets:
        name, eq, value = item.partition("=")
        table, dot, key = name.partition(".")
        if not (eq and dot and table and key):
            sys.exit(f"--set {item}: write TABLE.KEY=VALUE")
        if table not in cfg:
            sys.exit(f"--set {item}: {path} has no [{table}] table")
        try:
            cfg[table][key] = tomllib.loads(f"v = {value}")["v"]
        except tomllib.TOMLDecodeError as e:
            sys.exit(f"--set {item}: {value} is not a TOML value ({e})")
    for table in tables:
        if table not in cfg:
            sys.exit(f"{path}: the config has no [{table}] table")
    return cfg


def seed_everything(seed: int) -> None:
    random.seed(seed)
    np.random.seed(seed % 2**32)
    torch.manual_seed(seed)


def set_threads(cfg: dict) -> None:
    torch.set_num_threads(int(cfg["run"].get("threads", 2)))


DRAWN_ROW = 5  # the planes' `drawn` row (docs/observation.md)


class Net(nn.Module):
    """An MLP over the flattened planes and the normalised scalars: masked logits over the action
    ids. The scalar statistics come from the BC data and travel with the weights.

    With `tile_head`, each discard's logit also gets a score computed from its own tile's column
    of the planes (one small MLP shared by the 34 columns, plus a summary of the whole position):
    comparing discards tile by tile (e.g. the shanten each leaves) is then one weight, where the
    flat MLP would have to learn it for every column apart."""

    def __init__(
        self,
        num_actions: int,
        hidden: int = 256,
        layers: int = 2,
        analysis=False,
        extra: int = 0,
        tile_head: bool = False,
        tile_hidden: int = 64,
        actions: list[str] | None = None,
    ):
        super().__init__()
        if actions is None and num_actions == len(ACTIONS):
            actions = list(ACTIONS)
        if actions is not None and len(actions) != num_actions:
            raise ValueError(f"{len(actions)} action names for {num_actions} logits")
        blocks: list[nn.Module] = []
        rows = PLANES[0] + (len(ANALYSIS) if analysis else 0)
        width = rows * PLANES[1] + SCALARS + extra
        for _ in range(layers):
            blocks += [nn.Linear(width, hidden), nn.ReLU()]
            width = hidden
        self.torso = nn.Sequential(*blocks)
        self.head = nn.Linear(hidden, num_actions)
        self.register_buffer("scalar_mean", torch.zeros(SCALARS))
        self.register_buffer("scalar_std", torch.ones(SCALARS))
        scale = [PLANE_SCALE] * PLANES[0] + (list(ANALYSIS_SCALE) if analysis else [])
        self.register_buffer("row_scale", torch.tensor(scale)[:, None])
        self.analysis = analysis
        self.tile_head = None
        if tile_head:
            self.tile_context = nn.Linear(hidden, 32)
            self.tile_head = nn.Sequential(
                nn.Linear(len(scale) + 32, tile_hidden), nn.ReLU(), nn.Linear(tile_hidden, 1)
            )
            names = self.actions_of(actions)
            cols = torch.from_numpy(Space(actions=names, names=names).discard_columns())
            self.register_buffer("discard_column", cols.clamp(min=0))
            self.register_buffer("is_discard", (cols >= 0).float())
        self.config = {
            "num_actions": num_actions,
            "hidden": hidden,
            "layers": layers,
            "analysis": analysis,
            "extra": extra,
            "tile_head": tile_head,
            "tile_hidden": tile_hidden,
        }
        if actions is not None:
            self.config["actions"] = list(actions)

    @staticmethod
    def actions_of(actions: list[str] | None) -> tuple[str, ...]:
        # A policy saved without names is from before kita joined the layout: red's.
        return tuple(actions) if actions is not None else action_names(RED)

    @property
    def actions(self) -> tuple[str, ...]:
        """The action name of each logit (a policy net's)."""
        return self.actions_of(self.config.get("actions"))

    def features(self, planes, scalars, extra=None, scaled=None) -> torch.Tensor:
        """The torso's output; `scaled` is `planes` already scaled by row (the forward pass
        needs them twice)."""
        if scaled is None:
            scaled = planes.float() * self.row_scale
        s = (scalars.float() - self.scalar_mean) / self.scalar_std
        flat = scaled.reshape(planes.shape[0], -1)
        return self.torso(torch.cat([flat, s] + ([] if extra is None else [extra]), dim=1))

    def forward(self, planes, scalars, mask) -> torch.Tensor:
        x = planes.float() * self.row_scale
        g = self.features(planes, scalars, scaled=x)
        logits = self.head(g)
        if self.tile_head is not None:
            # The tile head's first layer reads a tile's column and the position's context
            # side by side: its context half is the same for all 34 tiles, so it is computed once
            # per position and added to each column's half: the same function as the layer over
            # their concatenation, with a third fewer of its multiplications and no 34 copies of
            # the context.
            first, second = self.tile_head[0], self.tile_head[2]
            r = x.shape[1]
            context = F.linear(self.tile_context(g), first.weight[:, r:], first.bias)
            columns = F.linear(x.transpose(1, 2), first.weight[:, :r])
            per_tile = second(torch.relu(columns + context[:, None, :])).squeeze(2)
            drawn = planes[:, DRAWN_ROW].argmax(dim=1, keepdim=True)
            per_tile = torch.cat([per_tile, per_tile.gather(1, drawn)], dim=1)
            logits = logits + per_tile[:, self.discard_column] * self.is_discard
        return logits.masked_fill(~mask, MASKED)


def new_net(cfg: dict) -> Net:
    """An untrained policy net of the config's `[bc]` shape."""
    c = cfg["bc"]
    return Net(
        len(ACTIONS),
        int(c["hidden"]),
        int(c["layers"]),
        bool(cfg["run"].get("analysis", False)),
        tile_head=bool(c.get("tile_head", False)),
        tile_hidden=int(c.get("tile_hidden", 64)),
    )


# What an oracle critic reads of the hidden state, from the learner's seat: the others' hands and
# waits (3 rows each), the tiles of the next live-wall draws (1 row), and per other seat its
# shanten and furiten. The policy never reads it (`env.oracle` is for critics).
ORACLE_ROWS, ORACLE_SCALARS, WALL_AHEAD = 7, 6, 8
RED_FIVE_TYPES = np.array([4, 13, 22])


def oracle_features(o: dict) -> np.ndarray:
    """(B, 7 * 34 + 6) float32 features of `env.oracle(...)` arrays."""
    n = o["others_hand"].shape[0]
    wall = o["wall"].astype(np.int64)
    live = wall >= 0
    take = live & (np.cumsum(live, axis=1) <= WALL_AHEAD)
    types = np.where(wall >= 34, RED_FIVE_TYPES[np.clip(wall - 34, 0, 2)], wall)
    ahead = np.zeros((n, PLANES[1]), np.float32)
    np.add.at(ahead, (np.nonzero(take)[0], types[take]), 1.0)
    planes = np.concatenate(
        [o["others_hand"] / 4.0, o["others_waits"] > 0, ahead[:, None, :] / 4.0], axis=1
    )
    scalars = np.concatenate([o["others_shanten"] / 4.0, o["others_furiten"]], axis=1)
    return np.concatenate([planes.reshape(n, -1), scalars], axis=1).astype(np.float32)


class Critic(nn.Module):
    """The value of a seat's position, in the reward's units (a separate MLP, so that learning the
    value does not move the cloned policy's features); with `oracle`, it also reads what the seat
    cannot see, which takes much of the luck out of the advantages."""

    def __init__(self, hidden=256, layers=2, analysis=False, oracle=False):
        super().__init__()
        self.oracle = oracle
        extra = ORACLE_ROWS * PLANES[1] + ORACLE_SCALARS if oracle else 0
        self.body = Net(1, hidden, layers, analysis, extra)

    def forward(self, planes, scalars, hidden=None) -> torch.Tensor:
        return self.body.head(self.body.features(planes, scalars, hidden)).squeeze(1)


def save(net: nn.Module, path: pathlib.Path, **meta) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    torch.save({"config": net.config, "state": net.state_dict(), "meta": meta}, path)


def load_net(path: str | pathlib.Path) -> Net:
    ckpt = torch.load(path, map_location="cpu", weights_only=True)
    net = Net(**ckpt["config"])
    net.load_state_dict(ckpt["state"])
    net.eval()
    return net


def rows(obs: dict, analysis: bool) -> np.ndarray:
    """The planes, with the analysis tier's rows under them when the net reads those (uint8:
    shanten after a discard + 1, so that "not held" is 0)."""
    if not analysis:
        return np.asarray(obs["planes"])
    extra = [
        (obs["discard_shanten"].astype(np.int16) + 1).astype(np.uint8),
        obs["discard_ukeire"],
        obs["improving"],
    ]
    return np.concatenate([obs["planes"], np.stack(extra, axis=1)], axis=1)


def tensors(ts, space: Space, analysis: bool, take=None):
    """(planes, scalars, mask in the net's actions) tensors of a TimeStep, of the envs `take`
    (default: all). Copies: the env rewrites its arrays."""
    obs = ts.observation
    planes, scalars = rows(obs, analysis), np.asarray(obs["scalars"])
    mask = ts.legal_action_mask
    if take is None:
        planes, scalars = planes.copy(), scalars.copy()
    else:
        planes, scalars, mask = planes[take], scalars[take], mask[take]
    return torch.from_numpy(planes), torch.from_numpy(scalars), torch.from_numpy(space.mask(mask))


def greedy_policy(net: Net, variant: str):
    """A function TimeStep -> actions for `rinshan.evaluate`: the net's most likely legal action."""
    space = Space(variant, net.actions)

    def act(ts) -> np.ndarray:
        with torch.no_grad():
            logits = net(*tensors(ts, space, net.analysis))
        return space.to_env(logits.argmax(dim=1).numpy())

    return act


def rank_point(net: Net, variant: str, mode: str, analysis: bool, opponents, games: int, seed: int):
    """One point of a rank curve: the net's greedy play against `opponents` (an agent's name or a
    policy function) on the walls of `seed`, every set of walls once from each seat."""
    was_training = net.training
    net.eval()
    r = rinshan.evaluate(
        greedy_policy(net, variant),
        opponents=opponents,
        games=games,
        seed=seed,
        variant=variant,
        mode=mode,
        analysis=analysis,
    )
    net.train(was_training)
    # `even` is the average rank of an even match, the curve's reference line.
    return {"rank": r.average_rank, "ci95": r.ci95, "even": (seats(variant) + 1) / 2}


def entropy_and_kl(logp: torch.Tensor, ref_logp: torch.Tensor, mask: torch.Tensor):
    """Entropy of the policy and KL(policy || reference) over the legal actions only (illegal ones
    have probability 0 in both, and their log-probabilities are not finite in any useful sense)."""
    p = logp.exp()
    zero = torch.zeros_like(logp)
    ent = -torch.where(mask, p * logp, zero).sum(1)
    kl = torch.where(mask, p * (logp - ref_logp), zero).sum(1)
    return ent, kl


class Split:
    """Wall seconds per part of the training loop, to show where a step's time goes: the env's
    step (observations included), turning them into tensors, the critic's oracle, the nets'
    forward passes while playing, the rollout's bookkeeping, and learning."""

    PARTS = ("env", "observation", "oracle", "inference", "bookkeeping", "learning")

    def __init__(self):
        self.seconds = dict.fromkeys(self.PARTS, 0.0)

    @contextlib.contextmanager
    def __call__(self, part: str):
        t = time.perf_counter()
        try:
            yield
        finally:
            self.seconds[part] += time.perf_counter() - t

    def rounded(self) -> dict:
        return {k: round(v, 3) for k, v in self.seconds.items()}


class Log:
    """One JSON object per line, flushed at once: the plots and the report read these files."""

    def __init__(self, path: pathlib.Path):
        path.parent.mkdir(parents=True, exist_ok=True)
        self.f = open(path, "w")
        self.start = time.time()

    def write(self, **row) -> None:
        row["wall_s"] = round(time.time() - self.start, 2)
        self.f.write(json.dumps(row) + "\n")
        self.f.flush()

    def close(self) -> None:
        self.f.close()


def setting(cfg: dict, table: str) -> tuple[str, str]:
    """(variant, mode) of a stage: its own table's, else `[run]`'s."""
    t = cfg[table]
    return t.get("variant", cfg["run"]["variant"]), t.get("mode", cfg["run"]["mode"])


def make_env(cfg: dict, table: str, num_envs: int, seed: int, **kw) -> rinshan.Env:
    variant, mode = setting(cfg, table)
    return rinshan.make(
        variant,
        mode=mode,
        num_envs=num_envs,
        seed=seed,
        num_threads=int(cfg["run"].get("env_threads", 1)),
        analysis=bool(cfg["run"].get("analysis", False)),
        **kw,
    )
