"""Steps per second from Python against the Rust `bench env` of the same run.

    python python/bench.py [--batches 1,16,256,1024,4096,16384] [--seconds 1.0] [--threads 1]

For each batch size: the Rust figure (`rinshan bench env`, env step calls only), the package's
`env.step` from Python (the same work plus the numpy outputs, GIL released), and the whole Python
loop with a uniformly random legal policy chosen in numpy. Then the same with the planes
observation written every step (Rust: `--observe planes`).
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


def rust_rates(cli, batches, seconds, threads, observe) -> dict:
    """{batch: env steps/s} of the CLI's first table (1 thread, or `threads`)."""
    cmd = [
        cli,
        "bench",
        "env",
        "--threads",
        str(threads),
        "--seconds-per-point",
        str(seconds),
        "--batches",
        ",".join(map(str, batches)),
    ]
    if observe:
        cmd += ["--observe", "planes"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rates = {}
    for line in out.splitlines():
        m = re.match(r"\s+(\d+)\s+(\d+)\s+[\d.]+x\s+(\d+)(?:\s+(\d+))?", line)
        if m and int(m.group(1)) not in rates:
            rates[int(m.group(1))] = float(m.group(4) if observe else m.group(2))
    return rates


def python_rates(batch, seconds, threads, observation) -> tuple[float, float]:
    """(env.step steps/s, whole loop steps/s) of a random legal policy in numpy."""
    env = rinshan.make("red", num_envs=batch, num_threads=threads, seed=0, observation=observation)
    rng = np.random.default_rng(0)
    ts = env.reset()
    in_step, steps, warm = 0.0, 0, 3
    start = time.perf_counter()
    while True:
        noise = rng.random(ts.legal_action_mask.shape, dtype=np.float32)
        actions = (noise * ts.legal_action_mask).argmax(axis=1)
        t = time.perf_counter()
        ts = env.step(actions)
        dt = time.perf_counter() - t
        if warm:
            warm -= 1
            start = time.perf_counter()
            continue
        in_step += dt
        steps += batch
        total = time.perf_counter() - start
        if total >= seconds:
            env.close()
            return steps / in_step, steps / total


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--batches", default="1,16,256,1024,4096,16384")
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    batches = [int(b) for b in a.batches.split(",")]
    cli = find_cli()
    print(
        f"rinshan python/bench.py: red half games, {a.threads} thread(s), {a.seconds} s per point"
    )
    for observe in (False, True):
        rust = rust_rates(cli, batches, a.seconds, a.threads, observe)
        print("with planes every step" if observe else "no observation")
        print(
            f"  {'batch':>6} {'rust env/s':>12} {'python env.step/s':>18} {'ratio':>6} "
            f"{'python loop/s':>14}"
        )
        for b in batches:
            env_rate, loop_rate = python_rates(
                b, a.seconds, a.threads, ("planes",) if observe else ()
            )
            r = rust.get(b, float("nan"))
            print(f"  {b:>6} {r:>12.0f} {env_rate:>18.0f} {env_rate / r:>6.2f} {loop_rate:>14.0f}")


if __name__ == "__main__":
    main()
