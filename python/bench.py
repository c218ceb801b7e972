"""Steps per second from Python against the Rust `bench env` of the same run.

    python python/bench.py [--batches 1,16,256,1024,4096,16384] [--seconds 1.0] [--threads 1,0]
        [--form planes|tokens|packed]

For each thread count (0: all cores) and batch size: the Rust figure (`rinshan bench env`, env
step calls only, its table for that thread count), the package's `env.step` from Python (the same
work plus the numpy outputs, GIL released), and the whole Python loop. The policy is uniform over
the legal actions, chosen in numpy with buffers made once (`UniformLegal`), as the Rust bench's
is chosen in Rust. Then the same with an observation (`--form`, the planes by default) written
every step (Rust: `--observe FORM`).

While the policy runs, the env's threads sleep, and on a machine whose idle cores wake slowly
(a virtual machine: milliseconds) the next parallel `env.step` pays for waking them, whatever
calls it. So each Python point is also compared with Rust sleeping as long between steps
(`bench env --idle-us`, the column `rust at gap`).

`--policy argmax` chooses as many examples do, `(random floats * mask).argmax()`, with new
float arrays every step: a longer gap, and megabytes of temporaries at batch 4096 that push the
games' states out of the caches before the next `env.step`.
"""

from __future__ import annotations

import argparse
import pathlib
import re
import shutil
import subprocess
import sys
import time

import numpy as np

# Run as a script, this folder comes first on sys.path and its rinshan/ (the sources, without the
# compiled extension) would shadow the installed package.
sys.path[:] = [
    p
    for p in sys.path
    if pathlib.Path(p or ".").resolve() != pathlib.Path(__file__).parent.resolve()
]
import rinshan  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[1]


def find_cli() -> str:
    for p in (REPO / "target" / "release" / "rinshan", shutil.which("rinshan")):
        if p and pathlib.Path(p).is_file():
            return str(p)
    raise SystemExit("build the CLI first: cargo build --release")


class UniformLegal:
    """A uniformly random legal action per env, in numpy, with its buffers made once."""

    def __init__(self, shape, seed=0):
        self.rng = np.random.default_rng(seed)
        self.rank = np.empty(shape, np.uint8)
        self.above = np.empty(shape, bool)
        self.u = np.empty(shape[0], np.float32)

    def __call__(self, mask):
        # rank[i, j]: legal actions among 0..j; the first j whose rank passes a uniform k in
        # 0..count-1 is the (k+1)-th legal action.
        np.cumsum(mask, axis=1, dtype=np.uint8, out=self.rank)
        self.rng.random(out=self.u, dtype=np.float32)
        k = (self.u * self.rank[:, -1]).astype(np.uint8)
        np.greater(self.rank, k[:, None], out=self.above)
        return self.above.argmax(axis=1)


class ArgmaxNoise:
    """`(random floats * mask).argmax()`: new arrays every step."""

    def __init__(self, shape, seed=0):
        self.rng = np.random.default_rng(seed)

    def __call__(self, mask):
        return (self.rng.random(mask.shape, dtype=np.float32) * mask).argmax(axis=1)


POLICIES = {"uniform": UniformLegal, "argmax": ArgmaxNoise}


def rust_rates(cli, batches, seconds, threads, observe, idle_us=0) -> dict:
    """{batch: env steps/s} of the CLI's table for `threads` (0: all cores), the calling thread
    sleeping `idle_us` between steps."""
    cmd = [
        cli,
        "bench",
        "env",
        "--seconds-per-point",
        str(seconds),
        "--batches",
        ",".join(map(str, batches)),
    ]
    if threads:
        cmd += ["--threads", str(threads)]
    if idle_us:
        cmd += ["--idle-us", str(idle_us)]
    if observe:
        cmd += ["--observe", observe]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    # The CLI prints a one-thread table, then one for --threads (all cores by default).
    tables = out.split("\ncpu, ")[1:]
    table = tables[0] if threads == 1 else tables[-1]
    rates = {}
    for line in table.splitlines():
        m = re.match(r"\s+(\d+)\s+(\d+)\s+[\d.]+x\s+(\d+)(?:\s+(\d+))?", line)
        if m:
            rates[int(m.group(1))] = float(m.group(4) if observe else m.group(2))
    return rates


def python_rates(batch, seconds, threads, observation, policy) -> tuple[float, float, int]:
    """(env.step steps/s, whole loop steps/s, microseconds per step outside env.step) of a
    random legal policy in numpy."""
    env = rinshan.make(
        "red", num_envs=batch, num_threads=threads or None, seed=0, observation=observation
    )
    ts = env.reset()
    choose = POLICIES[policy](ts.legal_action_mask.shape)
    in_step, steps, calls, warm = 0.0, 0, 0, 3
    start = time.perf_counter()
    while True:
        actions = choose(ts.legal_action_mask)
        t = time.perf_counter()
        ts = env.step(actions)
        dt = time.perf_counter() - t
        if warm:
            warm -= 1
            start = time.perf_counter()
            continue
        in_step += dt
        steps += batch
        calls += 1
        total = time.perf_counter() - start
        if total >= seconds:
            env.close()
            return steps / in_step, steps / total, round((total - in_step) / calls * 1e6)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--batches", default="1,16,256,1024,4096,16384")
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("--threads", default="1,0", help="thread counts to measure; 0: all cores")
    ap.add_argument("--policy", choices=sorted(POLICIES), default="uniform")
    ap.add_argument("--form", choices=rinshan.env.OBSERVATION_FORMS, default="planes")
    a = ap.parse_args()
    batches = [int(b) for b in a.batches.split(",")]
    cli = find_cli()
    print(f"rinshan python/bench.py: red half games, {a.seconds} s per point, {a.policy} policy")
    print(
        "  gap: microseconds per step the Python loop spends outside env.step (the policy);"
        " rust at gap: bench env --idle-us gap; ratio: python env.step over rust at gap"
    )
    for threads in (int(t) for t in a.threads.split(",")):
        for observe in (None, a.form):
            observation = (observe,) if observe else ()
            rust = rust_rates(cli, batches, a.seconds, threads, observe)
            print(
                f"{threads or 'all'} thread(s), "
                + (f"with {observe} every step" if observe else "no observation")
            )
            print(
                f"  {'batch':>6} {'rust env/s':>12} {'gap us':>7} {'rust at gap':>12} "
                f"{'python env.step/s':>18} {'ratio':>6} {'python loop/s':>14}"
            )
            for b in batches:
                env_rate, loop_rate, gap = python_rates(
                    b, a.seconds, threads, observation, a.policy
                )
                r = rust.get(b, float("nan"))
                at_gap = rust_rates(cli, [b], a.seconds, threads, observe, gap).get(b, float("nan"))
                print(
                    f"  {b:>6} {r:>12.0f} {gap:>7} {at_gap:>12.0f} {env_rate:>18.0f} "
                    f"{env_rate / at_gap:>6.2f} {loop_rate:>14.0f}"
                )


if __name__ == "__main__":
    main()
