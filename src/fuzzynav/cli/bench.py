"""``fuzzynav bench SUITE… --controllers a,b,c [--fis ROLE=FILE] [--seeds K] [--workers N]
[--backend local|ray] [--perturb KEY=VALUE] [--plant kinematic|mujoco] [--out DIR] [--resume]`` — a benchmark campaign
(:mod:`fuzzynav.bench`).

Run every controller on every world of the suites (x seeds), write runs.csv as runs finish, then
rates with 95 % Wilson intervals, medians, plots and index.html.

SUITE is a folder of scenario files (e.g. written by ``fuzzynav import barn``) or a generated
family ``FAMILY[:COUNT[:SEED]]`` (circles, mixed, dense, utrap, dynamic, dynabarn, office, maze, forest). Controllers are registered
names (``fuzzynav run --help`` lists them) or trained model files (``.json``/``.npz``, labelled by
their file name without the suffix). ``--fis ROLE=FILE`` replaces that rule base in every
controller of the campaign that has the role (as ``fuzzynav run --fis`` does). ``--perturb
KEY=VALUE`` (repeatable) sets one of the robot's imperfections in every world
(:mod:`fuzzynav.robot.imperfections`, e.g. ``robot.sensor_noise.range_sigma=0.02``), recorded in
perturb.json and the summary. ``--plant`` chooses what moves the robots
(:mod:`fuzzynav.sim.plants`). Writes runs.csv /
runs.jsonl as runs finish, then summary.md, summary.json, plots and index.html into --out.
"""

from __future__ import annotations

import sys
from pathlib import Path

from fuzzynav import threads, validation
from fuzzynav.cli import arguments, help_line
from fuzzynav.cli.run import PLANT_HELP
from fuzzynav.errors import InputError

EXAMPLES = """
fuzzynav bench mixed:3 utrap:3 --controllers fuzzy-5b,dwa,astar-pp --out bench   # bench/index.html
fuzzynav bench mixed:100 utrap:100 --controllers fuzzy-5b,dwa --seeds 3 --workers 2 --out bench
fuzzynav bench barn-1.5 --controllers fuzzy-5b,dwa --out bench-barn   # a folder 'fuzzynav import barn' wrote"""


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "bench", run, help=help_line("bench"),
                               description=__doc__.split("\n\n")[1], example=EXAMPLES,
                               when_stopped="the runs done are kept; the same command with --resume goes on")
    parser.add_argument("suites", nargs="+", metavar="SUITE",
                        help="folder of scenario files, or FAMILY[:COUNT[:SEED]] with FAMILY circles|mixed|dense|utrap|dynamic|dynabarn|office|maze|forest, "
                             f"COUNT 1 to {validation.MAX_WORLDS:,}, SEED 0 to 2**63-1")
    parser.add_argument("--controllers", required=True, metavar="A,B,C",
                        help="comma-separated controller names or model files (.json/.npz)")
    parser.add_argument("--fis", action="append", metavar="ROLE=FILE",
                        help="replace the fuzzy system for ROLE in every controller that has it (any "
                             ".yaml/.json/.fll/.fis; repeat per role; part of what --resume checks)")
    parser.add_argument("--perturb", action="append", metavar="KEY=VALUE",
                        help="set one of the robot's imperfections in every world, e.g. "
                             "robot.sensor_noise.range_sigma=0.02 (repeat per key; keys: robot.sensor_noise."
                             "{range_sigma,dropout,max_range}, robot.actuation.{latency,steering_rate,acceleration,"
                             "slip}, robot.odometry.drift; part of what --resume checks)")
    parser.add_argument("--seeds", type=arguments.count(validation.MAX_SEEDS), default=1, metavar="K",
                        help=f"seeds 0..K-1, K from 1 to {validation.MAX_SEEDS:,} (generated families: K world "
                             f"sets; default 1); a campaign holds at most {validation.MAX_CAMPAIGN_RUNS:,} runs "
                             "(worlds x seeds x controllers), checked before any run")
    parser.add_argument("--workers", type=arguments.count(validation.MAX_WORKERS), default=None, metavar="N",
                        help=f"parallel workers, 1 to {validation.MAX_WORKERS} (default: the cores this process may use)")
    parser.add_argument("--backend", choices=("local", "ray"), default="local",
                        help="local process pool (default) or Ray tasks (pip install -e '.[cluster]' in the clone)")
    parser.add_argument("--ray-address", metavar="ADDR", default=None,
                        help="Ray cluster to join (default: $RAY_ADDRESS, else a local instance)")
    parser.add_argument("--plant", metavar="PLANT", default="kinematic", help=PLANT_HELP)
    parser.add_argument("--out", default="bench-out", type=arguments.path, metavar="DIR", help="output folder (default bench-out)")
    parser.add_argument("--resume", action="store_true", help="continue the campaign already in --out")
    parser.add_argument("--gallery", type=arguments.count(1000, lo=0), default=6, metavar="N",
                        help="failed runs drawn per controller, 0 to 1000 (default 6, 0: none)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _controllers(text: str) -> tuple[tuple[str, str], ...]:
    from fuzzynav.bench.cells import build_controller
    from fuzzynav.catalog.controllers import check_task
    from fuzzynav.storage import check_model_file, is_model_file

    specs = [spec.strip() for spec in text.split(",") if spec.strip()]
    if not specs:
        raise InputError("no controller given", field="--controllers")
    pairs = []
    for spec in specs:
        if is_model_file(spec):
            spec = str(check_model_file(spec, "--controllers").resolve())
        try:  # unknown names, controllers of other tasks and bad model files fail before any run
            if not is_model_file(spec):
                check_task(spec, "goal", field="--controllers")  # a campaign's worlds are goal tasks
            build_controller(spec)
        except InputError as error:
            if is_model_file(spec):
                raise
            raise InputError(error.problem, field="--controllers") from None
        pairs.append((Path(spec).stem if is_model_file(spec) else spec, spec))
    labels = [label for label, _ in pairs]
    for label in labels:  # a model file's name labels rows, the table on the terminal and the plots
        validation.text(label, None, "--controllers", one_line=True)
    if len(set(labels)) != len(labels):
        raise InputError(f"controller labels repeat ({', '.join(labels)})", field="--controllers")
    return tuple(pairs)


def _replacements(options: list[str] | None, controllers) -> tuple[tuple[str, str], ...]:
    """(role, absolute file) of every ``--fis ROLE=FILE``, each checked against every controller
    that has the role (InputError when none has it, or when the file does not fit)."""
    from fuzzynav.catalog.roles import ROLES, make_with_systems, parse_option, systems_from_options
    from fuzzynav.storage import is_model_file

    if not options:
        return ()
    pairs = [parse_option(option) for option in options]
    names = [spec for _, spec in controllers if not is_model_file(spec)]
    for option, (role, _) in zip(options, pairs):
        if not any(role in ROLES.get(name, {}) for name in names):
            known = sorted({r for name in names for r in ROLES.get(name, {})})
            raise InputError(f"no controller of the campaign has the role {role} (their roles: "
                             f"{', '.join(known) or 'none'})", field=f"--fis {option}")
    for name in names:
        mine = [option for option, (role, _) in zip(options, pairs) if role in ROLES.get(name, {})]
        if mine:
            make_with_systems(name, systems_from_options(name, mine))
    return tuple((role, str(Path(path).resolve())) for role, path in pairs)


def _perturbations(options: list[str] | None) -> tuple[tuple[str, float], ...]:
    """(key, value) of every ``--perturb KEY=VALUE``, each checked (InputError naming it)."""
    from fuzzynav.robot.imperfections import NONE, perturbed

    pairs: dict[str, float] = {}
    for option in options or ():
        name, equals, text = option.partition("=")
        if not equals:
            raise InputError(f"must be KEY=VALUE, got {validation.shown(option)}", field="--perturb")
        if name in pairs:
            raise InputError(f"{name} given twice", field="--perturb")
        try:
            value = arguments.decimal(text)
        except ValueError:
            raise InputError(f"the value of {name} must be a number, got {validation.shown(text)}",
                             field="--perturb") from None
        perturbed(NONE, name, value, source="--perturb")
        pairs[name] = value
    return tuple(pairs.items())


def run(args) -> int:
    from fuzzynav.bench.backends import ray_address
    from fuzzynav.bench.campaign import Plan, run_campaign
    from fuzzynav.bench.report import write_reports
    from fuzzynav.bench.suites import parse_suite
    from fuzzynav.robot.tricycle import DEFAULT_PARAMS
    from fuzzynav.sim.plants import DEFAULT_PLANT, check_plant

    suites = tuple(parse_suite(spec) for spec in args.suites)
    names = [suite.name for suite in suites]
    if len(set(names)) != len(names):  # a campaign's rows name a folder suite by its last part
        twice = sorted({name for name in names if names.count(name) > 1})
        given = [spec for spec, name in zip(args.suites, names) if name in twice]
        if len(set(given)) < len(given):
            raise InputError(f"suites repeat: {next(spec for spec in given if given.count(spec) > 1)} is given twice",
                             field="SUITE")
        folders = any(suite.family is None for suite in suites if suite.name in twice)
        raise InputError(f"suites repeat: {', '.join(given)} are all {', '.join(twice)}"
                         + (" (a folder suite is named by its last part: rename one)" if folders else ""), field="SUITE")
    check_plant(args.plant)
    if args.ray_address is not None and args.backend != "ray":
        raise InputError("joins a Ray cluster: give --backend ray too", field="--ray-address")
    if args.backend == "ray":
        ray_address(args.ray_address)  # before the campaign's folder is made
    controllers = _controllers(args.controllers)
    folder_specs = [spec for spec, suite in zip(args.suites, suites) if suite.family is None]
    if folder_specs and args.seeds > 1:  # the same worlds again: only the seeded draws differ
        print(f"note: {', '.join(folder_specs)}: a folder's worlds are the same for every seed, which changes only "
              "the sensor noise and the controllers' random draws: a deterministic controller without noise repeats "
              "each run, and the rates' intervals count every repeat as a trial", file=sys.stderr)
    plan = Plan(suites, controllers, args.seeds, DEFAULT_PARAMS.radius, _replacements(args.fis, controllers),
                _perturbations(args.perturb), args.plant)
    out = Path(args.out)
    workers = args.workers or threads.cores()
    rows = run_campaign(plan, out, resume=args.resume, backend=args.backend, workers=workers,
                        address=args.ray_address, progress=not args.quiet)
    arguments_used = {"suites": names, "controllers": [label for label, _ in plan.controllers], "seeds": args.seeds,
                      **({"fis": dict(plan.fis)} if plan.fis else {}),
                      **({"perturb": dict(plan.perturb)} if plan.perturb else {}),
                      **({"plant": plan.plant} if plan.plant != DEFAULT_PLANT else {})}
    summary = write_reports(plan, rows, out, gallery=args.gallery, arguments=arguments_used)
    print("\n".join(_table(summary["results"])))
    print(f"{len(rows)} run{'s' * (len(rows) != 1)} in {out}: summary.md (with 95 % intervals and more), summary.json, "
          "index.html", file=sys.stderr)
    return 0


def _table(records: list[dict]) -> list[str]:
    """The campaign's rates in a few columns, a line per suite and controller (summary.md has them all)."""
    width = max([len("controller")] + [len(r["controller"]) for r in records])
    suite = max([len("suite")] + [len(r["suite"]) for r in records])
    lines = [f"{'suite':<{suite}}  {'controller':<{width}}  {'runs':>5}  {'success':>8}  {'collision':>9}  "
             f"{'timeout':>8}  {'median time':>11}"]
    for r in records:
        time_s = "–" if r["median_time_s"] is None else f"{r['median_time_s']:.1f} s"
        lines.append(f"{r['suite']:<{suite}}  {r['controller']:<{width}}  {r['runs']:>5}  "
                     + "  ".join(f"{100 * r[o]['rate']:>{w - 2}.1f} %" for o, w in (("reached", 8), ("collision", 9),
                                                                                 ("timeout", 8)))
                     + f"  {time_s:>11}")
    return lines
