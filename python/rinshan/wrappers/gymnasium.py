"""Gymnasium adapters with a self-play view: every decision of every seat is a step, the
observation is the planes form of the seat to act with its legal mask (`action_mask`), and the
reward is the score change of the seat that acted (all four in `info["rewards"]`).

`RinshanEnv` is one game (`gymnasium.Env`); `RinshanVectorEnv` is a batch stepped in one call,
with Gymnasium's same-step auto-reset: the observation returned with `terminated` is the next
game's first.
"""

from __future__ import annotations

from typing import Any, Optional

import gymnasium
import numpy as np
from gymnasium import spaces

from ..env import Env
from ._spaces import planes_space


def _obs(ts, i: Optional[int] = None) -> dict:
    sel = slice(None) if i is None else i
    out = {k: v[sel].copy() for k, v in ts.observation.items()}
    out["action_mask"] = ts.legal_action_mask[sel].astype(np.int8)
    return out


def _info(ts, i: Optional[int] = None) -> dict:
    sel = slice(None) if i is None else i
    # Episode ids name games over the env's life, so a reseeded game gets a new one; Gymnasium
    # wants the info of a seed's game to repeat, and counts episodes itself.
    info = {k: v[sel].copy() for k, v in ts.info.items() if k != "episode_id"}
    info["rewards"] = ts.rewards[sel].copy()
    info["current_player"] = ts.current_player[sel].copy()
    return info


class RinshanEnv(gymnasium.Env):
    """One game of `variant`, every seat played by the caller.

    Args:
        variant: The rule set (`rinshan.VARIANTS`).
        mode: `half`, `east` or `single` (`rinshan.MODES`).
        penalty: Points an illegal action costs (None: the rule set's own).

    Example:
        >>> from rinshan.wrappers.gymnasium import RinshanEnv
        >>> env = RinshanEnv("red")
        >>> obs, info = env.reset(seed=3)
        >>> sorted(obs)
        ['action_mask', 'planes', 'scalars']
        >>> action = int(obs["action_mask"].argmax())
        >>> obs, reward, terminated, truncated, info = env.step(action)
        >>> env.close()
    """

    metadata = {"render_modes": []}

    def __init__(self, variant: str = "red", mode: str = "half", penalty: Optional[float] = None):
        self._env = Env(
            variant,
            mode=mode,
            num_envs=1,
            observation=("planes",),
            auto_reset=False,
            num_threads=1,
            penalty=penalty,
        )
        n = self._env.spec.num_actions
        self.observation_space = planes_space(n)
        self.action_space = spaces.Discrete(n)
        self._actor = 0

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """A new game (the same seed deals the same game); returns `(observation, info)`."""
        super().reset(seed=seed)
        if seed is None:
            seed = int(self.np_random.integers(0, 2**63))
        ts = self._env.reset(seed=seed)
        self._actor = int(ts.current_player[0])
        return _obs(ts, 0), _info(ts, 0)

    def step(self, action: Any):
        """The seat to act plays `action`; returns `(observation, reward, terminated, truncated,
        info)` with the observation of the next seat to act and the reward of the one that
        acted."""
        actor = self._actor
        ts = self._env.step(np.array([int(action)]))
        self._actor = int(ts.current_player[0])
        return (
            _obs(ts, 0),
            float(ts.rewards[0, actor]),
            bool(ts.terminated[0]),
            bool(ts.truncated[0]),
            _info(ts, 0),
        )

    def close(self):
        """Frees the game."""
        self._env.close()


class RinshanVectorEnv(gymnasium.vector.VectorEnv):
    """`num_envs` games stepped together, with same-step auto-reset.

    Args:
        variant: The rule set (`rinshan.VARIANTS`).
        num_envs: Games in the batch.
        **kwargs: `rinshan.make`'s other arguments (`mode`, `seed`, `backend`, `opponents` and
            `hero_seats`...); the observation is the planes form.

    Raises:
        ValueError: An observation other than the planes form, or what `rinshan.make` refuses.
    """

    metadata = {"autoreset_mode": gymnasium.vector.AutoresetMode.SAME_STEP, "render_modes": []}

    def __init__(self, variant: str = "red", num_envs: int = 16, **kwargs: Any):
        kwargs.setdefault("observation", ("planes",))
        if tuple(kwargs["observation"]) != ("planes",):
            raise ValueError("the Gymnasium adapter observes the planes form")
        self._env = Env(variant, num_envs=num_envs, auto_reset=True, **kwargs)
        n = self._env.spec.num_actions
        self.num_envs = num_envs
        self.single_observation_space = planes_space(n)
        self.single_action_space = spaces.Discrete(n)
        self.observation_space = gymnasium.vector.utils.batch_space(
            self.single_observation_space, num_envs
        )
        self.action_space = gymnasium.vector.utils.batch_space(self.single_action_space, num_envs)
        self._actors = np.zeros(num_envs, dtype=np.int64)

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """New games; returns the batched `(observations, infos)`."""
        ts = self._env.reset(seed=seed)
        self._actors = ts.current_player.astype(np.int64)
        return _obs(ts), _info(ts)

    def step(self, actions: Any):
        """One action per game; returns batched `(observations, rewards, terminated, truncated,
        infos)`, each reward that of the seat that acted."""
        actors = self._actors
        ts = self._env.step(np.asarray(actions))
        rewards = ts.rewards[np.arange(self.num_envs), actors].astype(np.float32)
        self._actors = ts.current_player.astype(np.int64)
        return _obs(ts), rewards, ts.terminated.copy(), ts.truncated.copy(), _info(ts)

    def close_extras(self, **kwargs):
        """Frees the games (Gymnasium's `close` calls it)."""
        self._env.close()
