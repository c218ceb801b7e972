"""The Gymnasium and PettingZoo adapters pass their libraries' own checkers."""

import numpy as np
from gymnasium.utils.env_checker import check_env
from pettingzoo.test import api_test

from rinshan.wrappers.gymnasium import RinshanEnv, RinshanVectorEnv
from rinshan.wrappers.pettingzoo import RinshanAECEnv


def test_gymnasium_env_checker():
    check_env(RinshanEnv(), skip_render_check=True)
    check_env(RinshanEnv("no-red", mode="single"), skip_render_check=True)


def test_gymnasium_vector_env_same_step_autoreset():
    v = RinshanVectorEnv(num_envs=8, num_threads=1)
    obs, info = v.reset(seed=3)
    assert v.observation_space.contains(obs)
    ended = 0
    for _ in range(3000):
        a = np.argmax(obs["action_mask"], axis=1)
        obs, rewards, terminated, truncated, info = v.step(a)
        assert v.observation_space.contains(obs)
        # Same-step auto-reset: the observation after a game ends is a new game's, with moves.
        assert obs["action_mask"].any(axis=1).all()
        ended += int(terminated.sum())
    assert ended > 0
    v.close()


def test_pettingzoo_api_test():
    api_test(RinshanAECEnv(), num_cycles=300)
    api_test(RinshanAECEnv("no-red", mode="single"), num_cycles=300)


def test_pettingzoo_plays_a_whole_game():
    env = RinshanAECEnv(mode="single")
    env.reset(seed=1)
    total = {a: 0.0 for a in env.possible_agents}
    for agent in env.agent_iter(10_000):
        obs, reward, term, trunc, info = env.last()
        total[agent] += reward
        action = None if term or trunc else int(np.flatnonzero(obs["action_mask"])[0])
        env.step(action)
    assert not env.agents
    # Points move between players: the game's rewards (uma included) sum to zero.
    assert abs(sum(total.values())) < 1e-3
    assert len(set(total.values())) > 1


def test_pettingzoo_three_player_game():
    env = RinshanAECEnv("sanma", mode="east")
    assert env.possible_agents == ["player_0", "player_1", "player_2"]
    api_test(RinshanAECEnv("sanma", mode="single"), num_cycles=300)
    env.reset(seed=4)
    total = {a: 0.0 for a in env.possible_agents}
    acted = set()
    for agent in env.agent_iter(20_000):
        obs, reward, term, trunc, info = env.last()
        total[agent] += reward
        if term or trunc:
            action = None
        else:
            acted.add(agent)
            action = int(np.flatnonzero(obs["action_mask"])[-1])
        env.step(action)
    assert not env.agents and acted == set(env.possible_agents)
    # Three players' points move among the three of them.
    assert abs(sum(total.values())) < 1e-3
