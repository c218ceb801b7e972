"""Duplicate arena through `rinshan.evaluate`: a checkpoint (or a built-in agent) against three
opponents, each a checkpoint or a built-in agent, every wall set played from all four seats.
Networks play their most likely legal action.

python examples/train/evaluate.py runs/x/ppo.pt --opponents runs/x/bc.pt --games 1000 --mode single
"""

from __future__ import annotations

import argparse
import json
import time

from common import greedy_policy, load_net, set_threads

import rinshan


def arena(policy: str, opponents: str, games: int, seed: int, variant: str, mode: str) -> dict:
    """`policy` against three `opponents`, each a built-in agent's name or a checkpoint path."""
    nets = {n: load_net(n) for n in (policy, opponents) if n not in rinshan.AGENTS}

    def player(name: str):
        return name if name in rinshan.AGENTS else greedy_policy(nets[name], variant)

    start = time.time()
    r = rinshan.evaluate(
        player(policy),
        opponents=player(opponents),
        games=games,
        seed=seed,
        variant=variant,
        mode=mode,
        analysis=any(net.analysis for net in nets.values()),
    )
    return {
        "policy": policy,
        "opponents": opponents,
        "variant": variant,
        "mode": mode,
        "seed": seed,
        "games": r.games,
        "rank": r.average_rank,
        "ci95": r.ci95,
        "places": r.rank_counts,
        "score": r.average_score,
        "illegal": r.illegal,
        "seconds": round(time.time() - start, 1),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("policy", help="a checkpoint (.pt) or a built-in agent")
    ap.add_argument("--opponents", default="rule", help="a checkpoint or a built-in agent")
    ap.add_argument("--games", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--variant", default="no-red", choices=rinshan.VARIANTS)
    ap.add_argument("--mode", default="single", choices=rinshan.MODES)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    set_threads({"run": {"threads": a.threads}})
    r = arena(a.policy, a.opponents, a.games, a.seed, a.variant, a.mode)
    print(json.dumps(r))
    print(f"average rank {r['rank']:.3f} ± {r['ci95']:.3f} over {r['games']} games")


if __name__ == "__main__":
    main()
