"""PPO from the cloned policy, with a KL penalty that keeps it near the frozen BC policy.

Opponents (`[ppo] opponents`):
- "bc": the frozen BC net plays the other seats (its most likely action); the learner sits in
  seat `env % seats`, so every seat and wind is trained; with `bc_in_rust = true` the env plays
  those seats itself (the BC net exported, as `net:PATH` opponents), measured slower on 2 cores
  (docs/rl-validation.md);
- "self": the learner plays every seat;
- a built-in agent ("rule", "greedy", ...): hero mode, the agents play inside `step`.

Per-seat GAE: a transition is one of a learner seat's decisions; the rewards of every step until
that seat's next decision (others' moves included) accumulate on it, and the game's end closes it.
A seat's last decision of a rollout that has no successor yet only bootstraps the ones before it.

python examples/train/ppo.py --config configs/seed.toml --bc runs/x/bc.pt --out runs/x
"""

from __future__ import annotations

import argparse
import copy
import pathlib
import time

import numpy as np
import torch
from common import (
    ORACLE_ROWS,
    ORACLE_SCALARS,
    PLANES,
    SCALARS,
    Critic,
    Log,
    Space,
    Split,
    config_arguments,
    entropy_and_kl,
    greedy_policy,
    load_config,
    load_net,
    make_env,
    oracle_features,
    rank_point,
    save,
    seats,
    seed_everything,
    set_threads,
    setting,
    tensors,
)
from export import export


class Rollout:
    """The learner's decisions of one rollout, in time order."""

    def __init__(self, capacity: int, rows: int, num_actions: int, oracle: bool):
        self.planes = torch.empty((capacity, rows, PLANES[1]), dtype=torch.uint8)
        width = ORACLE_ROWS * PLANES[1] + ORACLE_SCALARS if oracle else 0
        self.hidden = torch.empty((capacity, width)) if oracle else None
        self.scalars = torch.empty((capacity, SCALARS), dtype=torch.int16)
        self.mask = torch.empty((capacity, num_actions), dtype=torch.bool)
        self.action = torch.empty(capacity, dtype=torch.int64)
        self.logp = torch.empty(capacity)
        self.value = torch.empty(capacity)
        self.ref_logp = torch.empty((capacity, num_actions))
        self.reward = np.zeros(capacity, np.float32)
        self.done = np.zeros(capacity, bool)
        self.env = np.zeros(capacity, np.int64)
        self.seat = np.zeros(capacity, np.int64)
        self.blocks: list[tuple[int, int]] = []
        self.size = 0

    def clear(self) -> None:
        self.reward[:] = 0
        self.done[:] = False
        self.blocks = []
        self.size = 0

    def add(self, planes, scalars, mask, action, logp, value, ref_logp, env, seat, hidden):
        k = len(env)
        a, b = self.size, self.size + k
        if b > len(self.reward):
            raise RuntimeError("rollout buffer overflow")
        self.planes[a:b], self.scalars[a:b], self.mask[a:b] = planes, scalars, mask
        self.action[a:b], self.logp[a:b], self.value[a:b] = action, logp, value
        self.ref_logp[a:b] = ref_logp
        if hidden is not None:
            self.hidden[a:b] = hidden
        self.env[a:b], self.seat[a:b] = env, seat
        self.blocks.append((a, b))
        self.size = b
        return np.arange(a, b)

    def advantages(self, lam: float, gamma: float) -> tuple[np.ndarray, np.ndarray]:
        """GAE per (env, seat) chain; returns (advantages, trainable) over the stored rows."""
        n = self.size
        value = self.value[:n].numpy()
        adv = np.zeros(n, np.float32)
        ok = np.zeros(n, bool)
        # Position of each chain's next decision, filled walking backwards.
        nxt = np.full((int(self.env[:n].max(initial=0)) + 1, 4), -1)
        for a, b in reversed(self.blocks):
            e, s = self.env[a:b], self.seat[a:b]
            j = nxt[e, s]
            done = self.done[a:b]
            has = (j >= 0) & ~done
            jj = np.where(has, j, 0)
            next_value = np.where(has, value[jj], 0.0)
            delta = self.reward[a:b] + gamma * next_value - value[a:b]
            # A chain's open end has no return yet: it only bootstraps (advantage 0, untrained).
            tail = ~has & ~done
            adv[a:b] = np.where(tail, 0.0, delta + gamma * lam * np.where(has, adv[jj], 0.0))
            ok[a:b] = ~tail
            nxt[e, s] = np.arange(a, b)
        return adv, ok


def train_ppo(
    cfg: dict,
    seed: int,
    bc_path: pathlib.Path,
    out: pathlib.Path,
    table: str = "ppo",
    start_from: pathlib.Path | None = None,
) -> dict:
    """Trains from `start_from` (default: the BC net) with `[table]`'s settings; writes
    `{table}.pt` and `{table}.jsonl` in `out`."""
    c = cfg[table]
    seed_everything(seed)
    set_threads(cfg)
    bc = load_net(bc_path)
    for p in bc.parameters():
        p.requires_grad_(False)
    policy = load_net(start_from) if start_from else copy.deepcopy(bc)
    policy.train()
    for p in policy.parameters():
        p.requires_grad_(True)
    analysis = bc.analysis
    oracle = bool(c.get("oracle_critic", False))
    critic = Critic(
        int(c.get("critic_hidden", 256)), int(c.get("critic_layers", 2)), analysis, oracle
    )
    critic.body.scalar_mean.copy_(bc.scalar_mean)
    critic.body.scalar_std.copy_(bc.scalar_std)
    opt = torch.optim.Adam([*policy.parameters(), *critic.parameters()], lr=float(c["lr"]))

    n, t_len = int(c["num_envs"]), int(c["rollout"])
    opponents = c["opponents"]
    # With `bc_in_rust`, the frozen BC net plays its seats inside the env (`net:PATH`, the same
    # greedy function in Rust): this loop then reads and infers only the learner's rows.
    bc_in_rust = opponents == "bc" and bool(c.get("bc_in_rust", False))
    env_opponents = opponents
    if bc_in_rust:
        env_opponents = f"net:{out / 'bc.safetensors'}"
        export(bc, out / "bc.safetensors")
    variant, mode = setting(cfg, table)
    players = seats(variant)
    rank_reward = np.asarray(c["rank_reward"], np.float32)
    if len(rank_reward) != players:
        raise SystemExit(f"[{table}] rank_reward: {len(rank_reward)} values for {players} places")
    # The env's per-seat arrays are four wide for three players too (the fourth seat empty).
    learner = np.zeros((n, 4), bool)
    hero_mode = bc_in_rust or opponents not in ("bc", "self")
    if opponents == "self":
        learner[:, :players] = True
    else:
        learner[np.arange(n), np.arange(n) % players] = True
    kw = {"opponents": env_opponents, "hero_seats": np.arange(n) % players} if hero_mode else {}
    kw["oracle"] = oracle
    env = make_env(cfg, table, n, seed + 1000, **kw)
    space = Space(variant, bc.actions)
    points_scale = float(c.get("points_scale", 0.0))
    gamma, lam = float(c["gamma"]), float(c["gae_lambda"])
    clip, ent_coef = float(c["clip"]), float(c["entropy"])
    vf_coef, kl_coef = float(c["value"]), float(c["kl"])
    epochs, minibatch = int(c["epochs"]), int(c["minibatch"])
    warmup = int(c.get("critic_warmup", 0))
    # Learning's matrix products in bfloat16 (the losses and the optimiser stay in float32).
    half = torch.autocast("cpu", dtype=torch.bfloat16, enabled=bool(c.get("bf16", False)))
    critic_epochs = int(c.get("critic_epochs", epochs))
    buf = Rollout(n * t_len, bc.row_scale.shape[0], bc.config["num_actions"], oracle)
    rng = np.random.default_rng(seed)
    bc_act = greedy_policy(bc, variant)

    log = Log(out / f"{table}.jsonl")
    start = time.time()
    env_steps = decisions = 0
    last = np.full((n, 4), -1)
    finished_ranks: list[int] = []
    ts = env.reset()
    first_value_loss = None
    evaluations = []

    def evaluate(update: int) -> None:
        games = int(c.get("evaluate_games", 0))
        if games <= 0:
            return
        against = bc_act if opponents in ("bc", "self") else opponents
        point = rank_point(policy, variant, mode, analysis, against, games, 10_000 + seed)
        row = {"update": update, "env_steps": env_steps, **point}
        evaluations.append(row)
        log.write(kind="evaluate", **row)
        print(f"{table} update {update}: average rank {row['rank']:.3f} ± {row['ci95']:.3f}")

    evaluate(0)
    total = Split()
    for update in range(1, int(c["updates"]) + 1):
        split = Split()
        buf.clear()
        last[:] = -1
        policy.eval()
        t0 = time.time()
        with torch.inference_mode():
            for _ in range(t_len):
                with split("observation"):
                    cp = ts.current_player.astype(np.int64)
                    mine = learner[np.arange(n), cp]
                    if hero_mode:
                        mine &= ts.info["hero"]
                    rows = np.nonzero(mine)[0]
                    actions = np.zeros(n, np.int64)
                    # Every row only where this loop plays the BC seats too.
                    take = rows if hero_mode else None
                    planes, scalars, mask = tensors(ts, space, analysis, take)
                    p, s, m = (planes, scalars, mask)
                    if not hero_mode:
                        p, s, m = planes[rows], scalars[rows], mask[rows]
                with split("inference"):
                    if opponents == "bc" and not bc_in_rust:
                        bc_logits = bc(planes, scalars, mask)
                        actions[:] = bc_logits.argmax(1).numpy()
                        ref = torch.log_softmax(bc_logits[rows], 1)
                    else:
                        ref = torch.log_softmax(bc(p, s, m), 1)
                if len(rows):
                    h = None
                    if oracle:
                        with split("oracle"):
                            h = torch.from_numpy(oracle_features(env.oracle(cp))[rows])
                    with split("inference"):
                        logp_all = torch.log_softmax(policy(p, s, m), 1)
                        a = torch.multinomial(logp_all.exp(), 1).squeeze(1)
                        logp = logp_all.gather(1, a[:, None]).squeeze(1)
                        value = critic(p, s, h)
                    with split("bookkeeping"):
                        pos = buf.add(p, s, m, a, logp, value, ref, rows, cp[rows], h)
                        actions[rows] = a.numpy()
                        last[rows, cp[rows]] = pos
                with split("env"):
                    ts = env.step(space.to_env(actions))
                env_steps += n
                decisions += len(rows)
                with split("bookkeeping"):
                    # Rewards of this step go to each learner seat's latest decision.
                    has = last >= 0
                    if points_scale:
                        np.add.at(buf.reward, last[has], ts.rewards[has] * points_scale)
                    for e in np.nonzero(ts.terminated)[0]:
                        for s_ in np.nonzero(learner[e])[0]:
                            rank = int(ts.info["final_rank"][e, s_])
                            if last[e, s_] >= 0:
                                buf.reward[last[e, s_]] += rank_reward[rank]
                                buf.done[last[e, s_]] = True
                            finished_ranks.append(rank + 1)
                        last[e] = -1
        rollout_s = time.time() - t0
        t1 = time.time()
        adv_all, ok = buf.advantages(lam, gamma)
        size = buf.size
        # A decision with one legal action teaches nothing.
        choice = buf.mask[:size].sum(1).numpy() > 1
        idx = np.nonzero(ok & choice)[0]
        returns = torch.from_numpy(adv_all) + buf.value[:size]
        adv_t = torch.from_numpy(adv_all)
        # How much of the return the critic explained before it trained on this rollout.
        r_ok = returns[torch.from_numpy(idx)]
        v_ok = buf.value[:size][torch.from_numpy(idx)]
        explained = float(1 - (r_ok - v_ok).var() / r_ok.var().clamp(min=1e-8))
        policy.train()
        stats: dict[str, list] = {k: [] for k in ("pg", "value", "entropy", "kl", "clipfrac")}
        by_epoch: dict[str, list] = {"pg": [], "value": []}
        for epoch in range(epochs):
            seen = len(stats["value"])
            perm = idx[rng.permutation(len(idx))]
            for i in range(0, len(perm), minibatch):
                mb = torch.from_numpy(np.sort(perm[i : i + minibatch]))
                if len(mb) < 2:
                    continue
                p, s, m = buf.planes[mb], buf.scalars[mb], buf.mask[mb]
                with half:
                    logits = policy(p, s, m)
                logp_all = torch.log_softmax(logits.float(), 1)
                logp = logp_all.gather(1, buf.action[mb][:, None]).squeeze(1)
                ratio = (logp - buf.logp[mb]).exp()
                adv = adv_t[mb]
                adv = (adv - adv.mean()) / (adv.std() + 1e-8)
                pg = -torch.min(ratio * adv, ratio.clamp(1 - clip, 1 + clip) * adv).mean()
                h = buf.hidden[mb] if oracle else None
                # More passes over one rollout make the critic memorise its games' outcomes.
                critic_on = epoch < critic_epochs
                # Past its epochs the critic's loss is only reported: no graph to build for it.
                with torch.set_grad_enabled(critic_on):
                    with half:
                        value = critic(p, s, h)
                    value_loss = 0.5 * (value.float() - returns[mb]).pow(2).mean()
                ent, kl = entropy_and_kl(logp_all, buf.ref_logp[mb], m)
                terms = [vf_coef * value_loss] if critic_on else []
                if update > warmup:
                    terms.append(pg - ent_coef * ent.mean() + kl_coef * kl.mean())
                if terms:
                    opt.zero_grad()
                    sum(terms).backward()
                    params = [*policy.parameters(), *critic.parameters()]
                    torch.nn.utils.clip_grad_norm_(params, 0.5)
                    opt.step()
                stats["pg"].append(pg.item())
                stats["value"].append(value_loss.item())
                stats["entropy"].append(ent.mean().item())
                stats["kl"].append(kl.mean().item())
                stats["clipfrac"].append(((ratio - 1).abs() > clip).float().mean().item())
            # Each epoch's mean losses over the same rollout: the optimiser must bring them down.
            for k in by_epoch:
                by_epoch[k].append(float(np.mean(stats[k][seen:])) if stats[k][seen:] else None)
        split.seconds["learning"] += time.time() - t1
        for k, v in split.seconds.items():
            total.seconds[k] += v
        means = {k: float(np.mean(v)) if v else None for k, v in stats.items()}
        if first_value_loss is None:
            first_value_loss = means["value"]
        recent = finished_ranks[-2000:]
        log.write(
            kind="update",
            update=update,
            env_steps=env_steps,
            decisions=decisions,
            trained_rows=int(len(idx)),
            explained_variance=explained,
            return_var=float(r_ok.var()),
            rollout_s=round(rollout_s, 2),
            train_s=round(split.seconds["learning"], 2),
            split=split.rounded(),
            games=len(finished_ranks),
            rollout_rank=float(np.mean(recent)) if recent else None,
            pg_by_epoch=by_epoch["pg"],
            value_by_epoch=by_epoch["value"],
            **means,
        )
        if update % max(1, int(c.get("print_every", 1))) == 0:
            print(
                f"{table} update {update}: {env_steps} steps, value {means['value']:.4f} "
                f"explained {explained:.2f} "
                f"kl {means['kl']:.4f} entropy {means['entropy']:.3f} "
                f"rank {np.mean(recent) if recent else float('nan'):.3f} "
                f"({env_steps / sum(total.seconds.values()):.0f} steps/s)"
            )
        if update % int(c.get("evaluate_every", 10**9)) == 0:
            evaluate(update)
            save(policy, out / f"{table}.pt", seed=seed, update=update, env_steps=env_steps)
    env.close()
    save(policy, out / f"{table}.pt", seed=seed, update=int(c["updates"]), env_steps=env_steps)
    log.close()
    return {
        "env_steps": env_steps,
        "decisions": decisions,
        "games": len(finished_ranks),
        "first_value_loss": first_value_loss,
        "value_loss": means["value"],
        "evaluations": evaluations,
        "seconds": round(time.time() - start, 1),
        # The training loop alone (evaluations left out): where its time went, and its speed.
        "split": total.rounded(),
        "steps_per_s": round(env_steps / sum(total.seconds.values()), 1),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    config_arguments(ap)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--bc", required=True, help="the BC checkpoint (bc.pt)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--table", default="ppo", help="the config table of settings (ppo, finetune)")
    ap.add_argument("--start", help="a policy checkpoint to go on from (default: the BC net)")
    a = ap.parse_args()
    cfg = load_config(a.config, ("run", a.table), a.set)
    start = pathlib.Path(a.start) if a.start else None
    print(train_ppo(cfg, a.seed, pathlib.Path(a.bc), pathlib.Path(a.out), a.table, start))


if __name__ == "__main__":
    main()
