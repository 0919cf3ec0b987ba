"""Chapter V comparison table: our three trackers against pure pursuit and Stanley.

Mean / max cross-track error (distance to the path polyline), completion and time on the V, N and
trapezoid paths (built-in scenarios ``path-v``, ``path-n``, ``path-trapezoid``: robot on the path,
V = 1 m/s, |α| ≤ π/4, l = 0.5 m, 1 m waypoint tolerance zone), for

- ``fuzzy-tracker``, ``neural-tracker``, ``anfis-tracker`` with their defaults — one setting for
  every path: corner anticipation on the smoothed reference of ``fuzzynav.control.reference``
  (R = R_min = 0.5 m, look-ahead 0.35 m, 1.5 m for the fuzzy tracker) — and as in the thesis
  (``corner_radius=0``: aim at the waypoint, switch in the tolerance zone);
- ``pure-pursuit`` and ``stanley`` with their defaults, and with the setting that minimises the
  max cross-track error on each path separately (look-ahead L from 0.3 to 2 m every 0.05 m;
  Stanley k ∈ {0.5 … 30} × softening ∈ {0.1, 0.5, 1, 2} m/s) — a per-path tuning our trackers do
  not get.

Wall time per episode is the median of ``--repeats`` runs. ``--json`` prints one JSON object.

    python benchmarks/tracking_bench.py [--json] [--repeats 3]
"""

from __future__ import annotations

import json
import statistics
import time

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import Parser
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.scenario import load_scenario

PATHS = ("path-v", "path-n", "path-trapezoid")
OURS = ("fuzzy-tracker", "neural-tracker", "anfis-tracker")
GRIDS = {
    "pure-pursuit": [{"lookahead": round(0.3 + 0.05 * i, 2)} for i in range(35)],
    "stanley": [{"gain": k, "softening": s} for k in (0.5, 1, 1.5, 2, 2.5, 3, 4, 5, 7.5, 10, 15, 20, 30)
                for s in (0.1, 0.5, 1.0, 2.0)],
}


def episode(scenario, name: str, repeats: int, **options) -> dict:
    times, numbers = [], None
    for _ in range(repeats):
        controller = make_controller(name, **options)
        start = time.perf_counter()
        trace = run_episode(scenario, controller)
        times.append(time.perf_counter() - start)
        numbers = metrics(trace, scenario)
    return {"completed": numbers["completed"], "mean_cross_track_m": numbers["mean_cross_track_m"],
            "max_cross_track_m": numbers["max_cross_track_m"], "time_s": numbers["time_s"],
            "wall_ms": 1e3 * statistics.median(times), "options": options}


def table(repeats: int) -> dict:
    rows: dict[str, dict[str, dict]] = {}
    for path in PATHS:
        scenario = load_scenario(path)
        for name in OURS:
            rows.setdefault(name, {})[path] = episode(scenario, name, repeats)
            rows.setdefault(f"{name} (thesis)", {})[path] = episode(scenario, name, repeats, corner_radius=0.0)
        for name, grid in GRIDS.items():
            rows.setdefault(name, {})[path] = episode(scenario, name, repeats)
            tuned = [episode(scenario, name, 1, **options) for options in grid]
            best = min((r for r in tuned if r["completed"]), key=lambda r: r["max_cross_track_m"])
            rows.setdefault(f"{name} (tuned per path)", {})[path] = best
    verdict = {}
    for path in PATHS:
        ours = min(rows[n][path]["max_cross_track_m"] for n in rows if n.split(" ")[0] in OURS and rows[n][path]["completed"])
        base = min(rows[n][path]["max_cross_track_m"] for n in rows if n.split(" ")[0] in GRIDS and rows[n][path]["completed"])
        verdict[path] = {"best_ours_max_m": ours, "best_baseline_max_m": base, "ours_better": ours < base}
    return {"rows": rows, "verdict": verdict}


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    result = table(args.repeats)
    if args.json:
        print(json.dumps(result))
        return
    header = f"{'controller':34s}" + "".join(f"{p:>46s}" for p in PATHS)
    print(header)
    print(f"{'':34s}" + "".join(f"{'mean / max (m)  time (s)':>46s}" for _ in PATHS))
    for name, per_path in result["rows"].items():
        cells = []
        for path in PATHS:
            r = per_path[path]
            flag = "" if r["completed"] else " (not completed)"
            extra = "".join(f" {k}={v:g}" for k, v in r["options"].items() if k != "corner_radius")
            cells.append(f"{r['mean_cross_track_m']:.3f} / {r['max_cross_track_m']:.3f}  {r['time_s']:5.1f}{extra}{flag}")
        print(f"{name:34s}" + "".join(f"{c:>46s}" for c in cells))
    for path, v in result["verdict"].items():
        word = "beats" if v["ours_better"] else "does NOT beat"
        print(f"{path}: best of ours {v['best_ours_max_m']:.3f} m {word} best baseline {v['best_baseline_max_m']:.3f} m (max cross-track)")


if __name__ == "__main__":
    main()
