"""A trained net as the Rust side plays it (`net:PATH`): the training example's export read back
and run by rinshan-net gives PyTorch's logits on the same observations, and seated as the env's
opponents it plays the games PyTorch's greedy policy plays. Under CI torch must be there."""

import importlib.util
import os
import pathlib
import sys

import numpy as np
import pytest

import rinshan
from rinshan import _core

TRAIN = pathlib.Path(__file__).resolve().parents[2] / "examples" / "train"
HAVE = all(importlib.util.find_spec(m) for m in ("torch", "safetensors"))

pytestmark = pytest.mark.skipif(
    not HAVE and not os.environ.get("CI"),
    reason="no torch/safetensors (pip install -r examples/train/requirements.txt)",
)


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """A net of the seed's shape with random weights and scalar statistics, and its export."""
    import torch

    sys.path.insert(0, str(TRAIN))
    from common import ACTIONS, SCALARS, Net
    from export import export

    torch.manual_seed(3)
    net = Net(len(ACTIONS), 96, 2, analysis=True, tile_head=True, tile_hidden=24)
    with torch.no_grad():
        # Trained nets' statistics are far from 0 and 1: the normalisation must be read.
        net.scalar_mean.copy_(torch.rand(SCALARS) * 20)
        net.scalar_std.copy_(0.5 + torch.rand(SCALARS) * 10)
        for p in net.parameters():
            p.mul_(3.0)
    net.eval()
    path = tmp_path_factory.mktemp("net") / "net.safetensors"
    export(net, path)
    return net, path


@pytest.mark.parametrize("variant,mode", [("red", "half"), ("no-red", "single"), ("sanma", "east")])
def test_the_rust_net_gives_pytorchs_logits(exported, variant, mode):
    import torch
    from common import Space, tensors

    net, path = exported
    rust = _core.Net(str(path))
    assert rust.actions == list(net.actions)
    assert rust.analysis == ["discard_shanten", "discard_ukeire", "improving"]
    space = Space(variant, net.actions)
    env = rinshan.make(variant, num_envs=32, mode=mode, seed=5, analysis=True)
    ts = env.reset()
    rows = 0
    for _ in range(40):
        p, s, m = tensors(ts, space, net.analysis)
        with torch.no_grad():
            want = net(p, s, m).numpy()
        got = rust.logits(p.numpy(), s.numpy(), m.numpy())
        legal = m.numpy()
        np.testing.assert_allclose(got[legal], want[legal], rtol=1e-4, atol=1e-4)
        assert (got[~legal] == want[~legal]).all()
        assert (got.argmax(1) == want.argmax(1)).all()
        rows += len(want)
        ts = env.step(space.to_env(want.argmax(1)))
    assert rows == 32 * 40


@pytest.mark.parametrize("variant", ["red", "sanma"])
def test_net_opponents_play_pytorchs_games(exported, variant):
    """The same walls, the net in the other seats: once as `opponents="net:PATH"` (the Rust side
    plays it inside step), once as a PyTorch greedy policy function: the same results. One net
    plays four and three players (its layout holds kita)."""
    from common import greedy_policy

    net, path = exported
    kw = dict(games=16, seed=11, variant=variant, mode="east", analysis=True)
    rust = rinshan.evaluate("rule", opponents=f"net:{path}", **kw)
    torch_side = rinshan.evaluate("rule", opponents=greedy_policy(net, variant), **kw)
    assert rust.rank_counts == torch_side.rank_counts
    assert rust.average_score == torch_side.average_score
    # Not the same as any seating: the rule agent in their seats plays other games.
    assert rust.average_score != rinshan.evaluate("rule", opponents="rule", **kw).average_score


def test_a_file_that_is_not_a_net_is_a_value_error(tmp_path, exported):
    bad = tmp_path / "bad.safetensors"
    bad.write_bytes(b"not a net")
    with pytest.raises(ValueError, match="not a safetensors file"):
        _core.Net(str(bad))
    with pytest.raises(ValueError, match="no such file|No such file"):
        rinshan.make("red", num_envs=2, opponents=f"net:{tmp_path / 'missing.safetensors'}")
    # A net saved in red's layout, before kita joined the nets' actions, cannot play sanma.
    from common import RED, Net, action_names
    from export import export

    red_only = tmp_path / "red.safetensors"
    export(Net(len(action_names(RED)), 32, 1, analysis=True).eval(), red_only)
    with pytest.raises(ValueError, match="no logit for kita"):
        rinshan.make("sanma", num_envs=2, opponents=f"net:{red_only}")
    rust = _core.Net(str(exported[1]))
    with pytest.raises(ValueError, match="decisions"):
        rust.logits(
            np.zeros((2, 67, 34), np.uint8),
            np.zeros((3, 48), np.int16),
            np.ones((2, len(rust.actions)), bool),
        )
