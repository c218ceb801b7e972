"""The examples run: Ray rollouts on a local instance with two actors, the numpy random agent,
and the PyTorch policy where torch is installed."""

import importlib.util
import pathlib
import runpy
import subprocess
import sys

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


def test_ray_rollouts_with_two_local_actors():
    import ray

    mod = runpy.run_path(str(EXAMPLES / "ray_rollouts.py"))
    try:
        summaries = mod["run"](actors=2, iterations=2, steps=32, num_envs=16)
    finally:
        ray.shutdown()
    assert [s["steps"] for s in summaries] == [2 * 32 * 16] * 2


def test_ray_actor_trajectories_are_consistent():
    import ray

    mod = runpy.run_path(str(EXAMPLES / "ray_rollouts.py"))
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        actor = mod["RolloutActor"].remote(0, 8, None)
        w = np.zeros((64 * 34, 87), np.float32)
        b = ray.get(actor.rollout.remote(w, 50))
    finally:
        ray.shutdown()
    # Every action gathered was legal for the seat that chose it.
    t, n = b["actions"].shape
    assert b["legal_action_mask"][np.arange(t)[:, None], np.arange(n), b["actions"]].all()


def test_random_agent_example():
    out = subprocess.run(
        [sys.executable, str(EXAMPLES / "random_agent.py")],
        check=True,
        capture_output=True,
        text=True,
        timeout=600,
    ).stdout
    assert "games finished" in out


@pytest.mark.skipif(importlib.util.find_spec("torch") is None, reason="torch is not installed")
def test_torch_policy_example():
    out = subprocess.run(
        [sys.executable, str(EXAMPLES / "torch_policy.py")],
        check=True,
        capture_output=True,
        text=True,
        timeout=600,
    ).stdout
    assert "no illegal action" in out
