"""A trained policy net as a file the Rust side plays: `--agents net:PATH` in the arena, selfplay,
the web page, `mjai-bot` and the Python env's opponents, with no Python at play time.

python examples/train/export.py runs/seed/seed0/ppo.pt runs/seed/seed0/ppo.safetensors

The file is safetensors: the state dict's tensors under their PyTorch names, float32 (the
discard columns int64), and in its metadata what the reader needs to rebuild the function: the
net's shape (`config`), the action names its logits are indexed by (`actions`), and the
observation layout it was trained on (`plane_rows`, `scalars`, `analysis_rows`), which the reader
checks against its own engine's.
"""

from __future__ import annotations

import argparse
import json
import pathlib

import torch
from common import ANALYSIS, PLANES, SCALARS, Net, load_net
from safetensors.torch import save_file

# What a reader checks first: a file of another layout is refused, not misread.
FORMAT, VERSION = "rinshan-net", "1"


def export(net: Net, path: str | pathlib.Path) -> None:
    """Writes `net` (a policy net) as a safetensors file `path`."""
    if net.config["extra"]:
        raise ValueError("only policy nets are exported: this one reads extra (critic) inputs")
    tensors = {
        name: (t.to(torch.int64) if name == "discard_column" else t.float()).contiguous()
        for name, t in net.state_dict().items()
    }
    metadata = {
        "format": FORMAT,
        "version": VERSION,
        "config": json.dumps(net.config),
        "actions": json.dumps(list(net.actions)),
        "plane_rows": str(PLANES[0]),
        "scalars": str(SCALARS),
        "analysis_rows": json.dumps(list(ANALYSIS) if net.analysis else []),
    }
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    save_file(tensors, str(path), metadata=metadata)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("checkpoint", help="a policy checkpoint of bc.py or ppo.py (bc.pt, ppo.pt)")
    ap.add_argument("out", help="the safetensors file to write")
    a = ap.parse_args()
    export(load_net(a.checkpoint), a.out)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
