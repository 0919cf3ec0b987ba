"""A campaign folder read back: every file is user input, validated as such.

A ``--resume`` reads ``runs.jsonl`` and ``fis.json`` from a folder anyone may have edited. Each
row of ``runs.jsonl`` must be a JSON object with every column (:data:`~fuzzynav.bench.campaign.COLUMNS`)
of the right type — names strings, ``seed`` an integer, ``outcome`` one of
:data:`OUTCOMES`, the measures finite numbers (times, lengths and efforts ≥ 0) or null — and
be one of the campaign's own runs (its suite, world, seed and controller in the plan). Anything
else is an :class:`~fuzzynav.errors.InputError` naming the file, the line and the field: a
tampered row is never kept in the final files, never silently dropped. Only the last line may be
cut (an interruption while it was written): it is dropped, as the run is simply made again.
"""

from __future__ import annotations

from pathlib import Path

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.sim.plants import PLANTS
from fuzzynav.sim.trace import OUTCOMES

NAMES = ("suite", "world", "controller")
# measure -> lowest value (None: any finite number)
MEASURES = {"time_s": 0.0, "path_length_m": 0.0, "shortest_path_m": 0.0, "path_ratio": 0.0,
            "min_clearance_m": None, "steering_effort_rad": 0.0, "steering_variation_rad": 0.0,
            "final_distance_m": 0.0, "barn_score": 0.0,
            "barn_score_challenge": 0.0}


def check_row(row, columns, source: str, where: str) -> dict:
    """One stored run, its fields checked (module docstring)."""
    validation.known_keys(row, columns, source, where, required=columns)
    for name in NAMES:
        validation.text(row[name], source, f"{where}.{name}", max_length=10_000, allow_empty=False)
    validation.integer(row["seed"], source, f"{where}.seed", lo=0, hi=validation.MAX_SEEDS - 1)
    validation.choice(row["outcome"], OUTCOMES, source, f"{where}.outcome")
    for name, lo in MEASURES.items():
        if row[name] is not None:
            if lo is None:
                validation.number(row[name], source, f"{where}.{name}")
            else:
                validation.number(row[name], source, f"{where}.{name}", lo=lo)
    return row


def read_runs(out: Path, columns, plan_keys=None) -> list[dict]:
    """The rows of ``out/runs.jsonl`` (module docstring); ``plan_keys``: the (suite, world, seed,
    controller) keys of the campaign, a row outside them is refused."""
    file = out / "runs.jsonl"
    if not file.is_file():
        return []
    source = str(file)
    text = validation.read_text(file, max_bytes=validation.MAX_MODEL_BYTES * 16)
    lines = text.split("\n")
    rows = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        where = f"line {number}"
        try:
            row = validation.parse_json(line, source)
        except InputError as error:
            if not error.problem.startswith("invalid JSON"):  # JSON past a limit (nesting, size)
                raise InputError(error.problem, source=source, field=where) from None
            if number == len(lines):  # the last line, not ended by a newline: cut by an interruption
                continue
            raise InputError("not a JSON object (a campaign file edited by hand? choose another --out)",
                             source=source, field=where) from None
        check_row(row, columns, source, where)
        run = (row["suite"], row["world"], row["seed"], row["controller"])
        if plan_keys is not None and run not in plan_keys:
            raise InputError(f"run {run} is not one of this campaign's (its suites, seeds and controllers): resume "
                             "with the same arguments, or choose another --out", source=source, field=where)
        rows.append(row)
    return rows


def json_mapping(path: Path) -> dict:
    """The JSON object in the file ``path``, read as user input (an InputError names the file)."""
    source = str(path)
    return validation.mapping(validation.parse_json(validation.read_text(path), source), source)


def read_replacements(path: Path) -> dict:
    """``fis.json``: {role: {"file": text, "sha256": 64 hex digits}}."""
    source = str(path)
    record = json_mapping(path)
    for role, item in record.items():
        validation.known_keys(item, ("file", "sha256"), source, role, required=("file", "sha256"))
        validation.text(item["file"], source, f"{role}.file")
        _checked_sha256(item["sha256"], source, f"{role}.sha256")
    return record


def read_inputs(path: Path) -> dict:
    """``inputs.json``: {"models": {label: sha256}, "worlds": {file: sha256}}, 64 hex digits each."""
    source = str(path)
    record = json_mapping(path)
    validation.known_keys(record, ("models", "worlds"), source, None, required=("models", "worlds"))
    for part in ("models", "worlds"):
        for name, digest in validation.mapping(record[part], source, part).items():
            _checked_sha256(digest, source, f"{part}.{name}")
    return record


def _checked_sha256(value, source: str, field: str) -> str:
    digest = validation.text(value, source, field)
    if len(digest) != 64 or any(c not in "0123456789abcdef" for c in digest):
        raise InputError("must be 64 lowercase hexadecimal digits", source=source, field=field)
    return digest


def read_perturbations(path: Path) -> dict:
    """``perturb.json``: {key: value}, each a known imperfection key with a value in its range."""
    from fuzzynav.robot.imperfections import NONE, perturbed

    source = str(path)
    record = json_mapping(path)
    for name, value in record.items():
        perturbed(NONE, name, value, source)
    return record


def read_plant(path: Path) -> str:
    """``plant.json``: {"plant": name}, the name one of :data:`fuzzynav.sim.plants.PLANTS`."""
    source = str(path)
    record = json_mapping(path)
    validation.known_keys(record, ("plant",), source, required=("plant",))
    name = validation.text(record["plant"], source, "plant")
    if name not in PLANTS:
        raise InputError(f"unknown plant {name!r} (known: {', '.join(PLANTS)})", source=source, field="plant")
    return name
