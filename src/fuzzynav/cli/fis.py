"""``fuzzynav fis show|eval|convert|plot|export-c`` — fuzzy systems on the command line.

SYSTEM is a built-in system (``goal-seeking``, ``obstacle-avoidance``, ``tracking``, ...), a
controller's role (``fuzzy-5b:foa``: the system that role uses) or a file (``.json``,
``.yaml``/``.yml``, ``.fll``, MATLAB ``.fis``).

    fuzzynav fis show goal-seeking
    fuzzynav fis eval goal-seeking --input drg=5 --input theta=0.3      # JSON on stdout
    fuzzynav fis eval tracking --csv inputs.csv -o outputs.csv          # one column per input
    fuzzynav fis convert goal-seeking --to fll -o gs.fll
    fuzzynav fis convert fuzzy-5b-thesis:foa --to yaml -o foa.yaml      # edit, then run --fis foa=foa.yaml
    fuzzynav fis convert tipper.fis --to yaml
    fuzzynav fis plot tracking --surface -o fig-V7.png
    fuzzynav fis export-c goal-seeking -o controller.c [--fixed Q16.16]   # and controller.h
"""

from __future__ import annotations

import csv
import difflib
import functools
import io
import json
import math
import sys
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.catalog.roles import ROLES, default_system
from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.engine.convert import engine_to_system
from fuzzynav.fuzzy.export_c import FIXED_FORMATS
from fuzzynav.fuzzy.fll_terms import term_to_fll
from fuzzynav.fuzzy.io import FORMATS, dumps, load
from fuzzynav.fuzzy.io.files import format_of
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems import SYSTEMS, get_system
from fuzzynav.storage import is_model_file, read_document, savefig_atomic, write_text_atomic


def read_model_or_none(path: str) -> dict | None:
    """The document of ``path`` if it is a model file (JSON or NPZ with a ``kind``), else ``None``."""
    try:
        return read_document(path)
    except InputError:
        return None


def resolve(name: str) -> FuzzySystem | Engine:
    """A built-in system by name, a controller's role (``fuzzy-5b:foa``), or the system in the file ``name``."""
    if name in SYSTEMS:
        return get_system(name)
    controller, sep, role = name.partition(":")
    if sep and not Path(name).exists() and controller in ROLES:
        return default_system(controller, role, field="system")
    npz = Path(name).suffix.lower() == ".npz"  # only a model file: why it cannot be read is the answer
    if npz or is_model_file(name) and Path(name).is_file():
        document = read_document(name) if npz else read_model_or_none(name)
        if document is not None and document.get("kind") == "anfis-tracker":
            from fuzzynav.learn.tasks.trackers import anfis_tracker_system

            return anfis_tracker_system(document, name)  # the trained ANFIS, exported
        if document is not None and npz:  # a learned rule base stored as NPZ
            from fuzzynav.fuzzy.io.document import from_document

            return from_document(document, source=name)
    if Path(name).suffix:
        return load(name)
    close = difflib.get_close_matches(name, [*SYSTEMS, *(f"{c}:{r}" for c in ROLES for r in ROLES[c])], n=3)
    hint = f" (did you mean {', '.join(close)}?)" if close else ""
    raise InputError(f"not a built-in system, a CONTROLLER:ROLE nor a .json/.yaml/.fll/.fis file{hint}; built-in "
                     f"systems: {', '.join(SYSTEMS)}; controllers with roles: {', '.join(ROLES)}", field=name)


def describe(system: FuzzySystem | Engine) -> str:
    """Variables, terms and the rule base (as a grid when it is a complete two-input table)."""
    if isinstance(system, Engine):
        return _describe_engine(system)
    out = [f"{system.name or '(unnamed)'}: {system.description}".rstrip(": "),
           f"method {system.method}, t-norm {system.tnorm}, defuzzifier {system.defuzzifier}"
           + (f", implication {system.implication}, aggregation {system.aggregation}, resolution {system.resolution}"
              if system.method == "mamdani" else "")]
    for side, variables in (("input", system.inputs), ("output", system.outputs)):
        for v in variables:
            out.append(f"{side} {v.name} in [{v.universe[0]:.6g}, {v.universe[1]:.6g}]")
            out += [f"    {label:<4} {mf.kind} {' '.join(f'{p:.6g}' for p in mf.params())}" for label, mf in v.terms.items()]
    grid = _grid(system)
    if grid:
        out.append(grid)
    else:
        out += [f"rule {i + 1}: {rule.text()}" for i, rule in enumerate(system.rules)]
    return "\n".join(out)


def _describe_engine(engine: Engine) -> str:
    """An engine's variables (with their own settings) and its rule blocks."""
    out = [f"{engine.name or '(unnamed)'}: {engine.description}".rstrip(": ")]
    for side, variables in (("input", engine.inputs), ("output", engine.outputs)):
        for v in variables:
            flags = [f"lock-range {'on' if v.lock_range else 'off'}"] + ([] if v.enabled else ["disabled"])
            if side == "output":
                flags += [f"aggregation {v.aggregation or 'none'}",
                          f"defuzzifier {v.defuzzifier.text() if v.defuzzifier else 'none'}"
                          + (" (MATLAB sampling)" if v.defuzzifier and v.defuzzifier.grid == "linspace" else ""),
                          f"default {v.default:g}"] + (["lock-previous"] if v.lock_previous else [])
            out.append(f"{side} {v.name} in [{v.minimum:.6g}, {v.maximum:.6g}], {', '.join(flags)}")
            out += [f"    {label:<4} {term_to_fll(mf)}" for label, mf in v.terms.items()]
    for b, block in enumerate(engine.blocks, start=1):
        out.append(f"rule block {block.name or b}: conjunction {block.conjunction or 'none'}, disjunction "
                   f"{block.disjunction or 'none'}, implication {block.implication or 'none'}, activation "
                   f"{block.activation}{'' if block.enabled else ' (disabled)'}")
        out += [f"rule {i + 1}: {rule.text()}" for i, rule in enumerate(block.rules)]
    return "\n".join(out)


def _grid(system: FuzzySystem) -> str | None:
    """The rule table, if the rules fill a two-input grid exactly once.

    Rows are the input with more terms (the first input on a tie): the layout of Tables IV.1,
    IV.2 (rows θ, columns distance) and V.1 (rows θ_er, columns dθ_er).
    """
    if len(system.inputs) != 2:
        return None
    c = system.compiled
    if (c.premises < 0).any() or (c.weights != 1).any() or (c.conclusions < 0).any():
        return None
    row_i = 0 if len(system.inputs[0].terms) >= len(system.inputs[1].terms) else 1
    col_i = 1 - row_i
    cols, rows = system.inputs[col_i], system.inputs[row_i]
    cells: dict[tuple[int, int], str] = {}
    for r in range(len(system.rules)):
        key = (int(c.premises[r, row_i]), int(c.premises[r, col_i]))
        if key in cells:
            return None
        cells[key] = "/".join(v.labels[c.conclusions[r, o]] for o, v in enumerate(system.outputs))
    if len(cells) != len(rows.labels) * len(cols.labels):
        return None
    corner = f"{rows.name} \\ {cols.name}"
    first_width = max(len(corner), *(len(label) for label in rows.labels)) + 2
    width = max(len(s) for s in list(cells.values()) + cols.labels) + 2
    lines = [f"rules ({'/'.join(system.output_names)}):",
             f"{corner:<{first_width}}" + "".join(f"{label:<{width}}" for label in cols.labels)]
    for i, label in enumerate(rows.labels):
        lines.append(f"{label:<{first_width}}" + "".join(f"{cells[i, j]:<{width}}" for j in range(len(cols.labels))))
    return "\n".join(line.rstrip() for line in lines)


def _parse_inputs(system: FuzzySystem, pairs: list[str]) -> np.ndarray:
    values = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or name not in system.input_names:
            raise InputError(f"expected NAME=VALUE with NAME in {', '.join(system.input_names)}", field=f"--input {pair}")
        if name in values:
            raise InputError(f"{name} is given twice", field=f"--input {pair}")
        try:
            values[name] = arguments.decimal(value)
        except ValueError as error:
            raise InputError(str(error), field=f"--input {pair}") from None
        if math.isnan(values[name]):
            raise InputError("NaN input", field=f"--input {pair}")
    missing = [n for n in system.input_names if n not in values]
    if missing:
        raise InputError(f"missing input(s) {', '.join(missing)}", field="--input")
    return np.array([[values[n] for n in system.input_names]])


def _read_csv(system: FuzzySystem, path: str) -> np.ndarray:
    text = validation.read_text(sys.stdin.buffer if path == "-" else path, source=path)
    header, table = validation.csv_table(text, path)
    missing = [n for n in system.input_names if n not in header]
    if missing:
        raise InputError(f"missing column(s) {', '.join(missing)} (header: {', '.join(header)})", source=path,
                         field="header")
    rows = []
    for line, row in table:
        short = [n for n in system.input_names if row[n] is None]
        if short:
            raise InputError(f"has no value for {', '.join(short)} (the row is shorter than the header)",
                             source=path, field=f"line {line}")
        try:
            rows.append([arguments.decimal(row[n]) for n in system.input_names])
        except (TypeError, ValueError) as error:
            raise InputError(f"{error} in {dict((n, row[n]) for n in system.input_names)}",
                             source=path, field=f"line {line}") from None
        if any(math.isnan(v) for v in rows[-1]):
            raise InputError(f"NaN input in {dict((n, row[n]) for n in system.input_names)}",
                             source=path, field=f"line {line}")
    if not rows:
        raise InputError("no data rows", source=path)
    return np.array(rows)


def training_report(name: str) -> str | None:
    """For a model file trained by fuzzy Q-learning: how it was trained and how many rules differ
    from the initial table (the model's ``training`` record); else ``None``."""
    document = read_model_or_none(name) if is_model_file(name) and Path(name).is_file() else None
    training = validation.mapping(document.get("training", {}), name, "training") if document is not None else {}
    if "rules_changed" not in training:
        return None
    rules = validation.integer(training.get("rules_learned", len(document.get("rules", []))), name,
                               "training.rules_learned", lo=0)
    changed = validation.integer(training["rules_changed"], name, "training.rules_changed", lo=0, hi=rules)
    protocol, prior = (validation.text(training.get(key, "?"), name, f"training.{key}", max_length=100, one_line=True)
                       for key in ("protocol", "prior"))  # printed: an ESC of an edited file reached the terminal
    if protocol == "parallel":
        robots = validation.integer(training.get("robots_per_batch"), name, "training.robots_per_batch", lo=1)
        protocol += f", {robots} robots per batch"
    return f"learned ({protocol} protocol, prior {prior}): {changed} of {rules} rules differ from the initial table"


def _show(args) -> int:
    print(describe(resolve(args.system)))
    report = training_report(args.system)
    if report:
        print(report)
    return 0


def _naming_the_system(action):
    """``action`` whose :class:`InputError` without a source (a term's formula giving inf, say)
    names the system or file it was asked of."""
    @functools.wraps(action)
    def named(args) -> int:
        try:
            return action(args)
        except InputError as error:
            if error.source:
                raise
            raise InputError(error.problem, source=args.system, field=error.field) from None
    return named


@_naming_the_system
def _eval(args) -> int:
    system = resolve(args.system)
    if args.csv:
        if args.input:
            raise InputError("give either --input or --csv", field="--csv")
        X = _read_csv(system, args.csv)
        Y = system.evaluate(X)
        system.check_finite(X, Y)
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        writer.writerow(system.input_names + system.output_names)
        for x, y in zip(X, Y):
            writer.writerow([repr(float(v)) for v in (*x, *y)])
        _write(buffer.getvalue(), args.output)
        return 0
    X = _parse_inputs(system, args.input or [])
    y = system.evaluate(X)
    system.check_finite(X, y)
    result = {name: float(v) for name, v in zip(system.output_names, y[0])}
    _write(json.dumps(result) + "\n", args.output)
    return 0


def _convert(args) -> int:
    if args.output and args.output != "-":
        if args.output.endswith(("/", "\\")) or Path(args.output).is_dir():
            raise InputError(f"{args.output} is a folder; give a file name", field="-o")
        try:
            said = format_of(args.output)
        except InputError:  # a suffix of no fuzzy format (e.g. .txt): the text goes there as asked
            said = args.to
        if said != args.to:
            raise InputError(f"the file's suffix says {said}, --to says {args.to}", field="-o")
    system = resolve(args.system)
    try:
        text = dumps(system, args.to)
    except InputError as error:  # what the format cannot hold: name the file that holds it
        raise InputError(error.problem, source=error.source or args.system, field=error.field) from None
    _write(text, args.output)
    return 0


def _export_c(args) -> int:
    from fuzzynav.fuzzy.export_c import to_c

    system = resolve(args.system)
    if isinstance(system, Engine):
        system = engine_to_system(system) or system
    source = Path(args.output)
    if source.suffix != ".c":
        raise InputError(f"the output is a .c file (its .h is written beside it), got {args.output!r}", field="-o")
    header_path = source.with_suffix(".h")
    header, code = to_c(system, name=args.name or source.stem, fixed=args.fixed, header_file=header_path.name)
    for path, text in ((header_path, header), (source, code)):
        write_text_atomic(path, text)
    print(f"wrote {source} and {header_path}")
    return 0


@_naming_the_system
def _plot(args) -> int:
    from fuzzynav.fuzzy.plot import plot_surface, plot_system

    if args.surface_output is not None and not args.surface:
        raise InputError("chooses the output --surface draws: give --surface too", field="--output-variable")
    system = resolve(args.system)
    if args.surface:
        if args.surface_output is not None and args.surface_output not in system.output_names:
            raise InputError(f"unknown output (one of {', '.join(system.output_names)})", field="--output-variable")
        try:
            fig = plot_surface(system, args.surface_output)
        except ValueError as error:
            raise InputError(str(error), field="--surface") from None
    else:
        fig = plot_system(system)
    savefig_atomic(fig, args.output, dpi=120)
    print(f"wrote {args.output}")
    return 0


def _write(text: str, output: str | None) -> None:
    if output and output != "-":
        write_text_atomic(output, text)
        print(f"wrote {output}", file=sys.stderr)
    else:
        sys.stdout.write(text)


def register(subparsers) -> None:
    parser = subparsers.add_parser("fis", help=help_line("fis"),
                                   description=__doc__.split("\n\n")[0],
                                   **arguments.with_example("fuzzynav fis show goal-seeking\nfuzzynav fis eval --help"))
    sub = parser.add_subparsers(dest="fis_command", metavar="ACTION", required=True)
    target = ("built-in name (" + ", ".join(SYSTEMS) + "), CONTROLLER:ROLE, a .json/.yaml/.fll/.fis file, or a model "
              "file of `fuzzynav train` holding a rule base (.json/.npz)")

    show = arguments.command(sub, "show", _show, help="variables, terms and rule table",
                             description="Print SYSTEM's inputs and outputs with their terms, then its rules (as "
                                         "a grid when two inputs' rules fill the table, as in the thesis).",
                             example="""
fuzzynav fis show goal-seeking               # Table IV.1 as a rule grid
fuzzynav fis show fuzzy-5b:foa
fuzzynav fis show gsb.fis""")
    show.add_argument("system", metavar="SYSTEM", help=target)

    ev = arguments.command(sub, "eval", _eval, help="evaluate for one input (--input) or a CSV table (--csv)",
                          description="Evaluate SYSTEM: the outputs for the --input values as one JSON object, or "
                                      "a --csv table's rows with their outputs as CSV (to stdout, or -o FILE).",
                          example="""
fuzzynav fis eval goal-seeking --input drg=5 --input theta=0.3
fuzzynav fis eval goal-seeking --csv inputs.csv -o outputs.csv""")
    ev.add_argument("system", metavar="SYSTEM", help=target)
    ev.add_argument("--input", action="append", metavar="NAME=VALUE", help="one input value (repeat per input)")
    ev.add_argument("--csv", metavar="IN.csv", type=arguments.file_name, help="CSV with one column per input ('-' = stdin; other columns, "
                    "an output's name included, are left out: the answer has the inputs' columns, then the outputs')")
    ev.add_argument("-o", "--output", metavar="FILE", type=arguments.file_name, help="write here instead of stdout")

    conv = arguments.command(sub, "convert", _convert, help="write the system as FLL, MATLAB .fis, JSON or YAML",
                            description="Write SYSTEM in another format: fuzzylite's FLL, MATLAB's .fis, JSON or "
                                        "YAML (to stdout, or -o FILE).",
                            example="""
fuzzynav fis convert tracking --to fll -o tracking.fll
fuzzynav fis convert fuzzy-5b-thesis:foa --to yaml -o foa.yaml""")
    conv.add_argument("system", metavar="SYSTEM", help=target)
    conv.add_argument("--to", choices=FORMATS, required=True, help="the format to write")
    conv.add_argument("-o", "--output", metavar="FILE", type=arguments.file_name, help="write here instead of stdout")

    plot = arguments.command(sub, "plot", _plot,
                             help="membership functions (Figs IV.5-IV.8) or control surface (Fig V.7)",
                             description="Draw the membership functions of SYSTEM's variables (Figs IV.5-IV.8), "
                                         "or with --surface the control surface of a two-input system (Fig V.7).",
                             example="""
fuzzynav fis plot goal-seeking -o terms.png
fuzzynav fis plot tracking --surface -o surface.png""")
    plot.add_argument("system", metavar="SYSTEM", help=target)
    plot.add_argument("--surface", action="store_true", help="control surface of a two-input system")
    plot.add_argument("--output-variable", dest="surface_output", metavar="NAME", help="the output --surface draws "
                      "(default: the first)")
    plot.add_argument("-o", "--output", required=True, metavar="FILE.png", type=arguments.figure_path,
                      help="the figure to write (PNG; any suffix matplotlib writes)")

    export = arguments.command(sub, "export-c", _export_c,
                               help="C99 evaluator of a TS0 / TS1 / Mamdani system (double or Q16.16)",
                               description="Write SYSTEM as a dependency-free C99 function (no heap): "
                                           "-o controller.c and controller.h beside it.",
                               example="fuzzynav fis export-c goal-seeking -o controller.c --fixed Q16.16")
    export.add_argument("system", metavar="SYSTEM", help=target)
    export.add_argument("-o", "--output", required=True, metavar="FILE.c", type=arguments.file_name,
                        help="the .c file (the .h goes beside it)")
    export.add_argument("--fixed", choices=FIXED_FORMATS, help="fixed-point arithmetic (default: double)")
    export.add_argument("--name", help="prefix of the C identifiers (default: the file's stem)")
