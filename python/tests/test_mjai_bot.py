"""`rinshan.mjai.Bot`: a Python policy as an MJAI bot. It answers each line of the host, asks
the policy only at its seat's decisions with that seat's observation and legal mask, and turns
the action id into the reaction; examples/mjai/bot.py plays whole arena games through the CLI."""

import json
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import rinshan
import rinshan.mjai

ROOT = pathlib.Path(__file__).resolve().parents[2]
HAND = ["1m", "2m", "3m", "4p", "5p", "6p", "7s", "8s", "9s", "E", "E", "P", "P"]
HIDDEN = ["?"] * 13


def kyoku(seat=1):
    tehais = [HIDDEN] * 4
    tehais[seat] = HAND
    return {
        "type": "start_kyoku",
        "bakaze": "E",
        "dora_marker": "1s",
        "kyoku": 1,
        "honba": 0,
        "kyotaku": 0,
        "oya": 0,
        "scores": [25000] * 4,
        "tehais": tehais,
    }


class Recorder(rinshan.mjai.Bot):
    """Plays the first legal action named in `prefer`, else the first legal one; keeps what
    it was shown."""

    prefer = ("ron", "tsumo", "pass")

    def __init__(self, *args, **kw):
        super().__init__(*args, **kw)
        self.seen = []

    def act(self, observation, legal_mask):
        names = [self.action_names[i] for i in np.flatnonzero(legal_mask)]
        self.seen.append((observation, names))
        for want in self.prefer:
            if want in names:
                return self.action_names.index(want)
        return int(np.flatnonzero(legal_mask)[0])


def test_the_policy_is_asked_at_the_seats_decisions_with_its_observation():
    bot = Recorder()
    assert bot.react(json.dumps([{"type": "start_game", "id": 1}])) == '{"type":"none"}'
    assert bot.seat == 1
    # Seat 0 discards E: seat 1 holds a pair of E and waits on E and P, so it may ron or pon.
    line = [kyoku(), {"type": "tsumo", "actor": 0, "pai": "?"}]
    line.append({"type": "dahai", "actor": 0, "pai": "E", "tsumogiri": True})
    reply = json.loads(bot.react(json.dumps(line)))
    assert reply == {"type": "hora", "actor": 1, "target": 0, "pai": "E"}
    observation, names = bot.seen[-1]
    assert names == ["ron", "pon", "pass"]
    # The observation is the seat's, as an env gives it: its hand on the first planes.
    hand = (observation["planes"][:4] > 0).sum(axis=0)
    assert hand.sum() == 13 and hand[27] == 2 and hand[31] == 2
    # Nothing to decide on another seat's draw.
    assert bot.react(json.dumps([{"type": "tsumo", "actor": 2, "pai": "?"}])) == '{"type":"none"}'
    assert len(bot.seen) == 1


def test_stdio_dialect_answers_only_when_the_seat_can_act():
    bot = Recorder(seat=1, dialect="stdio")
    assert bot.react(json.dumps({"type": "start_game"})) is None
    assert bot.react(json.dumps(kyoku())) is None
    assert bot.react(json.dumps({"type": "tsumo", "actor": 0, "pai": "?"})) is None
    reply = bot.react(json.dumps({"type": "dahai", "actor": 0, "pai": "9m", "tsumogiri": True}))
    assert reply is None  # nothing to claim on a 9m
    reply = bot.react(json.dumps({"type": "tsumo", "actor": 1, "pai": "N"}))
    assert json.loads(reply)["actor"] == 1
    # Mortal's hint: told only.
    told = {"type": "dahai", "actor": 1, "pai": "N", "tsumogiri": True, "can_act": False}
    assert bot.react(json.dumps(told)) is None


class Broken(rinshan.mjai.Bot):
    def __init__(self, returns, **kw):
        super().__init__(**kw)
        self.returns = returns

    def act(self, observation, legal_mask):
        if isinstance(self.returns, Exception):
            raise self.returns
        return self.returns


@pytest.mark.parametrize("returns", [RuntimeError("boom"), 84, 10_000])
def test_a_failing_policy_is_reported_and_answered_legally(returns, capsys):
    # 84 is pass, not legal on a turn; 10000 is no action at all.
    bot = Broken(returns, seat=1)
    line = [kyoku(), {"type": "tsumo", "actor": 0, "pai": "?"}]
    line.append({"type": "dahai", "actor": 0, "pai": "9m", "tsumogiri": True})
    line.append({"type": "tsumo", "actor": 1, "pai": "N"})
    # Its own turn: the fallback discards the drawn tile.
    reply = json.loads(bot.react(json.dumps(line)))
    assert reply == {"type": "dahai", "actor": 1, "pai": "N", "tsumogiri": True}
    err = capsys.readouterr().err
    assert "the policy failed" in err
    # Garbage is reported and answered with none.
    assert bot.react("not json") == '{"type":"none"}'
    assert "not JSON" in capsys.readouterr().err


def test_bad_arguments_raise():
    with pytest.raises(ValueError):
        rinshan.mjai.Bot(seat=7)
    with pytest.raises(ValueError):
        rinshan.mjai.Bot(dialect="tcp").react("[]")

    class Oracle(rinshan.mjai.Bot):
        observation = ("oracle",)

    with pytest.raises(ValueError):
        Oracle()


@pytest.mark.parametrize("dialect", ["app", "stdio"])
def test_the_example_bot_plays_arena_games(cli, dialect):
    bot = f"mjai:{sys.executable} {ROOT / 'examples' / 'mjai' / 'bot.py'} --dialect {dialect}"
    args = ["arena", "--agents", f"defensive,greedy,rule,{bot}", "--mjai-dialect", dialect]
    args += ["--games", "4", "--mode", "east", "--json"]
    out = subprocess.run([cli, *args], check=True, capture_output=True, text=True).stdout
    report = json.loads(out)
    assert report["faults"] == []
    me = next(s for s in report["standings"] if s["agent"] == bot)
    assert me["games"] == 4 and me["illegal"] == 0


def test_the_example_net_bot_maps_its_nets_actions(tmp_path, capsys):
    """examples/mjai/bot.py's NetBot plays a trained net's choice in the bot's (red) ids, whatever
    the net's layout: here a net whose logits are in reverse order, biased towards ron."""
    torch = pytest.importorskip("torch")
    sys.path.insert(0, str(ROOT / "examples" / "mjai"))
    sys.path.insert(0, str(ROOT / "examples" / "train"))
    from bot import NetBot
    from common import ACTIONS, Net, save

    names = list(reversed(ACTIONS))
    net = Net(len(names), 16, 1, actions=names)
    with torch.no_grad():
        net.head.weight.zero_()
        net.head.bias.zero_()
        net.head.bias[names.index("ron")] = 10.0
    save(net, tmp_path / "model.pt")
    bot = NetBot(tmp_path / "model.pt", 1, "app")
    line = [kyoku(), {"type": "tsumo", "actor": 0, "pai": "?"}]
    line.append({"type": "dahai", "actor": 0, "pai": "E", "tsumogiri": True})
    reply = json.loads(bot.react(json.dumps(line)))
    assert reply == {"type": "hora", "actor": 1, "target": 0, "pai": "E"}
    assert "the policy failed" not in capsys.readouterr().err
