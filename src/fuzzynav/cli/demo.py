"""``fuzzynav demo --out DIR`` — the main job: every built-in thesis scenario with its controllers.

Each built-in scenario lists in its ``controllers`` key the controllers the thesis runs on it
(chapter IV navigators on the Fig IV.12–IV.23 worlds, the trackers on the chapter V paths…).
The demo runs every pair, prints a progress line per run, and writes into DIR one trajectory /
command plot per run (``<scenario>--<controller>.png``) and the metrics table as
``metrics.md`` (Markdown) and ``metrics.json``.
"""

from __future__ import annotations

import json
from pathlib import Path

from fuzzynav.atomic import write_text_atomic
from fuzzynav.control.registry import make_controller
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.scenario import list_scenarios, load_scenario

COLUMNS = ("scenario", "controller", "outcome", "time_s", "path_length_m", "min_clearance_m")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "demo",
        help="run the thesis' controllers on the built-in scenarios (plots + metrics table)",
        description=__doc__.split("\n\n")[1],
    )
    parser.add_argument("--out", type=Path, default=Path("fuzzynav-out"), help="output folder")
    parser.add_argument("--scenario", action="append", metavar="NAME",
                        help="only this built-in scenario (repeatable)")
    parser.add_argument("--no-plots", action="store_true", help="metrics only")
    parser.set_defaults(func=run)


def demo_runs(names=None) -> list[tuple[str, str]]:
    """The (scenario, controller) pairs of the built-in scenarios (all, or those named)."""
    runs = []
    for name in names or list_scenarios():
        runs.extend((name, controller) for controller in load_scenario(name).controllers)
    return runs


def markdown_table(rows: list[dict]) -> str:
    """The metrics as a Markdown table (one row per run)."""
    def cell(value):
        return f"{value:.2f}" if isinstance(value, float) else str(value)

    lines = ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    lines += ["| " + " | ".join(cell(row.get(key)) for key in COLUMNS) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def run(args) -> int:
    runs = demo_runs(args.scenario)
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for index, (name, controller_name) in enumerate(runs, 1):
        scenario = load_scenario(name)
        trace = run_episode(scenario, make_controller(controller_name), seed=0)
        row = metrics(trace, scenario)
        rows.append(row)
        if not args.no_plots:
            from fuzzynav.viz.trajectories import plot_episode

            plot_episode(trace, scenario, args.out / f"{name}--{controller_name}.png")
        print(f"[{index}/{len(runs)}] {name} / {controller_name}: {row['outcome']} in {row['time_s']:.1f} s",
              flush=True)
    write_text_atomic(args.out / "metrics.json", json.dumps(rows, indent=2))
    write_text_atomic(args.out / "metrics.md", markdown_table(rows))
    print(f"wrote {len(rows)} runs: {args.out / 'metrics.md'}, {args.out / 'metrics.json'}")
    return 0
