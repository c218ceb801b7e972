"""mjai.app's RulebaseBot in Mortal's stdio dialect, checking the host against libriichi.

Run with the `mjai` package of PyPI (0.2.1; AGPL-3.0, installed only in a test virtualenv).
Beside the bot, a `PlayerState` of Mortal's rules engine (`mjai.mlibriichi`) follows every event
the host sends, and the bot fails (a message on stderr, exit status 3) when:

* an event does not fit the state so far (`PlayerState.update` refuses it);
* the host asks the bot to act where libriichi says it cannot, or tells it an event with
  `"can_act": false` where libriichi says it can;
* its own reaction does not pass `PlayerState.validate_reaction`.

    python checked_rulebase.py SEAT
"""

import json
import sys

from mjai.bot.rulebase import RulebaseBot
from mjai.mlibriichi.state import PlayerState


def fail(message):
    print(f"checked_rulebase: {message}", file=sys.stderr, flush=True)
    sys.exit(3)


def main():
    seat = int(sys.argv[-1])
    bot = RulebaseBot(seat)
    check = PlayerState(seat)
    pending = []
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
        pending.append(event)
        if not can_act:
            continue
        reaction = bot.react(json.dumps(pending))
        pending = []
        try:
            check.validate_reaction(reaction)
        except Exception as e:
            fail(f"the bot's own reaction {reaction} to {event} is invalid: {e}")
        asked += 1
        sys.stdout.write(reaction + "\n")
        sys.stdout.flush()
    print(f"checked_rulebase: seat {seat} answered {asked} questions", file=sys.stderr)


if __name__ == "__main__":
    main()
