"""Rollouts on Ray: each actor holds a batched env and returns trajectories to a learner.

    pip install "ray[default]"
    python examples/ray_rollouts.py --actors 2 --iterations 3

On a cluster, start Ray there (`ray start --head` on one node, `ray start --address=HEAD:6379` on
the others) and pass `--address auto` (or the head's address): the actors spread over its nodes.
"""

from __future__ import annotations

import argparse

import numpy as np
import ray

import rinshan


@ray.remote
class RolloutActor:
    """A batch of games and a linear softmax policy over the planes."""

    def __init__(self, seed: int, num_envs: int, opponents: str | None):
        self.env = rinshan.make(
            "red", num_envs=num_envs, seed=seed, num_threads=1, opponents=opponents
        )
        self.rng = np.random.default_rng(seed)
        self.ts = self.env.reset()

    def rollout(self, weights: np.ndarray, steps: int) -> dict:
        n = self.env.num_envs
        a_dim = self.env.spec.num_actions
        planes = np.empty((steps, n, 64 * 34), dtype=np.uint8)
        masks = np.empty((steps, n, a_dim), dtype=bool)
        actions = np.empty((steps, n), dtype=np.int64)
        players = np.empty((steps, n), dtype=np.int32)
        rewards = np.empty((steps, n, 4), dtype=np.float32)
        done = np.empty((steps, n), dtype=bool)
        for t in range(steps):
            ts = self.ts
            x = ts.observation["planes"].reshape(n, -1)
            logits = (x @ weights).astype(np.float64)
            logits[~ts.legal_action_mask] = -np.inf
            p = np.exp(logits - logits.max(axis=1, keepdims=True))
            p /= p.sum(axis=1, keepdims=True)
            a = (p.cumsum(axis=1) > self.rng.random((n, 1))).argmax(axis=1)
            planes[t], masks[t], actions[t] = x, ts.legal_action_mask, a
            players[t] = ts.current_player
            self.ts = self.env.step(a)
            rewards[t], done[t] = self.ts.rewards, self.ts.terminated
        return {
            "planes": planes,
            "legal_action_mask": masks,
            "actions": actions,
            "current_player": players,
            "rewards": rewards,
            "terminated": done,
        }


def run(
    actors: int = 2,
    iterations: int = 3,
    steps: int = 64,
    num_envs: int = 64,
    address: str | None = None,
    opponents: str | None = None,
) -> list:
    """Gathers `iterations` rounds of trajectories from `actors` actors; returns per-iteration
    summaries (steps gathered, games finished)."""
    if not ray.is_initialized():
        ray.init(
            address=address,
            num_cpus=None if address else actors,
            include_dashboard=False,
            log_to_driver=False,
        )
    workers = [RolloutActor.remote(seed, num_envs, opponents) for seed in range(actors)]
    weights = np.zeros((64 * 34, rinshan.make("red", num_envs=1).spec.num_actions), np.float32)
    summaries = []
    for it in range(iterations):
        batches = ray.get([w.rollout.remote(weights, steps) for w in workers])
        gathered = {k: np.concatenate([b[k] for b in batches], axis=1) for k in batches[0]}
        # A learner would update `weights` here; this example only gathers.
        summaries.append(
            {
                "iteration": it,
                "steps": int(gathered["actions"].size),
                "games": int(gathered["terminated"].sum()),
            }
        )
        print(summaries[-1])
    return summaries


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--actors", type=int, default=2)
    ap.add_argument("--iterations", type=int, default=3)
    ap.add_argument("--steps", type=int, default=64)
    ap.add_argument("--num-envs", type=int, default=64)
    ap.add_argument("--address", default=None, help="a Ray cluster (`auto` or HOST:PORT)")
    ap.add_argument("--opponents", default=None, help="hero mode against built-in agents")
    a = ap.parse_args()
    run(a.actors, a.iterations, a.steps, a.num_envs, a.address, a.opponents)
