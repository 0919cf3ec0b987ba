"""Robustness curves: success and collisions of every navigator as each imperfection of the real
robot (:mod:`fuzzynav.robot.imperfections`) grows, one at a time, on suites of worlds (a folder
of scenario files, e.g. BARN imported by ``fuzzynav import barn``, or a generated family
``FAMILY:COUNT[:SEED]``), plus the combined set of the acceptance test.

Every run is one episode (seed 0) of a navigator on a world with one key set, as
``fuzzynav bench SUITE --perturb KEY=VALUE`` runs it. Rows go to ``OUT/runs.jsonl`` as they
finish (a run already there is skipped: an interrupted sweep resumes); at the end
``OUT/table.md`` (success / collision % per navigator, suite and condition) and
``OUT/robustness-SUITE.png`` (success and collisions against each key). The runs go world by
world, so a sweep stopped early (``--tables-only`` then writes the table and plots of what is
done) has every condition and navigator on the same first worlds.

Usage::

    python benchmarks/robustness.py SUITE... --navigators fuzzy-5b,dwa --out DIR [--workers 2] [--quick]
"""

from __future__ import annotations

import json
import multiprocessing
from pathlib import Path

from fuzzynav.cli import Parser

SWEEPS = {  # the ranges: noise 0–5 cm, latency 0–0.3 s, slip 0–20 %, drift 0–5 %
    "robot.sensor_noise.range_sigma": (0.01, 0.02, 0.05),
    "robot.actuation.latency": (0.1, 0.2, 0.3),
    "robot.actuation.slip": (0.05, 0.1, 0.2),
    "robot.odometry.drift": (0.01, 0.02, 0.05),
}
COMBINED = (("robot.sensor_noise.range_sigma", 0.02), ("robot.sensor_noise.dropout", 0.01),
            ("robot.actuation.latency", 0.1), ("robot.actuation.slip", 0.05), ("robot.odometry.drift", 0.01))
LABELS = {"robot.sensor_noise.range_sigma": "range noise σ (m)", "robot.actuation.latency": "latency (s)",
          "robot.actuation.slip": "slip (fraction)", "robot.odometry.drift": "odometry drift (m/m)"}


def conditions(quick: bool, keys=tuple(SWEEPS)) -> list[tuple[str, tuple]]:
    """(name, perturbations) of every condition: none, each of ``keys`` at each level, the combined set."""
    out = [("none", ())]
    for key, levels in SWEEPS.items():
        if key not in keys:
            continue
        for level in levels[1:] if quick else levels:
            out.append((f"{key}={level:g}", ((key, level),)))
    out.append(("combined", COMBINED))
    return out


def run(task) -> dict:
    """One episode: (suite spec, world index, condition name, perturbations, navigator)."""
    from fuzzynav.bench.cells import perturb_scenario
    from fuzzynav.bench.suites import parse_suite
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    spec, index, name, perturbations, navigator = task
    suite = parse_suite(spec)
    scenario = perturb_scenario(suite.scenario(index, 0), perturbations)
    trace = run_episode(scenario, make_controller(navigator), seed=0)
    return {"suite": suite.name, "world": suite.world_name(index, 0), "condition": name, "navigator": navigator,
            "outcome": trace.outcome, "time_s": round(float(trace.t[-1]), 2)}


def key(row: dict) -> tuple:
    return row["suite"], row["world"], row["condition"], row["navigator"]


def table(rows: list[dict], suites: list[str], navigators: list[str], names: list[str]) -> str:
    """Markdown: per suite, success / collision % of each navigator under each condition."""
    lines = []
    for suite in suites:
        lines += [f"\n**{suite}** (success % / collision %)\n", "| condition | " + " | ".join(navigators) + " |",
                  "|---" * (len(navigators) + 1) + "|"]
        for name in names:
            cells = []
            for navigator in navigators:
                mine = [r for r in rows if r["suite"] == suite and r["condition"] == name and r["navigator"] == navigator]
                if not mine:
                    cells.append("–")
                    continue
                reached = sum(r["outcome"] == "reached" for r in mine) / len(mine)
                hit = sum(r["outcome"] == "collision" for r in mine) / len(mine)
                cells.append(f"{100 * reached:.0f} / {100 * hit:.0f}")
            lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot(rows: list[dict], suite: str, navigators: list[str], out: Path) -> None:
    """Success and collision rate against each swept key (one column per key)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(SWEEPS), figsize=(4 * len(SWEEPS), 6.5), sharey="row")
    for column, (sweep, levels) in enumerate(SWEEPS.items()):
        xs = (0.0, *levels)
        for navigator in navigators:
            for row_index, outcome in enumerate(("reached", "collision")):
                ys, shown = [], []
                for x in xs:
                    name = "none" if x == 0.0 else f"{sweep}={x:g}"
                    mine = [r for r in rows if r["suite"] == suite and r["condition"] == name
                            and r["navigator"] == navigator]
                    if mine:
                        shown.append(x)
                        ys.append(100 * sum(r["outcome"] == outcome for r in mine) / len(mine))
                axes[row_index, column].plot(shown, ys, marker="o", label=navigator)
        axes[0, column].set_title(LABELS[sweep])
        axes[1, column].set_xlabel(LABELS[sweep])
    axes[0, 0].set_ylabel("success %")
    axes[1, 0].set_ylabel("collisions %")
    axes[0, -1].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"robustness on {suite}")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def main() -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("suites", nargs="+", help="folder of scenario files or FAMILY:COUNT[:SEED]")
    parser.add_argument("--navigators", required=True, help="comma-separated controller names")
    parser.add_argument("--out", required=True)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--quick", action="store_true", help="two levels per key (the middle and the largest)")
    parser.add_argument("--tables-only", action="store_true", help="no runs: the table and plots of the runs done")
    parser.add_argument("--keys", default=",".join(SWEEPS),
                        help="comma-separated keys to sweep (default: all; none and combined always run)")
    args = parser.parse_args()
    keys = [k.strip() for k in args.keys.split(",") if k.strip()]
    unknown = [k for k in keys if k not in SWEEPS]
    if unknown:
        parser.error(f"--keys: unknown {', '.join(unknown)}; known: {', '.join(SWEEPS)}")
    from fuzzynav.bench.suites import parse_suite

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    navigators = [n.strip() for n in args.navigators.split(",") if n.strip()]
    suites = [parse_suite(spec) for spec in args.suites]
    chosen = conditions(args.quick, keys)
    done_file = out / "runs.jsonl"
    rows = [json.loads(line) for line in done_file.read_text().splitlines() if line.strip()] \
        if done_file.exists() else []
    done = {key(r) for r in rows}
    # world by world (the suites in turn): a sweep stopped early has every condition on its first worlds
    tasks = [(spec, index, name, perturbations, navigator)
             for index in range(max(suite.size for suite in suites))
             for spec, suite in zip(args.suites, suites) if index < suite.size
             for name, perturbations in chosen for navigator in navigators
             if (suite.name, suite.world_name(index, 0), name, navigator) not in done]
    print(f"{len(tasks)} runs to do, {len(rows)} done", flush=True)
    if args.tables_only:
        tasks = []
    with open(done_file, "a", encoding="utf-8") as stream, multiprocessing.Pool(args.workers) as pool:
        for row in pool.imap_unordered(run, tasks):
            stream.write(json.dumps(row) + "\n")
            stream.flush()
            rows.append(row)
    names = [name for name, _ in chosen]
    (out / "table.md").write_text(table(rows, [s.name for s in suites], navigators, names))
    for suite in suites:
        plot(rows, suite.name, navigators, out / f"robustness-{suite.name.replace(':', '-')}.png")
    print((out / "table.md").read_text())


if __name__ == "__main__":
    main()
