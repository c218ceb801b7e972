"""Bad input raises a Python exception with a clear message; nothing crashes the interpreter."""

import numpy as np
import pytest

import rinshan


@pytest.fixture
def env():
    e = rinshan.make(num_envs=4, num_threads=1)
    e.reset()
    return e


def test_bad_actions(env):
    with pytest.raises(ValueError, match=r"shape \(3,\)"):
        env.step(np.zeros(3, dtype=int))
    with pytest.raises(TypeError, match="integers"):
        env.step(np.zeros(4))
    with pytest.raises(TypeError, match="integers"):
        env.step(np.zeros(4, dtype=bool))
    with pytest.raises(ValueError, match="action 87 of env 2 is out of range"):
        env.step(np.array([0, 0, 87, 0]))
    with pytest.raises(ValueError, match="out of range"):
        env.step(np.array([-1, 0, 0, 0]))
    with pytest.raises(ValueError, match="out of range"):
        env.step(np.array([2**64 - 1, 0, 0, 0], dtype=np.uint64))
    with pytest.raises(ValueError):
        env.step(np.zeros((4, 1), dtype=int))


def test_an_illegal_action_in_range_ends_only_that_game(env):
    ts = env.timestep
    legal = ts.legal_action_mask
    a = np.argmax(legal, axis=1)
    a[1] = int(np.flatnonzero(~legal[1])[0])
    actor = int(ts.current_player[1])
    ts = env.step(a)
    assert ts.info["illegal"].tolist() == [False, True, False, False]
    assert ts.terminated[1] and ts.rewards[1, actor] == -1.0
    # No standings for a game that did not end by the rules; its scores are where they stood.
    assert (ts.info["final_rank"][1] == -1).all()
    assert (ts.info["final_scores"][1] == 25000).all()


def test_bad_configuration():
    with pytest.raises(ValueError, match="unknown variant"):
        rinshan.make("blue")
    with pytest.raises(ValueError, match="mode"):
        rinshan.make(mode="forever")
    with pytest.raises(ValueError, match="at least 1"):
        rinshan.make(num_envs=0)
    with pytest.raises(ValueError, match="num_envs 1099511627776 needs about"):
        rinshan.make(num_envs=2**40)
    with pytest.raises(TypeError):
        rinshan.make(num_envs=2.5)
    with pytest.raises(TypeError, match="seed must be an int"):
        rinshan.make(num_envs=2, seed="1")
    with pytest.raises(TypeError, match="num_threads must be an int"):
        rinshan.make(num_envs=2, num_threads=1.5)
    with pytest.raises(ValueError, match="seed must be in"):
        rinshan.make(num_envs=2, seed=-1)
    with pytest.raises(ValueError, match="unknown observation form"):
        rinshan.make(observation=("pixels",))
    with pytest.raises(ValueError, match="opponents"):
        rinshan.make(num_envs=2, opponents="genius")
    with pytest.raises(ValueError, match="hero seats"):
        rinshan.make(num_envs=2, opponents="rule", hero_seats=7)
    with pytest.raises(ValueError, match="hero_seats has 3 entries"):
        rinshan.make(num_envs=2, opponents="rule", hero_seats=[0, 1, 2])
    with pytest.raises(ValueError, match="needs opponents"):
        rinshan.make(num_envs=2, hero_seats=1)
    with pytest.raises(ValueError, match="backend"):
        rinshan.make(num_envs=2, backend="tpu")


def test_bad_observe_and_state(env):
    with pytest.raises(ValueError, match="seats are 0..3"):
        env.observe(5)
    with pytest.raises(ValueError):
        env.observe(np.zeros(3, dtype=int))
    with pytest.raises(TypeError):
        env.set_state(np.zeros((4, 10), dtype=np.int64))
    with pytest.raises(ValueError, match="shape"):
        env.set_state(np.zeros((4, 10), dtype=np.uint32))
    with pytest.raises(ValueError, match="check words"):
        env.set_state(np.zeros_like(env.get_state()))


def test_closed_env_raises(env):
    env.close()
    assert env.closed
    with pytest.raises(RuntimeError, match="closed"):
        env.step(np.zeros(4, dtype=int))
    with pytest.raises(RuntimeError, match="closed"):
        env.reset()
    with pytest.raises(RuntimeError, match="closed"):
        env.get_state()


def test_bad_log_paths():
    with pytest.raises(ValueError):
        rinshan.tenhou.read("/nonexistent/game.json")
