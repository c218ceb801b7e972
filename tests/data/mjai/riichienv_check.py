"""rinshan's MJAI logs replayed in RiichiEnv (PyPI `riichienv` 0.4.11, test-only virtualenv):
every decision must be one of RiichiEnv's legal actions, and every win must score the same han,
fu and points in RiichiEnv's hand evaluator.

    python riichienv_check.py FOLDER [RULE]

prints a JSON summary; the exit status is 1 on a disagreement.

RULE is RiichiEnv's preset the games are replayed under: `tenhou` (the default, for rinshan's
`red`) or `mjsoul` (its `default_mjsoul()`, for rinshan's `mjsoul`).

Three-player games (a `start_kyoku` with three scores: rinshan's `sanma`) replay with the same
preset: RiichiEnv has no sanma preset, its replay turns three-player by the seat count. Their wins
are scored by RiichiEnv's three-player evaluator (`HandEvaluator3P`: the winner's kita as
nukidora, the 1m indicator showing 9m; the context's own calculator is the four-player one), a
tsumo is paid by two seats, and a kita's replacement draw, like a kan's, takes a live tile. Where
RiichiEnv gives double riichi to a first-turn riichi after a kita, which rinshan does not (a kita
ends the first go-round), the win is counted apart (`riichienv_double_riichi_after_kita`).
RiichiEnv's replay leaves its `kita` action's tile unset where its legal kita names the North, so
a kita is compared without its tile; and it stops at a discard or kita it finds illegal ("Replay
desync"), which is counted as an illegal decision. It does not notice a draw past the live wall's
end, so the live draws are counted here.

RiichiEnv's MJAI replay has quirks (0.4.11) that this check corrects from the log itself rather
than count as disagreements: it marks every ron as houtei and no win as rinshan kaihou (the
last-tile and replacement-tile flags are taken from the log's draws), it counts an added or open
kan's dora indicator twice (the indicators are taken from the log's `start_kyoku` and `dora`
events), and it misreads some closed kans' tiles (as 1m: such wins are counted apart as
`riichienv_misread`). Ura indicators count for a winner that declared riichi.
"""

import collections
import json
import pathlib
import sys

import riichienv
from riichienv._riichienv import HandEvaluator3P

HONORS = "ESWNPFC"
KITA = riichienv.ActionType.KITA
# Events after which the seat's next draw is a replacement tile.
REPLACED = ("ankan", "kakan", "daiminkan", "kita")
# Live draws of a round with no replacement draws: the wall less the dead wall and the hands.
LIVE = {4: 136 - 14 - 4 * 13, 3: 108 - 14 - 3 * 13}


def tile_id(name):
    """A plain copy of the tile in RiichiEnv's 136 ids (copy 0 of a five is the red one)."""
    if name in HONORS:
        kind = 27 + HONORS.index(name)
    else:
        kind = "mps".index(name[1]) * 9 + int(name[0]) - 1
    return kind * 4 + 1


def key(action):
    tile = None if action.action_type == KITA else action.tile
    return (str(action.action_type), tile, tuple(action.consume_tiles))


def live_draws(events):
    """Draws from the live wall, and the replacement draws taken off it, in `events`."""
    live, replace_next, replacement = 0, False, False
    for e in events:
        if e["type"] in REPLACED:
            replace_next = True
        elif e["type"] == "tsumo":
            live += not replace_next
            replacement, replace_next = replace_next, False
    return live, sum(e["type"] in REPLACED for e in events), replacement


def double_riichi_after_kita(hora, before, res):
    """RiichiEnv (0.4.11) gives double riichi to a first-turn riichi that a kita came before; a kita
    is a call that ends the first go-round (riichi.wiki, Daburu riichi: "In sanma, kita calls will
    also deny this yaku"), so rinshan scores plain riichi. Such a win differs by that han alone."""
    reach = next(
        i
        for i, e in enumerate(before + [hora])
        if e is hora or e.get("type") == "reach" and e["actor"] == hora["actor"]
    )
    kita_first = any(e["type"] == "kita" for e in before[:reach])
    theirs = [y.name_en for y in res.yaku_list()]
    ours = [name for name, _ in hora.get("yakus") or []]
    return (
        kita_first
        and "Double Riichi" in theirs
        and "riichi" in ours
        and res.han == (hora.get("fan") or 0) + 1
    )


def check_win(hora, before, context, seats, stats, bad):
    tsumo = hora["actor"] == hora["target"]
    live, taken, replacement = live_draws(before)
    last = live == LIVE[seats] - taken
    cond = context.conditions
    cond.houtei = not tsumo and last
    cond.haitei = tsumo and last and not replacement
    cond.rinshan = tsumo and replacement
    shown = [before[0]["dora_marker"]] + [e["dora_marker"] for e in before if e["type"] == "dora"]
    riichi = any(e["type"] == "reach" and e["actor"] == hora["actor"] for e in before)
    ura = [tile_id(x) for x in hora.get("ura_markers") or []] if riichi else []
    if seats == 3:
        # The context's `kita_count` is the winner's; the context's calculator ignores it.
        cond.is_sanma, cond.num_players = True, 3
        calculator = HandEvaluator3P(context.tiles, context.melds)
    else:
        calculator = context.create_calculator()
    res = calculator.calc(context.agari_tile, [tile_id(x) for x in shown], ura, cond)
    stats["wins"] += 1
    closed_kans = sorted(
        tile_id(e["consumed"][0]) // 4
        for e in before
        if e["type"] == "ankan" and e["actor"] == hora["actor"]
    )
    read = sorted(m.tiles[0] // 4 for m in context.melds if "Ankan" in str(m.meld_type))
    if not res.has_win_shape or read != closed_kans:
        stats["riichienv_misread"] += 1
        return
    oya = before[0]["oya"]
    if not tsumo:
        points = res.ron_agari
    elif hora["actor"] == oya:
        points = (seats - 1) * res.tsumo_agari_ko
    else:
        points = res.tsumo_agari_oya + (seats - 2) * res.tsumo_agari_ko
    same_han = res.yakuman or res.han == hora.get("fan")
    same_fu = hora.get("fu") is None or res.fu == hora["fu"]
    if not same_han and double_riichi_after_kita(hora, before, res):
        stats["riichienv_double_riichi_after_kita"] += 1
        return
    if not (same_han and same_fu and points == hora.get("hora_points")):
        stats["score_differs"] += 1
        mine = (hora.get("fan"), hora.get("fu"), hora.get("hora_points"), hora.get("yakus"))
        theirs = (res.han, res.fu, points, [y.name_en for y in res.yaku_list()])
        bad.append(f"win {hora}: rinshan {mine}, riichienv {theirs}")


def main():
    stats, bad = collections.Counter(), []
    rule = sys.argv[2] if len(sys.argv) > 2 else "tenhou"
    for path in sorted(pathlib.Path(sys.argv[1]).iterdir()):
        events = [json.loads(line) for line in path.open()]
        rounds = []
        for e in events:
            if e["type"] == "start_kyoku":
                rounds.append([e])
            elif rounds:
                rounds[-1].append(e)
        seats = len(rounds[0][0]["scores"]) if rounds else 4
        stats["games"] += 1
        stats[f"{seats}-player games"] += 1
        for i, kyoku in enumerate(
            riichienv.MjaiReplay.from_jsonl(str(path), rule=rule).take_kyokus()
        ):
            evs = rounds[i]
            stats["rounds"] += 1
            steps = iter(kyoku.steps(rule=kyoku.rule))
            while True:
                try:
                    seat, obs, action = next(steps)
                except StopIteration:
                    break
                except ValueError as e:
                    stats["illegal"] += 1
                    bad.append(f"{path.name} round {i}: {' '.join(str(e).split()[:16])}")
                    break
                stats["decisions"] += 1
                stats["kitas"] += action.action_type == KITA
                if key(action) not in {key(a) for a in obs.legal_actions()}:
                    stats["illegal"] += 1
                    bad.append(f"{path.name} round {i} seat {seat}: {action} is not legal")
            live, taken, _ = live_draws(evs)
            if live > LIVE[seats] - taken:
                stats["illegal"] += 1
                bad.append(
                    f"{path.name} round {i}: {live} live draws with {taken} replacement draws"
                )
            horas = [e for e in evs if e["type"] == "hora"]
            # Where Tenhou and Mahjong Soul part: three winners on one discard (Tenhou aborts).
            stats["triple_ron"] += len(horas) == 3
            for hora, context in zip(horas, kyoku.take_win_result_contexts()):
                check_win(hora, evs[: evs.index(hora)], context, seats, stats, bad)
    print(json.dumps({"rule": rule, "stats": stats, "disagreements": bad[:20]}))
    sys.exit(1 if stats["illegal"] or stats["score_differs"] else 0)


if __name__ == "__main__":
    main()
