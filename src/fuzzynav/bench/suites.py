"""What ``fuzzynav bench SUITE…`` runs on: folders of scenario files and generated families.

A SUITE argument is either

- a folder: every scenario file in it (``*.yaml``, ``*.yml``, any case), in name order (``world_10`` after ``world_9``:
  numbers sort as numbers); a ``benchmark.json`` beside them (written by ``fuzzynav import
  barn``) adds per-scenario reference data, e.g. BARN's optimal path length for its score;
- ``FAMILY[:COUNT[:SEED]]`` with FAMILY one of :data:`fuzzynav.world.generate.KINDS` (COUNT
  default 100, SEED default 0): the solvable worlds of :func:`~fuzzynav.world.generate.generate_world`.

With ``--seeds K``, seed k ∈ 0…K−1 of a generated family draws its own worlds (world seed
SEED + k) and runs them with episode seed k; a folder's worlds are fixed and run with episode
seed k (which only matters for noisy sensors or random controllers).
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field
from pathlib import Path

from fuzzynav import validation
from fuzzynav.bench.stored import json_mapping
from fuzzynav.errors import InputError
from fuzzynav.world.generate import KINDS, family_reference, generate_world
from fuzzynav.world.scenario import Scenario, load_scenario

DEFAULT_COUNT = 100
REFERENCE_FILE = "benchmark.json"
SCENARIO_SUFFIXES = (".yaml", ".yml")  # a folder's scenario files, in any case (a.YAML too), as `run` reads them


def _natural(path: Path):
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", path.stem)]


@dataclass(frozen=True)
class Suite:
    """A named list of worlds: ``files`` (a folder suite) or ``family``/``count``/``seed``."""

    name: str
    family: str | None = None
    count: int = 0
    seed: int = 0
    files: tuple[str, ...] = ()
    references: dict = field(default_factory=dict, hash=False, compare=False)

    @property
    def size(self) -> int:
        return len(self.files) if self.family is None else self.count

    def world_name(self, index: int, seed: int) -> str:
        """The identifier of world ``index`` under run seed ``seed`` (a column of runs.csv)."""
        if self.family is None:
            return Path(self.files[index]).stem
        return f"{self.family}-{self.seed + seed}-{index:03d}"

    def scenario(self, index: int, seed: int) -> Scenario:
        """The scenario of world ``index`` under run seed ``seed``."""
        if self.family is None:
            return load_scenario(self.files[index])
        return generate_world(self.family, self.seed + seed, index)

    def reference(self, index: int) -> dict:
        """Reference data of world ``index``: its family's (:func:`~fuzzynav.world.generate.family_reference`)
        or its entry in ``benchmark.json`` (empty when there is none)."""
        if self.family is not None:
            return family_reference(self.family)
        return self.references.get(Path(self.files[index]).stem, {})


def _count(text: str, field_name: str, spec: str, lo: int, hi: int) -> int:
    if not re.fullmatch(r"\d{1,30}", text, re.ASCII) or not lo <= int(text) <= hi:
        raise InputError(f"{field_name} must be a whole number from {lo} to {hi:,} in {validation.shown(spec)}",
                         field="SUITE")
    return int(text)


def read_references(file: Path) -> dict:
    """The ``scenarios`` of a folder's ``benchmark.json``: per world a mapping, its
    ``barn_optimal_path_m`` (if any) a number > 0 (read as user input: InputError naming the entry)."""
    source = str(file)
    document = json_mapping(file)
    references = validation.mapping(document.get("scenarios", {}), source, "scenarios")
    for name, entry in references.items():
        validation.mapping(entry, source, f"scenarios.{name}")
        if "barn_optimal_path_m" in entry:
            validation.number(entry["barn_optimal_path_m"], source, f"scenarios.{name}.barn_optimal_path_m",
                              lo=0.0, lo_open=True)
        if "barn_challenge_path_m" in entry:  # the challenge's own value, which may be wrong (negative)
            validation.number(entry["barn_challenge_path_m"], source, f"scenarios.{name}.barn_challenge_path_m")
    return references


def parse_suite(spec: str) -> Suite:
    """The :class:`Suite` a SUITE argument names (module docstring); InputError otherwise."""
    if not spec.strip():  # Path("") is the current folder: never read it unasked
        raise InputError("is empty: name a family (mixed:40) or a folder of scenario files (. for the current one)",
                         field="SUITE")
    path = Path(spec)
    if path.is_dir():
        files = sorted((f for f in path.iterdir() if f.suffix.lower() in SCENARIO_SUFFIXES), key=_natural)
        if not files:
            raise InputError("folder has no scenario files (*.yaml, *.yml)", source=spec, field="SUITE")
        stems = [f.stem.lower() for f in files]  # a world is named by its file's stem
        twice = sorted({f.name for f in files if stems.count(f.stem.lower()) > 1})
        if twice:
            raise InputError(f"{', '.join(twice)} would be one world (a world is named by its file name without "
                             "the suffix): rename one", source=spec, field="SUITE")
        for label in (path.resolve().name, *(f.stem for f in files)):  # they name the runs, the table, the plots
            validation.text(label, None, "SUITE", one_line=True)
        references = read_references(path / REFERENCE_FILE) if (path / REFERENCE_FILE).is_file() else {}
        return Suite(name=path.resolve().name, files=tuple(str(f) for f in files), references=references)
    family, *rest = spec.split(":")
    if family not in KINDS:
        close = difflib.get_close_matches(family, KINDS, n=3)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        raise InputError(f"{spec!r} is neither a folder nor a world family ({', '.join(KINDS)}) "
                         f"written FAMILY[:COUNT[:SEED]]{hint}; `fuzzynav import barn` writes a folder of BARN "
                         "worlds, `fuzzynav worlds generate` one of a family's", field="SUITE")
    if len(rest) > 2:
        raise InputError(f"too many ':' in {spec!r} (FAMILY[:COUNT[:SEED]])", field="SUITE")
    count = _count(rest[0], "COUNT", spec, 1, validation.MAX_WORLDS) if rest else DEFAULT_COUNT
    seed = _count(rest[1], "SEED", spec, 0, validation.MAX_SEED) if len(rest) > 1 else 0
    return Suite(name=f"{family}:{count}:{seed}", family=family, count=count, seed=seed)
