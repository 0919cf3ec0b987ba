"""Chapter IV navigators on generated world families, seed by seed: success, collisions, timeouts
and stand-stills — or, with ``--layers``, what each optional layer adds to them.

The worlds are those of :func:`fuzzynav.world.generate.generate_worlds` (families ``mixed``,
``circles``, ``dense``, ``utrap``, ...), the worlds of ``fuzzynav evaluate`` with the same episode
seed, so the outcomes are those of ``fuzzynav evaluate --worlds FAMILY --n N --seed S``.

Default: for every episode the outcome and, for episodes that end away from the goal, how long
the robot stood still at the end (``|V| < 1e-6``); per family and seed the rates and
``stood_still_10s`` (episodes ending more than 10 s at a stand-still away from the goal)::

    python benchmarks/robust_nav.py --controller fuzzy-5b-rays --family mixed dense utrap --seeds 0 1 2 3 4 [--n 100] [--json]

``--layers``: each controller as published (no layer), with each layer of
:data:`fuzzynav.control.batched.LAYERS` alone, and with all of them, on the same worlds; one
markdown row per variant (success, collision and timeout rates)::

    python benchmarks/robust_nav.py --layers --controller fuzzy-2b-thesis fuzzy-5b-thesis --family mixed --seeds 0 --n 100
"""

from __future__ import annotations

import json

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import Parser
from fuzzynav.control.batched import LAYERS
from fuzzynav.sim import run_episode
from fuzzynav.world.generate import generate_worlds


def stand_still(trace) -> float:
    """Seconds the robot stood still (|V| < 1e-6) at the end of the episode."""
    moving = np.flatnonzero(np.abs(trace.speed) >= 1e-6)
    last = moving[-1] + 1 if len(moving) else 0
    return float((len(trace.speed) - last) * trace.dt)


def run(controller: str, family: str, n: int, seed: int, **options) -> dict:
    """Rates, stand-stills and failures of ``controller`` (built with ``options``) on ``n`` worlds."""
    episodes = []
    for scenario in generate_worlds(family, n, seed):
        trace = run_episode(scenario, make_controller(controller, **options), seed=seed)
        away = float(np.hypot(*(trace.pose[-1, :2] - scenario.goal.position)))
        episodes.append({"scenario": scenario.name, "outcome": trace.outcome, "time_s": float(trace.time),
                         "still_s": stand_still(trace) if trace.outcome != "reached" else 0.0, "goal_distance_m": away})
    rate = lambda o: sum(e["outcome"] == o for e in episodes) / n  # noqa: E731
    return {"controller": controller, **options, "family": family, "seed": seed, "n": n,
            "success_rate": rate("reached"), "collision_rate": rate("collision"), "timeout_rate": rate("timeout"),
            "stood_still_10s": sum(int(e["still_s"] > 10.0) for e in episodes),
            "failures": [e for e in episodes if e["outcome"] != "reached"]}


def variants():
    """(label, layers) of each ``--layers`` row: none, each alone, all."""
    return [("bare (as published)", ()), *((f"+ {name}", (name,)) for name in LAYERS), ("all layers", tuple(LAYERS))]


def print_run(r: dict) -> None:
    print(f"{r['controller']:16s} {r['family']:7s} seed {r['seed']}: success {100 * r['success_rate']:5.1f} %  "
          f"collisions {100 * r['collision_rate']:4.1f} %  timeouts {100 * r['timeout_rate']:4.1f} %  "
          f"stood still >10 s: {r['stood_still_10s']}", flush=True)
    for e in r["failures"]:
        print(f"    {e['scenario']}: {e['outcome']} at {e['time_s']:.1f} s, {e['goal_distance_m']:.1f} m from "
              f"the goal, still for the last {e['still_s']:.1f} s", flush=True)


def main(argv=None) -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--controller", nargs="+", default=["fuzzy-5b-rays"])
    parser.add_argument("--family", nargs="+", default=["mixed", "dense", "utrap"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2, 3, 4])
    parser.add_argument("--n", type=int, default=100)
    parser.add_argument("--layers", action="store_true", help="a row per layer variant of each controller")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    results = []
    for family in args.family:
        for seed in args.seeds:
            if args.layers and not args.json:
                print(f"| navigator | layers | success | collision | timeout |  ({args.n} {family} worlds, seed {seed})")
                print("|---|---|---|---|---|")
            for controller in args.controller:
                for label, layers in variants() if args.layers else [(None, None)]:
                    results.append(run(controller, family, args.n, seed, **({} if layers is None else {"layers": layers})))
                    r = results[-1]
                    if args.json:
                        continue
                    if args.layers:
                        print(f"| {controller} | {label} | {r['success_rate']:.0%} | {r['collision_rate']:.0%} | "
                              f"{r['timeout_rate']:.0%} |", flush=True)
                    else:
                        print_run(r)
    if args.json:
        print(json.dumps(results))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
