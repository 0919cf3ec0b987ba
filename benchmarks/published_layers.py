"""What each optional layer adds to the published chapter IV navigators on generated worlds.

``fuzzy-2b-thesis`` and ``fuzzy-5b-thesis`` run as published (no layer), with each layer of
:data:`fuzzynav.control.batched.LAYERS` alone, and with all of them (``fuzzy-*-layered``), on the
same ``--n`` worlds of ``--worlds``; one row per variant: success, collision and timeout rates.

    PYTHONPATH=src python benchmarks/published_layers.py --worlds mixed --n 100 --seed 0
"""

from __future__ import annotations

import argparse

from fuzzynav.control.batched import LAYERS
from fuzzynav.experiments.evaluation import evaluate


def variants():
    """(label, layers) of each row: none, each alone, all."""
    return [("bare (as published)", ()), *((f"+ {name}", (name,)) for name in LAYERS), ("all layers", tuple(LAYERS))]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worlds", default="mixed")
    parser.add_argument("--n", type=int, default=100)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(f"| navigator | layers | success | collision | timeout |  ({args.n} {args.worlds} worlds, seed {args.seed})")
    print("|---|---|---|---|---|")
    for controller in ("fuzzy-2b-thesis", "fuzzy-5b-thesis"):
        for label, layers in variants():
            r = evaluate(controller, args.worlds, args.n, args.seed, options={"layers": layers})
            print(f"| {controller} | {label} | {r['success_rate']:.0%} | {r['collision_rate']:.0%} | "
                  f"{r['timeout_rate']:.0%} |", flush=True)


if __name__ == "__main__":
    main()
