"""The examples run: Ray rollouts on a local instance with two actors, the numpy random agent,
and the PyTorch policy where torch is installed."""

import importlib.util
import pathlib
import re
import runpy
import subprocess
import sys

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


def test_ray_rollouts_with_two_local_actors():
    import ray

    mod = runpy.run_path(str(EXAMPLES / "ray_rollouts.py"))
    # One local Ray instance for both checks: starting Ray is most of the test's time.
    try:
        summaries = mod["run"](actors=2, iterations=2, steps=32, num_envs=16)
        actor = mod["RolloutActor"].remote(0, 8, None)
        b = ray.get(actor.rollout.remote(np.zeros((64 * 34, 87), np.float32), 50))
    finally:
        ray.shutdown()
    assert [s["steps"] for s in summaries] == [2 * 32 * 16] * 2
    # Every action gathered was legal for the seat that chose it.
    t, n = b["actions"].shape
    assert b["legal_action_mask"][np.arange(t)[:, None], np.arange(n), b["actions"]].all()


def run_example(name: str) -> str:
    return subprocess.run(
        [sys.executable, str(EXAMPLES / name)],
        check=True,
        capture_output=True,
        text=True,
        timeout=600,
    ).stdout


def test_random_agent_example():
    assert "games finished" in run_example("random_agent.py")


@pytest.mark.skipif(importlib.util.find_spec("torch") is None, reason="torch is not installed")
def test_torch_policy_example():
    out = run_example("torch_policy.py")
    # It plays until games end (it once stopped after 200 steps: "0 games finished").
    assert re.search(r"[1-9][0-9]* games finished, no illegal action", out), out
