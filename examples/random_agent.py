"""A uniformly random legal policy over a batch of games, in numpy.

python examples/random_agent.py
"""

import numpy as np

import rinshan

env = rinshan.make("red", num_envs=1024, seed=0)
rng = np.random.default_rng(0)
ts = env.reset()
games, points = 0, np.zeros(4)
for _ in range(2000):
    noise = rng.random(ts.legal_action_mask.shape)
    actions = np.argmax(np.where(ts.legal_action_mask, noise, -1.0), axis=1)
    ts = env.step(actions)
    games += int(ts.terminated.sum())
    points += ts.info["final_scores"][ts.terminated].sum(axis=0)
print(f"{games} games finished; average final scores by seat: {points / max(games, 1)}")
