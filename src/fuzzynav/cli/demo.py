"""``fuzzynav demo --out OUT`` — the main job: every built-in thesis scenario with its controllers.

Each built-in scenario lists in its ``controllers`` key the controllers to run on it: the thesis'
own (the trackers on the chapter V paths…) or, on the chapter IV obstacle worlds, this package's
variants of them (``fuzzy-2b``, ``fuzzy-5b-rays``).
The demo first compiles the kernels its controllers use (``fuzzynav warmup``; a progress
bar on the first run), then runs every pair in ``--workers`` processes (default: one per core; the
results do not depend on it), prints a progress line per run in order, and writes into OUT one trajectory /
command plot per run (``<scenario>--<controller>.png``) and the metrics table as
``metrics.md`` (Markdown) and ``metrics.json``. ``--scenario`` takes built-in names or your own
scenario files, ``--controllers a,b`` the controllers to run on them (instead of their own list; each
on the scenarios whose task it can do, a scenario none of them can do is refused before any run).

The table's columns are the metrics of :func:`fuzzynav.sim.metrics.metrics` shared by every task,
then each task's own: cross-track error (mean / max) and waypoints reached for paths, capture
time for moving targets (empty where a task has none).
"""

from __future__ import annotations

import json
import os
import shutil
import sys
from pathlib import Path

from fuzzynav import threads, validation
from fuzzynav.cli import arguments, help_line

COLUMNS = ("scenario", "controller", "outcome", "time_s", "path_length_m", "min_clearance_m", "final_distance_m")
LEGEND = ("time_s: simulated seconds to the end of the run (its outcome); path_length_m: the length driven; "
          "min_clearance_m: the least gap between the robot's footprint and any obstacle or the workspace's "
          "boundary (the boundary alone in a world without obstacles; < 0 an overlap); final_distance_m: to the "
          "goal, waypoint or target at the end; cross-track errors: from the path polyline (§V.4). Every field: "
          "`fuzzynav run SCENARIO --json`, documented in fuzzynav.sim.metrics.\n")
TASK_COLUMNS = {"path": ("mean_cross_track_m", "max_cross_track_m", "waypoints_reached"),
                "target": ("capture_time_s",)}


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "demo", run,
                               help=help_line("demo"),
                               description=__doc__.split("\n\n")[1],
                               example="""
fuzzynav demo --out fuzzynav-out
fuzzynav demo --scenario fig-IV-23 --scenario my-world.yaml --controllers fuzzy-5b,dwa --out my-demo/""")
    parser.add_argument("--out", type=arguments.path, default=Path("fuzzynav-out"), help="output folder (default: fuzzynav-out)")
    parser.add_argument("--scenario", action="append", metavar="NAME|FILE",
                        help="only this built-in scenario or scenario file (repeatable)")
    parser.add_argument("--controllers", metavar="A,B", type=arguments.names,
                        help="run these controllers (comma-separated) instead of each scenario's own list")
    parser.add_argument("--no-plots", action="store_true", help="metrics only")
    parser.add_argument("--workers", type=arguments.count(validation.MAX_WORKERS), default=None, metavar="N",
                        help=f"parallel processes, 1 to {validation.MAX_WORKERS} (default: the cores this process may use); "
                             "the results do not depend on it")


def demo_runs(names=None, controllers=None, skipped: list | None = None) -> list[tuple[str, str]]:
    """The (scenario, controller) pairs of the built-in scenarios (all, or those named — built-in
    names or scenario files), with each scenario's own controllers or the ``controllers`` given.

    Every pair is one whose controller can do the scenario's task, checked before anything runs
    (:func:`fuzzynav.catalog.controllers.check_task`): a scenario's own controller that cannot is an
    :class:`InputError` naming the scenario; of the ``controllers`` given, those that cannot are left
    out of that scenario's runs (each such pair added to ``skipped``: a goal world and a path given
    with ``--controllers fuzzy-5b,fuzzy-tracker`` run one each). A scenario named (``names``) that
    none of them can do is an :class:`InputError` naming it; of all the built-in ones, it is left
    out (every controller does one of the tasks the built-in scenarios hold)."""
    from fuzzynav.catalog.controllers import check_task, scenario_controllers, spec_of
    from fuzzynav.errors import InputError
    from fuzzynav.storage import file_name_part
    from fuzzynav.world.scenario import list_scenarios
    from fuzzynav.world.scenario_file import open_scenario

    for k, controller in enumerate(controllers or ()):
        try:  # an unknown name is refused as such, not as a scenario's
            spec_of(controller)
        except InputError as error:
            raise InputError(error.problem, field="--controllers") from None
        if controller in controllers[:k]:
            raise InputError(f"{controller} is given twice", field="--controllers")
    runs, named = [], {}  # the file name part of each scenario's plots (any case: some systems ignore it)
    for name in names or list_scenarios():
        scenario = open_scenario(name)
        plot_name = file_name_part(scenario.name).lower()
        if named.get(plot_name) == name:
            raise InputError("is given twice", source=name, field="--scenario")
        if plot_name in named:  # its plots and table rows would be the other's
            raise InputError(f"scenario {scenario.name!r} is also the name of {named[plot_name]}, as the name of a "
                             f"file ({file_name_part(scenario.name)}--….png): each run's plot is named after its "
                             "scenario (give each file its own name: key)", source=name, field="--scenario")
        named[plot_name] = name
        chosen = controllers or scenario_controllers(scenario, name)
        if not chosen and names:  # a built-in scenario without controllers is left out of the full demo
            raise InputError(f"scenario {scenario.name!r} names no controllers (no 'controllers' key): "
                             "give them with --controllers, e.g. --controllers fuzzy-5b,fuzzy-2b", field="--controllers")
        able = [controller for controller in chosen if scenario.task in spec_of(controller).tasks]
        for i, controller in enumerate(chosen):
            field = "--controllers" if controllers else f"controllers[{i}]"
            if controller not in able and (not controllers or (not able and names)):
                try:
                    check_task(controller, scenario.task, field=field)
                except InputError as error:
                    raise InputError(error.problem, source=name, field=field) from None
        if skipped is not None:
            skipped.extend((name, controller) for controller in chosen if controller not in able)
        runs.extend((name, controller) for controller in able)
    return runs


def markdown_table(rows: list[dict]) -> str:
    """The metrics as a Markdown table (one row per run; task columns empty where they do not apply)."""
    def cell(value):
        return "" if value is None else f"{value:.3f}" if isinstance(value, float) else str(value)

    tasks = dict.fromkeys(row["task"] for row in rows)
    columns = COLUMNS + tuple(key for task in tasks for key in TASK_COLUMNS.get(task, ()))
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(cell(row.get(key)) for key in columns) + " |" for row in rows]
    shown = {(row["controller"], row["scenario"]): tuple(cell(row.get(key)) for key in columns[2:]) for row in rows}
    return "\n".join(lines) + "\n\n" + LEGEND + "".join(
        f"\n{a} and {b} give the same numbers, to the digits shown, on all {n} scenarios both ran: they drive "
        "alike there.\n" for a, b, n in _alike(shown))


def _alike(shown: dict) -> list[tuple[str, str, int]]:
    """(a, b, n): controllers whose rows read the same on the n > 1 scenarios both ran (``shown``:
    the printed cells by (controller, scenario)), as the Markdown table prints them."""
    runs: dict[str, dict] = {}
    for (controller, scenario), cells in shown.items():
        runs.setdefault(controller, {})[scenario] = cells
    pairs = []
    for i, a in enumerate(runs):
        for b in list(runs)[i + 1:]:
            common = runs[a].keys() & runs[b].keys()
            if len(common) > 1 and all(runs[a][s] == runs[b][s] for s in common):
                pairs.append((a, b, len(common)))
    return pairs


def run_one(item: tuple[str, str, Path | None]) -> tuple[dict, str]:
    """One demo run, ``(scenario, controller, plot folder or None)``: its metrics row, and why it
    did not reach its goal (the scenario's description) or ``""``; the plot written when a folder is
    given. Module-level, so the demo's worker processes can run it."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import metrics, run_episode
    from fuzzynav.storage import file_name_part
    from fuzzynav.world.scenario_file import open_scenario

    name, controller_name, plots = item
    scenario = open_scenario(name)
    trace = run_episode(scenario, make_controller(controller_name), seed=0)
    row = metrics(trace, scenario)
    if plots is not None:
        from fuzzynav.viz.trajectories import plot_episode

        plot_episode(trace, scenario, plots / f"{file_name_part(scenario.name)}--{file_name_part(controller_name)}.png")
    why = f" — the scenario: {scenario.description}" if row["outcome"] != "reached" and scenario.description else ""
    return row, why


def run(args) -> int:
    from fuzzynav.cli.warmup import announce, warm_up

    arguments.check_folder(args.out, "--out", ("metrics.json", "metrics.md"))  # before the header, not after
    what = ", ".join(args.scenario) if args.scenario else "the built-in thesis scenarios"
    if args.controllers:
        driven = ", ".join(args.controllers)
    elif args.scenario:
        driven = "the controllers it names" if len(args.scenario) == 1 else "the controllers each names"
    else:
        driven = "their controllers"
    print(f"fuzzynav demo: {what} with {driven}, into {args.out}/", flush=True)
    from fuzzynav.jit import NOTICE

    NOTICE.silence()  # loading a scenario may compile (its start's placement check): the banner below says it
    skipped: list[tuple[str, str]] = []
    runs = demo_runs(args.scenario, args.controllers, skipped)  # bad names are refused before compiling is said
    for controller_name in dict.fromkeys(name for _, name in skipped):
        names = [name for name, skipped_name in skipped if skipped_name == controller_name]
        print(f"left out: {controller_name} on {', '.join(names)} (a task it cannot do)", flush=True)
    announce()  # making a controller may compile (neural-tracker): after the banner that silences the notice
    from fuzzynav.bench.backends import pool_map
    from fuzzynav.storage import write_text_atomic

    args.out.mkdir(parents=True, exist_ok=True)
    warm_up(list(dict.fromkeys(name for _, name in runs)))
    rows: list[dict] = []
    finished: dict[int, tuple[dict, str]] = {}

    def report(index: int, result: tuple[dict, str]) -> None:  # the lines in the runs' order
        finished[index] = result
        while len(rows) in finished:
            row, why = finished.pop(len(rows))
            rows.append(row)
            print(f"[{len(rows)}/{len(runs)}] {row['scenario']} / {row['controller']}: {row['outcome']} "
                  f"after {row['time_s']:.1f} s simulated{why}", flush=True)

    items = [(name, controller_name, None if args.no_plots else args.out) for name, controller_name in runs]
    pool_map(run_one, items, min(args.workers or threads.cores(), len(items) or 1), report)
    write_text_atomic(args.out / "metrics.json", json.dumps(rows, indent=2))
    write_text_atomic(args.out / "metrics.md", markdown_table(rows))
    plots = "" if args.no_plots else f", {len(rows)} plots {args.out}/<scenario>--<controller>.png"
    print(f"wrote {len(rows)} run{'s' * (len(rows) != 1)}: {args.out / 'metrics.md'}, {args.out / 'metrics.json'}{plots}")
    command = command_name()
    print(f"next: `{command} run fig-IV-23 --plot u.png` drives the default navigator, fuzzy-5b (its first run "
          "compiles its kernels, about half a minute once); "
          f"`{command} COMMAND --help` shows each command with examples; the README's tour tries them all")
    return 0


def command_name() -> str:
    """How to type the command in this shell: ``fuzzynav`` when it is on the PATH, else the
    script beside this Python (e.g. ``.venv/bin/fuzzynav`` of an environment not activated), by
    its path from the current folder when that path stays inside it, else by its absolute path."""
    if shutil.which("fuzzynav"):
        return "fuzzynav"
    script = Path(sys.executable).parent / "fuzzynav"
    if not (script.exists() or script.with_suffix(".exe").exists()):
        return "fuzzynav"
    try:
        relative = os.path.relpath(script)
    except ValueError:  # another drive (Windows)
        return str(script)
    return str(script.absolute()) if relative.startswith(os.pardir) else relative
