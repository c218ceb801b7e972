"""A small MJAI bot for rinshan's tests (Python standard library only).

It keeps its own hand from the events, discards what it draws, pons whenever it holds a pair of
the discarded tile (then discards a tile of another kind) and passes everything else. At a
three-player table (`start_kyoku` lists three scores) it sets a drawn North aside (`kita`) in the
first ten turns of a round, when the wall surely has a replacement tile. Modes that
misbehave on purpose exercise the host's penalties: `garbage`, `sleep`, `die`, `flood`,
`wrong-actor` and `illegal` do so at the bot's third decision.

    python3 simple_bot.py --dialect app|stdio [--mode MODE] SEAT
"""

import json
import sys
import time


def kind(tile):
    return tile[:2] if tile.endswith("r") else tile


class Bot:
    def __init__(self, seat, mode):
        self.seat = seat
        self.mode = mode
        self.hand = []
        self.turns = 0
        self.three = False
        self.round_turns = 0

    def update(self, e):
        t = e["type"]
        if t == "start_kyoku":
            self.hand = list(e["tehais"][self.seat])
            self.three = len(e["scores"]) == 3
            self.round_turns = 0
        elif e.get("actor") != self.seat:
            return
        elif t == "tsumo":
            self.hand.append(e["pai"])
        elif t == "dahai":
            self.hand.remove(e["pai"])
        elif t in ("pon", "chi"):
            for c in e["consumed"]:
                self.hand.remove(c)
        elif t == "kita":
            self.hand.remove(e["pai"])

    def react(self, last):
        """The reaction to the event `last`, which the bot can act on."""
        t = last["type"]
        mine = last.get("actor") == self.seat
        if t not in ("tsumo", "pon", "dahai") or (t == "dahai" and mine):
            return {"type": "none"}
        if t == "tsumo" and mine:
            self.turns += 1
            self.round_turns += 1
            if self.turns == 3 and self.mode != "play":
                return self.misbehave(last)
            if self.three and last["pai"] == "N" and self.round_turns <= 10:
                return {"type": "kita", "actor": self.seat, "pai": "N"}
            return {"type": "dahai", "actor": self.seat, "pai": last["pai"], "tsumogiri": True}
        if t == "pon" and mine:
            other = [x for x in self.hand if kind(x) != kind(last["pai"])]
            return {"type": "dahai", "actor": self.seat, "pai": other[-1], "tsumogiri": False}
        pair = [x for x in self.hand if kind(x) == kind(last["pai"])][:2]
        if t == "dahai" and len(pair) == 2:
            return {
                "type": "pon",
                "actor": self.seat,
                "target": last["actor"],
                "pai": last["pai"],
                "consumed": pair,
            }
        return {"type": "none"}

    def misbehave(self, last):
        if self.mode == "garbage":
            return "this is not a reaction {"
        if self.mode == "sleep":
            time.sleep(3600)
        if self.mode == "die":
            print("simple_bot: dying on purpose", file=sys.stderr, flush=True)
            sys.exit(3)
        if self.mode == "flood":
            sys.stdout.write("x" * (3 << 20))
            sys.stdout.flush()
            time.sleep(3600)
        if self.mode == "wrong-actor":
            return {
                "type": "dahai",
                "actor": (self.seat + 1) % 4,
                "pai": last["pai"],
                "tsumogiri": True,
            }
        # illegal: a discard of a tile the hand does not hold.
        missing = next(t for t in ("E", "S", "W", "N", "P", "F", "C") if t not in self.hand)
        return {"type": "dahai", "actor": self.seat, "pai": missing, "tsumogiri": False}


def send(reaction):
    text = reaction if isinstance(reaction, str) else json.dumps(reaction)
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def main():
    args = sys.argv[1:]
    seat = int(args[-1])
    dialect = args[args.index("--dialect") + 1]
    mode = args[args.index("--mode") + 1] if "--mode" in args else "play"
    bot = Bot(seat, mode)
    for line in sys.stdin:
        if dialect == "app":
            events = json.loads(line)
            for e in events:
                bot.update(e)
            send(bot.react(events[-1]))
        else:
            e = json.loads(line)
            bot.update(e)
            if e.get("can_act", True):
                send(bot.react(e))


if __name__ == "__main__":
    main()
