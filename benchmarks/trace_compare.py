"""Record and compare closed-loop traces of two checkouts of fuzzynav (a refactoring check).

Runs the chapter IV navigators (``goal-seeking``, ``fuzzy-2b-thesis``, ``fuzzy-5b-thesis``, ``wall-follow``; older checkouts
name the thesis navigators ``fuzzy-2b``, ``fuzzy-5b``) on
every built-in scenario and on the worlds of ``fuzzynav evaluate --worlds mixed --n 100 --seed 0``,
plus the path / target trackers on the built-in path and target scenarios, and stores each
episode's outcome, poses, commands and behaviour labels. Run it once with the old checkout on
``PYTHONPATH`` (``--record old.npz``), once with the new one (``--record new.npz``), then
``--compare old.npz new.npz``: it prints the largest pose difference (m, rad) and every episode
whose outcome, length or labels differ, and exits 1 when any pose differs by more than ``--tol``.

    PYTHONPATH=/path/to/old/src python benchmarks/trace_compare.py --record old.npz
    python benchmarks/trace_compare.py --record new.npz
    python benchmarks/trace_compare.py --compare old.npz new.npz
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np

from fuzzynav.cli import Parser

NAVIGATORS = ("goal-seeking", "fuzzy-2b-thesis", "fuzzy-5b-thesis", "wall-follow")
TRACKERS = ("fuzzy-tracker", "pure-pursuit", "stanley")


def episodes(n_worlds: int):
    """(key, scenario, controller name) of every episode compared."""
    from fuzzynav.world.generate import generate_worlds
    from fuzzynav.world.scenario import list_scenarios, load_scenario

    for name in list_scenarios():
        scenario = load_scenario(name)
        names = NAVIGATORS if scenario.task == "goal" else TRACKERS
        for controller in names:
            yield f"{name}/{controller}", scenario, controller
    for i, scenario in enumerate(generate_worlds("mixed", n_worlds, 0)):
        for controller in NAVIGATORS:
            yield f"mixed-{i}/{controller}", scenario, controller


def record(path: str, n_worlds: int) -> None:
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    arrays, meta = {}, {}
    t0 = time.perf_counter()
    for key, scenario, controller in episodes(n_worlds):
        trace = run_episode(scenario, make_controller(controller), seed=0)
        arrays[f"{key}/pose"] = trace.pose
        arrays[f"{key}/command"] = np.column_stack([trace.steering, trace.speed])
        meta[key] = {"outcome": trace.outcome, "steps": trace.steps, "behaviour": "|".join(trace.behaviour.tolist())}
    arrays["meta"] = np.array(json.dumps(meta))
    np.savez_compressed(path, **arrays)
    print(f"{len(meta)} episodes recorded in {time.perf_counter() - t0:.1f} s -> {path}")


def compare(old_path: str, new_path: str, tol: float) -> int:
    old, new = np.load(old_path), np.load(new_path)
    old_meta, new_meta = json.loads(str(old["meta"])), json.loads(str(new["meta"]))
    worst, worst_key, differing = 0.0, None, []
    for key, a in old_meta.items():
        b = new_meta.get(key)
        if b is None:
            differing.append(f"{key}: missing")
            continue
        if (a["outcome"], a["steps"]) != (b["outcome"], b["steps"]):
            differing.append(f"{key}: {a['outcome']} in {a['steps']} steps -> {b['outcome']} in {b['steps']}")
        if a["behaviour"] != b["behaviour"]:
            differing.append(f"{key}: behaviour labels differ")
        pa, pb = old[f"{key}/pose"], new[f"{key}/pose"]
        k = min(len(pa), len(pb))
        gap = float(np.max(np.abs(pa[:k] - pb[:k]))) if k else 0.0
        gap = max(gap, float(np.max(np.abs(old[f"{key}/command"][:k - 1] - new[f"{key}/command"][:k - 1])))
                  if k > 1 else 0.0)
        if gap > worst:
            worst, worst_key = gap, key
    print(f"{len(old_meta)} episodes; largest pose/command difference {worst:.3g} ({worst_key})")
    for line in differing:
        print("  " + line)
    return 1 if differing or worst > tol else 0


def main(argv=None) -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--record", metavar="FILE", help="run every episode and store the traces (.npz)")
    parser.add_argument("--compare", nargs=2, metavar=("OLD", "NEW"), help="compare two recordings")
    parser.add_argument("--worlds", type=int, default=100, help="mixed worlds (seed 0) per navigator (default 100)")
    parser.add_argument("--tol", type=float, default=1e-9, help="largest pose / command difference allowed")
    args = parser.parse_args(argv)
    if args.record:
        record(args.record, args.worlds)
        return 0
    if args.compare:
        return compare(*args.compare, args.tol)
    parser.print_help()
    return 2


if __name__ == "__main__":
    sys.exit(main())
