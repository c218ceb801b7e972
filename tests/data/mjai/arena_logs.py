"""MJAI logs as libriichi's arena writes them: half games of four RulebaseBots in Mortal's
rules engine (`mjai.mlibriichi.arena.Match`, the engine of mjai.app and of Mortal's self-play).

Run with the `mjai` package of PyPI (0.2.1; AGPL-3.0, installed only in a test virtualenv,
`.ci/mjai-venv`). Each seed gives one game, written as OUT_DIR/arena-SEED.mjson.gz exactly as
the arena wrote it: a `hora` with only its deltas and ura markers, a `ryukyoku` with only its
deltas.

    python arena_logs.py OUT_DIR SEED [SEED ...]

The one change to RulebaseBot: its riichi discard keeps the hand tenpai. Left alone it
sometimes breaks tenpai with it, which libriichi lets through and Tenhou's rules do not, and a
log with such a riichi is not a game of Tenhou's rules.
"""

import json
import shutil
import sys
import tempfile
from pathlib import Path

from loguru import logger
from mjai.bot.rulebase import RulebaseBot
from mjai.mlibriichi.arena import Match

# RulebaseBot logs every discard it considers.
logger.remove()


class Player(RulebaseBot):
    def think(self) -> str:
        if self.can_discard and self.self_riichi_declared and not self.self_riichi_accepted:
            keep = sorted(self.discardable_tiles_riichi_declaration)
            if keep:
                return self.action_discard(keep[0])
        return super().think()


class Engine:
    """One of the arena's four engines: a Player per game, told each event once, as a seat
    sees it (others' draws and starting hands hidden)."""

    def __init__(self, name: str):
        self.engine_type = "mjai-log"
        self.name = name
        self.player_ids: list[int] = []
        self.players: dict[int, Player] = {}
        # Per game: the round's start_kyoku and how many of its events were told.
        self.told: dict[int, tuple[str, int]] = {}

    def set_player_ids(self, player_ids: list[int]):
        self.player_ids = player_ids

    def start_game(self, game: int):
        seat = self.player_ids[game]
        self.players[game] = Player(seat)
        start = {"type": "start_game", "names": ["0", "1", "2", "3"], "id": seat}
        self.players[game].react(json.dumps([start]))
        self.told.pop(game, None)

    def end_kyoku(self, game: int):
        self.told.pop(game, None)

    def end_game(self, game: int, scores: list[int]):
        pass

    def react_batch(self, game_states) -> list[str]:
        out = []
        for state in game_states:
            game = state.game_index
            seat = self.player_ids[game]
            # The events of the round so far, from its start_kyoku.
            events = json.loads(state.events_json)
            start = json.dumps(events[0])
            known, count = self.told.get(game, (None, 0))
            new = events[count if known == start else 0 :]
            self.told[game] = (start, len(events))
            for event in new:
                if event["type"] == "tsumo" and event["actor"] != seat:
                    event["pai"] = "?"
                if event["type"] == "start_kyoku":
                    event["tehais"] = [
                        hand if s == seat else ["?"] * 13 for s, hand in enumerate(event["tehais"])
                    ]
            out.append(self.players[game].react(json.dumps(new)))
        return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for seed in map(int, sys.argv[2:]):
        with tempfile.TemporaryDirectory() as tmp:
            Match(log_dir=tmp).py_match(*(Engine(str(i)) for i in range(4)), seed_start=(seed, 1))
            (log,) = Path(tmp).glob("*.json.gz")
            shutil.copyfile(log, out / f"arena-{seed}.mjson.gz")


if __name__ == "__main__":
    main()
