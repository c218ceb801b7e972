"""A PettingZoo AEC env: one game, agents `player_0`..`player_3` (absolute seats; `player_2` the
last in a three-player variant), each observing
the planes form from its own seat with its legal mask inside the observation (`action_mask`, all
zeros when it is not that player's decision). Rewards are each step's score changes."""

from __future__ import annotations

from typing import Optional

import numpy as np
from gymnasium import spaces
from pettingzoo import AECEnv

from ..env import Env
from ._spaces import planes_space


class RinshanAECEnv(AECEnv):
    """One game as a PettingZoo AEC env, agents `player_0`.. by absolute seat.

    Args:
        variant: The rule set (`rinshan.VARIANTS`); a three-player one has three agents.
        mode: `half`, `east` or `single` (`rinshan.MODES`).

    Example:
        >>> from rinshan.wrappers.pettingzoo import RinshanAECEnv
        >>> env = RinshanAECEnv("sanma")
        >>> env.reset(seed=1)
        >>> env.possible_agents
        ['player_0', 'player_1', 'player_2']
        >>> mask = env.observe(env.agent_selection)["action_mask"]
        >>> env.step(int(mask.argmax()))
        >>> env.close()
    """

    metadata = {"name": "rinshan_v0", "render_modes": [], "is_parallelizable": False}

    def __init__(self, variant: str = "red", mode: str = "half"):
        super().__init__()
        self._env = Env(
            variant, mode=mode, num_envs=1, observation=("planes",), auto_reset=False, num_threads=1
        )
        n = self._env.spec.num_actions
        self.possible_agents = [f"player_{i}" for i in range(self._env.spec.num_players)]
        self.agents = []
        self._obs_space = planes_space(n)
        self._act_space = spaces.Discrete(n)
        self._seed = None

    def observation_space(self, agent):
        """The planes form's `Dict` space with `action_mask` (the same for every agent)."""
        return self._obs_space

    def action_space(self, agent):
        """`Discrete(A)`, the variant's action ids."""
        return self._act_space

    def observe(self, agent):
        """`agent`'s planes observation, its legal mask all zeros unless it is to act."""
        seat = self.possible_agents.index(agent)
        obs = {k: v[0] for k, v in self._env.observe(seat, "planes").items()}
        ts = self._env.timestep
        decides = int(ts.current_player[0]) == seat and not ts.terminated[0]
        mask = ts.legal_action_mask[0] if decides else np.zeros_like(ts.legal_action_mask[0])
        obs["action_mask"] = mask.astype(np.int8)
        return obs

    def reset(self, seed: Optional[int] = None, options: Optional[dict] = None):
        """A new game; a seed starts a sequence of games that repeats."""
        if seed is not None:
            self._seed = np.random.SeedSequence(seed)
        elif self._seed is None:
            self._seed = np.random.SeedSequence()
        game_seed = int(self._seed.spawn(1)[0].generate_state(1, np.uint64)[0])
        ts = self._env.reset(seed=game_seed)
        self.agents = self.possible_agents[:]
        self.rewards = {a: 0.0 for a in self.agents}
        self._cumulative_rewards = {a: 0.0 for a in self.agents}
        self.terminations = {a: False for a in self.agents}
        self.truncations = {a: False for a in self.agents}
        self.infos = {a: {} for a in self.agents}
        self.agent_selection = self.possible_agents[int(ts.current_player[0])]

    def step(self, action):
        """`agent_selection` plays `action` (a finished agent's step is PettingZoo's dead step)."""
        agent = self.agent_selection
        if self.terminations[agent] or self.truncations[agent]:
            self._was_dead_step(action)
            return
        self._cumulative_rewards[agent] = 0.0
        ts = self._env.step(np.array([int(action)]))
        for i, a in enumerate(self.possible_agents):
            self.rewards[a] = float(ts.rewards[0, i])
        if ts.terminated[0] or ts.truncated[0]:
            for a in self.agents:
                self.terminations[a] = bool(ts.terminated[0])
                self.truncations[a] = bool(ts.truncated[0])
                self.infos[a] = {
                    "final_score": int(ts.info["final_scores"][0, self.possible_agents.index(a)]),
                    "final_rank": int(ts.info["final_rank"][0, self.possible_agents.index(a)]),
                }
        else:
            self.agent_selection = self.possible_agents[int(ts.current_player[0])]
        self._accumulate_rewards()

    def render(self):
        """Nothing: draw the table with `rinshan.Env.render` or `rinshan render`."""
        return None

    def close(self):
        """Frees the game."""
        self._env.close()
