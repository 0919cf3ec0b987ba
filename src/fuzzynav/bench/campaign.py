"""A campaign: suites × controllers × seeds, written as it runs, resumable, in a fixed final order.

Files in the output folder:

- ``runs.jsonl`` and ``runs.csv``: one row per run (:data:`COLUMNS`), appended as each cell
  finishes. An interrupted campaign restarted with ``--resume`` reads ``runs.jsonl`` (a line cut
  by the interruption is dropped; every other row validated and required to be one of the
  plan's, :mod:`.stored`), skips the runs already there and runs the rest; a folder that
  already holds runs is not overwritten without ``--resume``. One campaign writes a folder at a
  time (:mod:`.lock`).
- At the end both files are rewritten in the campaign's order (suites as given, then seed,
  world, controller as given), so they are byte-identical whatever the backend, the number of
  workers, or where an interruption fell; then the reports (:mod:`.report`).
- ``cache/shortest/``: the shortest path of each world (:mod:`.measures`).
- ``fis.json``: the rule-base replacements (``--fis``: role, file, SHA-256 of its content); a
  ``--resume`` with other replacements (or none where there were some) is refused.
- ``perturb.json``: the robot's imperfections set in every world (``--perturb KEY=VALUE``,
  :mod:`fuzzynav.robot.imperfections`); a ``--resume`` with others is refused likewise.
- ``plant.json``: the plant that moved the robots (``--plant``, :mod:`fuzzynav.sim.plants`); a
  ``--resume`` with another plant is refused.
- ``inputs.json``: the SHA-256 of every file the runs read under a name that may stay while the
  content changes — the model files of ``--controllers`` (by label), the scenario files of
  folder suites and each folder's reference data (by suite and file name, as the runs name their
  worlds); a ``--resume`` after one of them changed is refused, naming it.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import sys
from dataclasses import dataclass
from pathlib import Path

from fuzzynav import validation
from fuzzynav.bench import stored
from fuzzynav.bench.backends import execute
from fuzzynav.bench.cells import Cell
from fuzzynav.bench.lock import campaign_lock
from fuzzynav.bench.suites import REFERENCE_FILE, Suite
from fuzzynav.errors import InputError
from fuzzynav.progress import bar as progress_bar, quiet as quiet_progress
from fuzzynav.sim.plants import DEFAULT_PLANT
from fuzzynav.storage import is_model_file, remove_temporaries_under, write_text_atomic

# the tables and reports a campaign writes after runs.jsonl (module docstring, :mod:`.report`)
WRITTEN = ("runs.csv", "summary.json", "summary.md", "index.html", "rates.png", "path_ratio.png")
COLUMNS = ("suite", "world", "seed", "controller", "outcome", "time_s", "path_length_m", "shortest_path_m",
           "path_ratio", "min_clearance_m", "steering_effort_rad", "steering_variation_rad", "final_distance_m",
           "barn_score", "barn_score_challenge", "collision_by")


@dataclass(frozen=True)
class Plan:
    """What to run: ``suites``, ``controllers`` ((label, spec) pairs), ``seeds`` (count), robot
    ``radius``, ``fis``: (role, file) rule-base replacements (``--fis``), ``perturb``: (key,
    value) imperfections set in every world (``--perturb``), and the ``plant``."""

    suites: tuple[Suite, ...]
    controllers: tuple[tuple[str, str], ...]
    seeds: int
    radius: float
    fis: tuple[tuple[str, str], ...] = ()
    perturb: tuple[tuple[str, float], ...] = ()
    plant: str = DEFAULT_PLANT

    def __post_init__(self):
        validation.count(self.seeds, field="--seeds", hi=validation.MAX_SEEDS)
        for suite in self.suites:  # seed k runs the family's worlds of seed SEED + k, which must stay a seed
            if suite.family is not None and suite.seed + self.seeds - 1 > validation.MAX_SEED:
                raise InputError(f"{suite.name} with {self.seeds} seeds would run worlds of seed up to "
                                 f"{suite.seed + self.seeds - 1}, above {validation.MAX_SEED:,}: lower its SEED",
                                 field="SUITE")
        runs = sum(suite.size for suite in self.suites) * self.seeds * len(self.controllers)
        if runs > validation.MAX_CAMPAIGN_RUNS:
            raise InputError(f"{runs:,} runs (worlds x seeds x controllers), more than the "
                             f"{validation.MAX_CAMPAIGN_RUNS:,} of one campaign: split it over several --out folders",
                             field="SUITE")

    def order(self) -> dict[tuple, int]:
        """Position of every run key (suite, world, seed, controller) in the final files."""
        keys = {}
        for suite in self.suites:
            for seed in range(self.seeds):
                for index in range(suite.size):
                    world = suite.world_name(index, seed)
                    for label, _ in self.controllers:
                        keys[(suite.name, world, seed, label)] = len(keys)
        return keys

    def cells(self, done: set, cache_dir: str | None) -> list[Cell]:
        """The cells with at least one run not in ``done``, each with its missing controllers only."""
        cells = []
        for suite in self.suites:
            for seed in range(self.seeds):
                for index in range(suite.size):
                    world = suite.world_name(index, seed)
                    todo = tuple((label, spec) for label, spec in self.controllers
                                 if (suite.name, world, seed, label) not in done)
                    if todo:
                        cells.append(Cell(suite, index, seed, todo, self.radius, cache_dir, self.fis, self.perturb,
                                          self.plant))
        return cells


def key(row: dict) -> tuple:
    return (row["suite"], row["world"], int(row["seed"]), row["controller"])


def _csv_value(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    return str(value)


def csv_lines(rows) -> str:
    """The CSV text of ``rows`` (no header), one line each, ``\\n`` line ends."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    for row in rows:
        writer.writerow([_csv_value(row.get(column)) for column in COLUMNS])
    return buffer.getvalue()


def json_lines(rows) -> str:
    return "".join(json.dumps({column: row.get(column) for column in COLUMNS}) + "\n" for row in rows)


def read_runs(out: Path, plan: Plan | None = None) -> list[dict]:
    """The rows of ``out/runs.jsonl``, validated (:func:`.stored.read_runs`; a cut last line is
    dropped); with ``plan``, a row that is not one of its runs is refused."""
    return stored.read_runs(out, COLUMNS, None if plan is None else plan.order())


def _write_all(out: Path, rows: list[dict]) -> None:
    write_text_atomic(out / "runs.jsonl", json_lines(rows))
    write_text_atomic(out / "runs.csv", ",".join(COLUMNS) + "\n" + csv_lines(rows))


def _describe(record: dict) -> str:
    return ", ".join(f"--fis {role}={item['file']} (sha256 {item['sha256'][:12]})" for role, item in record.items()) \
        or "no --fis"


def _file_sha256(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _keep(out: Path, name: str, record, resuming: bool, read, absent, conflict) -> None:
    """Write a campaign's setting ``record`` to ``out/name``; resuming, first refuse it where the
    runs already made had another: ``conflict(before)`` (``before`` read by ``read``, or
    ``absent`` where the file is missing) gives the problem and the option at fault, or None.
    Runs made otherwise cannot be mixed."""
    path = out / name
    problem = conflict(read(path) if path.exists() else absent) if resuming else None
    if problem:
        raise InputError(problem[0], source=str(out), field=problem[1])
    write_text_atomic(path, json.dumps(record, indent=1) + "\n")


def _mixed(before: str, now: str, what: str, option: str) -> tuple[str, str]:
    return (f"its runs were made with {before}, this campaign {now}: runs of different {what} cannot be mixed "
            f"(resume with the same {option}, or choose another --out)", option)


def _keep_settings(out: Path, plan: Plan, resuming: bool) -> None:
    """Record the campaign's settings beside its runs (module docstring: ``fis.json``,
    ``perturb.json``, ``plant.json``, ``inputs.json``); a ``--resume`` whose settings differ from
    those of the runs already made is refused, naming the option, or the files changed since."""
    fis = {role: {"file": path, "sha256": _file_sha256(path)} for role, path in plan.fis}

    def other_fis(before):
        same = {role: item["sha256"] for role, item in before.items()} == {r: v["sha256"] for r, v in fis.items()}
        return None if same else _mixed(_describe(before), f"gives {_describe(fis)}", "rule bases", "--fis")
    _keep(out, "fis.json", fis, resuming, stored.read_replacements, {}, other_fis)
    perturb = dict(plan.perturb)
    _keep(out, "perturb.json", perturb, resuming, stored.read_perturbations, {}, lambda before: None if before == perturb
          else _mixed(f"--perturb {before or 'none'}", f"gives {perturb or 'none'}", "robots", "--perturb"))
    _keep(out, "plant.json", {"plant": plan.plant}, resuming, stored.read_plant, DEFAULT_PLANT, lambda before: None
          if before == plan.plant else _mixed(f"the {before} plant", f"asks for {plan.plant}", "plants", "--plant"))
    inputs = {"models": {label: _file_sha256(spec) for label, spec in plan.controllers if is_model_file(spec)},
              "worlds": _world_digests(plan.suites)}

    def changed(before):  # a folder written before inputs.json has nothing to compare
        names = [name for part in ("models", "worlds") for name in sorted(before[part].keys() & inputs[part].keys())
                 if before[part][name] != inputs[part][name]] if before else []
        return (f"changed since its runs were made: {', '.join(names)}; runs of different files cannot be mixed "
                "(restore them, or choose another --out)", "--resume") if names else None
    _keep(out, "inputs.json", inputs, resuming, stored.read_inputs, None, changed)


def _world_digests(suites) -> dict[str, str]:
    """The SHA-256 of every scenario file of the folder suites, and of each folder's reference data
    (``benchmark.json`` as read; none is ``{}``), keyed as the runs know them — suite name and file
    name (``w/a.yaml``, ``w/benchmark.json``) — not by the path as typed, so that the same folder
    spelled another way, or another folder of the same name, is compared with the record too."""
    digests = {}
    for suite in suites:
        if suite.family is not None:
            continue
        for file in suite.files:
            digests[f"{suite.name}/{Path(file).name}"] = _file_sha256(file)
        reference = json.dumps(suite.references, sort_keys=True).encode()
        digests[f"{suite.name}/{REFERENCE_FILE}"] = hashlib.sha256(reference).hexdigest()
    return digests


def _not_anothers(out: Path) -> None:
    """Refuse a folder that holds files of the names a campaign writes but no ``runs.jsonl``: not a
    campaign's folder, and the campaign would overwrite them (a user's ``index.html`` was lost)."""
    if (out / "runs.jsonl").exists():
        return
    theirs = [name for name in WRITTEN if (out / name).exists()] + sorted(p.name for p in out.glob("failures-*.png"))
    if theirs:
        raise InputError(f"holds {', '.join(theirs)} but no runs.jsonl: it is not a campaign's folder, and a campaign "
                         "would overwrite them; choose another --out", source=str(out), field="--out")


def check_tasks(plan: Plan) -> None:
    """Refuse, before anything runs, a world whose task a controller of ``plan`` cannot do: a
    campaign runs goal tasks (every generated world is one), and a scenario file of a folder
    suite says its own task. The :class:`InputError` names the first such file and controller
    (:func:`fuzzynav.catalog.controllers.check_task`'s message)."""
    from fuzzynav.catalog.controllers import check_task

    for suite in plan.suites:
        worlds = [(suite.name, "goal")] if suite.family is not None else \
            [(file, suite.scenario(index, 0).task) for index, file in enumerate(suite.files)]
        for source, task in worlds:
            for label, spec in plan.controllers:
                try:
                    if not is_model_file(spec):
                        check_task(spec, task, field="--controllers")
                    elif task != "goal":
                        raise InputError(f"model file {label} cannot do a {task} task (a campaign runs model "
                                         "files on goal tasks)")
                except InputError as error:
                    note = "" if task == "goal" else ("; but a campaign runs goal tasks only: leave this file out of "
                                                      "the folder (`fuzzynav run FILE --controller NAME` runs it)")
                    raise InputError(error.problem + note, source=source, field="--controllers") from None


def run_campaign(plan: Plan, out: Path, *, resume: bool = False, backend: str = "local", workers: int = 1,
                 address: str | None = None, progress: bool = True) -> list[dict]:
    """Run ``plan`` into ``out`` (module docstring); returns every row in the final order. A world
    of a task one of its controllers cannot do is refused first (:func:`check_tasks`)."""
    check_tasks(plan)
    _not_anothers(out)  # before the lock's file is made in someone else's folder
    with campaign_lock(out):
        return _run(plan, out, resume, backend, workers, address, progress)


def _run(plan: Plan, out: Path, resume: bool, backend: str, workers: int, address: str | None,
         progress: bool) -> list[dict]:
    previous = read_runs(out, plan if resume else None)
    if resume:  # under the campaign's lock: a temporary file here is a killed run's (plots included)
        remove_temporaries_under(out)
    if previous and not resume:
        held = f"{len(previous)} runs: add --resume to continue them" if len(previous) != 1 else \
            "1 run: add --resume to continue it"
        raise InputError(f"already holds {held}, or choose another --out", source=str(out), field="--out")
    _keep_settings(out, plan, bool(previous))
    rows = {key(row): row for row in previous}
    _write_all(out, list(rows.values()))  # drop a line cut by an interruption
    cells = plan.cells(set(rows), str(out / "cache"))
    total = sum(len(cell.controllers) for cell in cells)
    if resume:
        print(f"--resume: {len(rows)} run{'s' * (len(rows) != 1)} already in {out}, {total} to run", file=sys.stderr)
    with quiet_progress(not progress or not total):  # a bar only on a terminal, as every command's
        bar = progress_bar(total=total, unit="run")
    with open(out / "runs.jsonl", "a", encoding="utf-8") as jsonl, open(out / "runs.csv", "a", encoding="utf-8") as table:
        def on_rows(new_rows):
            jsonl.write(json_lines(new_rows))
            table.write(csv_lines(new_rows))
            jsonl.flush()
            table.flush()
            for row in new_rows:
                rows[key(row)] = json.loads(json.dumps(row))  # the stored form, as a resume reads it
            bar.update(len(new_rows))

        try:
            execute(cells, on_rows, backend=backend, workers=workers, address=address)
        finally:
            bar.close()
    order = plan.order()
    final = sorted(rows.values(), key=lambda row: (order.get(key(row), len(order)), key(row)))
    _write_all(out, final)
    return final
