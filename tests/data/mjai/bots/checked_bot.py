"""An MJAI bot in Mortal's stdio dialect whose every exchange is checked against libriichi.

Run with the `mjai` package of PyPI (0.2.1; AGPL-3.0, installed only in a test virtualenv).
The bot is mjai.app's RulebaseBot, or with `--inner COMMAND` another bot run as
`COMMAND SEAT` in the same dialect (`rinshan mjai-bot --dialect stdio`), whose lines are passed
through. Beside it, a `PlayerState` of Mortal's rules engine (`mjai.mlibriichi`) follows every event
the host sends, and the bot fails (a message on stderr, exit status 3) when:

* an event does not fit the state so far (`PlayerState.update` refuses it);
* the host asks the bot to act where libriichi says it cannot, or tells it an event with
  `"can_act": false` where libriichi says it can;
* the reaction does not pass `PlayerState.validate_reaction`.

    python checked_bot.py [--inner COMMAND] SEAT
"""

import json
import shlex
import subprocess
import sys

from mjai.bot.rulebase import RulebaseBot
from mjai.mlibriichi.state import PlayerState


def fail(message):
    print(f"checked_bot: {message}", file=sys.stderr, flush=True)
    sys.exit(3)


class Inner:
    """A stdio-dialect bot in a child process."""

    def __init__(self, command, seat):
        self.proc = subprocess.Popen(
            [*shlex.split(command), str(seat)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )

    def send(self, event, can_act):
        line = json.dumps(event if can_act else {**event, "can_act": False})
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()
        if not can_act:
            return None
        reply = self.proc.stdout.readline()
        if not reply:
            fail(f"the inner bot stopped answering at {event}")
        return reply.strip()


class Rulebase:
    """mjai.app's RulebaseBot, told events in batches as mjai.app does."""

    def __init__(self, seat):
        self.bot = RulebaseBot(seat)
        self.pending = []

    def send(self, event, can_act):
        self.pending.append(event)
        if not can_act:
            return None
        reply = self.bot.react(json.dumps(self.pending))
        self.pending = []
        return reply


def main():
    args = sys.argv[1:]
    seat = int(args[-1])
    bot = Inner(args[args.index("--inner") + 1], seat) if "--inner" in args else Rulebase(seat)
    check = PlayerState(seat)
    asked = 0
    for line in sys.stdin:
        event = json.loads(line)
        can_act = event.pop("can_act", True)
        try:
            cans = check.update(json.dumps(event))
        except Exception as e:
            fail(f"libriichi refuses {event}: {e}")
        if can_act != cans.can_act:
            fail(f"the host {'asks' if can_act else 'does not ask'} at {event}, libriichi: {cans}")
        reaction = bot.send(event, can_act)
        if reaction is None:
            continue
        try:
            check.validate_reaction(reaction)
        except Exception as e:
            fail(f"the reaction {reaction} to {event} is invalid: {e}")
        asked += 1
        sys.stdout.write(reaction + "\n")
        sys.stdout.flush()
    print(f"checked_bot: seat {seat} answered {asked} questions", file=sys.stderr)


if __name__ == "__main__":
    main()
