"""rinshan's MJAI logs replayed in RiichiEnv (PyPI `riichienv` 0.4.11, test-only virtualenv):
every decision must be one of RiichiEnv's legal actions, and every win must score the same han,
fu and points in RiichiEnv's hand evaluator.

    python riichienv_check.py FOLDER [RULE]

prints a JSON summary; the exit status is 1 on a disagreement.

RULE is RiichiEnv's preset the games are replayed under: `tenhou` (the default, for rinshan's
`red`) or `mjsoul` (its `default_mjsoul()`, for rinshan's `mjsoul`).

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

HONORS = "ESWNPFC"


def tile_id(name):
    """A plain copy of the tile in RiichiEnv's 136 ids (copy 0 of a five is the red one)."""
    if name in HONORS:
        kind = 27 + HONORS.index(name)
    else:
        kind = "mps".index(name[1]) * 9 + int(name[0]) - 1
    return kind * 4 + 1


def key(action):
    return (str(action.action_type), action.tile, tuple(action.consume_tiles))


def check_win(hora, before, context, stats, bad):
    tsumo = hora["actor"] == hora["target"]
    live, after_kan, replacement = 0, False, False
    for e in before:
        if e["type"] in ("ankan", "kakan", "daiminkan"):
            after_kan = True
        elif e["type"] == "tsumo":
            live += not after_kan
            replacement, after_kan = after_kan, False
    kans = sum(e["type"] in ("ankan", "kakan", "daiminkan") for e in before)
    cond = context.conditions
    cond.houtei = not tsumo and live == 70 - kans
    cond.haitei = tsumo and live == 70 - kans and not replacement
    cond.rinshan = tsumo and replacement
    shown = [before[0]["dora_marker"]] + [e["dora_marker"] for e in before if e["type"] == "dora"]
    riichi = any(e["type"] == "reach" and e["actor"] == hora["actor"] for e in before)
    ura = [tile_id(x) for x in hora.get("ura_markers") or []] if riichi else []
    res = context.create_calculator().calc(
        context.agari_tile, [tile_id(x) for x in shown], ura, cond
    )
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
        points = 3 * res.tsumo_agari_ko
    else:
        points = res.tsumo_agari_oya + 2 * res.tsumo_agari_ko
    same_han = res.yakuman or res.han == hora.get("fan")
    same_fu = hora.get("fu") is None or res.fu == hora["fu"]
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
        stats["games"] += 1
        for i, kyoku in enumerate(
            riichienv.MjaiReplay.from_jsonl(str(path), rule=rule).take_kyokus()
        ):
            evs = rounds[i]
            stats["rounds"] += 1
            for seat, obs, action in kyoku.steps(rule=kyoku.rule):
                stats["decisions"] += 1
                if key(action) not in {key(a) for a in obs.legal_actions()}:
                    stats["illegal"] += 1
                    bad.append(f"{path.name} round {i} seat {seat}: {action} is not legal")
            horas = [e for e in evs if e["type"] == "hora"]
            # Where Tenhou and Mahjong Soul part: three winners on one discard (Tenhou aborts).
            stats["triple_ron"] += len(horas) == 3
            for hora, context in zip(horas, kyoku.take_win_result_contexts()):
                check_win(hora, evs[: evs.index(hora)], context, stats, bad)
    print(json.dumps({"rule": rule, "stats": stats, "disagreements": bad[:20]}))
    sys.exit(1 if stats["illegal"] or stats["score_differs"] else 0)


if __name__ == "__main__":
    main()
