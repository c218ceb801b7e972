"""An mjai.app submission: a Python policy playing as an MJAI bot through `rinshan.mjai.Bot`.

mjai.app runs `python bot.py PLAYER_ID` and speaks to it on stdin/stdout (a JSON array of events
per line, one reaction per line). Zip this file at the root with the `rinshan` wheel (or install
it in the image) and, optionally, a `model.pt` checkpoint of examples/train (bc.py or ppo.py) next
to it: with one, the net chooses; without, a few plain rules do. Try it against rinshan's agents:

    rinshan arena --agents defensive,greedy,rule,mjai:"python examples/mjai/bot.py"
"""

from __future__ import annotations

import pathlib
import sys

import numpy as np

import rinshan.mjai

HERE = pathlib.Path(__file__).resolve().parent


class RulesBot(rinshan.mjai.Bot):
    """Wins when it can, declares riichi when it can, never calls, and discards the lonest tile:
    the one with the fewest tiles of its own kind and neighbours in hand."""

    names = np.array(rinshan.mjai.Bot.action_names)
    win = np.isin(names, ["tsumo", "ron"])
    riichi = names == "riichi"
    discard = np.char.startswith(names.astype(str), "discard_")
    pass_ = int(np.flatnonzero(names == "pass")[0])

    def act(self, observation: dict, legal_mask: np.ndarray) -> int:
        for wanted in (self.win, self.riichi):
            if (legal_mask & wanted).any():
                return int(np.flatnonzero(legal_mask & wanted)[0])
        if legal_mask[self.pass_]:
            return self.pass_
        choices = np.flatnonzero(legal_mask & self.discard)
        if len(choices) == 0:
            # Only the drawn tile to give up (tsumogiri), as in riichi.
            return int(legal_mask.argmax())
        held = (observation["planes"][:4] > 0).sum(axis=0)  # copies of each tile type in hand
        near = np.convolve(held, [1, 1, 1], mode="same")
        kinds = np.array([self.kind(self.names[a]) for a in choices])
        return int(choices[np.argmin(near[kinds] + held[kinds])])

    @staticmethod
    def kind(name: str) -> int:
        number, suit = int(name[-2]), "mpsz".index(name[-1])
        return suit * 9 + (number or 5) - 1


class NetBot(rinshan.mjai.Bot):
    """A net trained by examples/train: its most likely legal action."""

    def __init__(self, checkpoint: pathlib.Path, seat: int | None, dialect: str):
        super().__init__(seat, dialect)
        import torch

        sys.path.insert(0, str(HERE.parent / "train"))
        from common import Space, load_net, rows

        self.torch, self.rows = torch, rows
        self.net = load_net(checkpoint)
        # The bot's ids are red's; the net's layout may hold more (kita).
        self.space = Space(actions=self.net.actions, names=self.action_names)
        if self.net.analysis:
            self.observation = ("planes", "analysis")
            super().__init__(seat, dialect)

    def act(self, observation: dict, legal_mask: np.ndarray) -> int:
        batch = {k: v[None] for k, v in observation.items()}
        with self.torch.no_grad():
            logits = self.net(
                self.torch.from_numpy(self.rows(batch, self.net.analysis).copy()),
                self.torch.from_numpy(np.asarray(batch["scalars"]).copy()),
                self.torch.from_numpy(self.space.mask(legal_mask[None])),
            )
        return int(self.space.to_env(logits.argmax(1).numpy())[0])


def main() -> None:
    # mjai.app: `python bot.py SEAT`; `--dialect stdio` speaks Mortal's dialect instead.
    args = sys.argv[1:]
    seat = int(args[-1]) if args and args[-1].isdigit() else None
    dialect = args[args.index("--dialect") + 1] if "--dialect" in args else "app"
    model = HERE / "model.pt"
    bot = NetBot(model, seat, dialect) if model.exists() else RulesBot(seat, dialect)
    bot.start()


if __name__ == "__main__":
    main()
