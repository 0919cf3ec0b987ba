"""One unit of campaign work, run in a worker: a world under one seed, with every controller
still to run on it. The world is drawn (or read) and its shortest path computed once, then each
controller runs one episode. Workers keep their imports, loaded model files and cached shortest
paths between cells (:data:`_MODELS`, :mod:`.measures`), so a cell costs little beyond its episodes.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from pathlib import Path

from fuzzynav.bench.measures import run_row, shortest_length
from fuzzynav.bench.suites import Suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.catalog.roles import ROLES, load_replacement, make_with_systems
from fuzzynav.robot.imperfections import perturbed
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.plants import DEFAULT_PLANT
from fuzzynav.world.scenario import Scenario

_MODELS: dict[str, object] = {}  # model file -> loaded controller (copied for every episode)
_SYSTEMS: dict[tuple, dict] = {}  # (controller, its (role, file) pairs) -> {role: replacement system}
MODEL_SUFFIXES = (".json", ".npz")


@dataclass(frozen=True)
class Cell:
    """World ``index`` of ``suite`` under ``seed``, to run with ``controllers`` ((label, spec)
    pairs: a registered name or a model file); ``radius`` is the simulated robot's; ``fis``
    ((role, file) pairs, ``--fis``) replaces that role's rule base in every controller that has it;
    ``perturb`` ((key, value) pairs, ``--perturb``) sets imperfections of the robot in the world;
    ``plant`` moves the robots (:mod:`fuzzynav.sim.plants`)."""

    suite: Suite
    index: int
    seed: int
    controllers: tuple[tuple[str, str], ...]
    radius: float
    cache_dir: str | None = None
    fis: tuple[tuple[str, str], ...] = ()
    perturb: tuple[tuple[str, float], ...] = ()
    plant: str = DEFAULT_PLANT


def perturb_scenario(scenario: Scenario, perturb) -> Scenario:
    """``scenario`` with the imperfections ``perturb`` ((key, value) pairs, keys written as in a
    scenario file: ``robot.actuation.latency``) set on top of its own."""
    imperfections = scenario.imperfections
    for name, value in perturb:
        imperfections = perturbed(imperfections, name, value)
    return replace(scenario, imperfections=imperfections) if perturb else scenario


def is_model_file(spec: str) -> bool:
    """True when a ``--controllers`` entry names a model file rather than a registered controller."""
    return spec.endswith(MODEL_SUFFIXES)


def build_controller(spec: str, fis: tuple[tuple[str, str], ...] = ()):
    """A fresh controller for ``spec`` (registered name, or model file loaded once per process),
    with the replacements ``fis`` ((role, file) pairs, read once per process) of the roles it has."""
    if not is_model_file(spec):
        mine = tuple((role, path) for role, path in fis if role in ROLES.get(spec, {}))
        if not mine:
            return make_controller(spec)
        if (spec, mine) not in _SYSTEMS:
            _SYSTEMS[(spec, mine)] = {role: load_replacement(spec, role, path) for role, path in mine}
        return make_with_systems(spec, _SYSTEMS[(spec, mine)])
    if spec not in _MODELS:
        from fuzzynav.catalog.tasks import load_controller

        _MODELS[spec] = load_controller(Path(spec))
    return copy.deepcopy(_MODELS[spec])


def run_cell(cell: Cell) -> list[dict]:
    """The rows (runs.csv fields, :mod:`.campaign`) of every controller of ``cell``."""
    scenario = perturb_scenario(cell.suite.scenario(cell.index, cell.seed), cell.perturb)
    shortest = shortest_length(scenario, cell.radius, cell.cache_dir)
    reference = cell.suite.reference(cell.index)
    rows = []
    for label, spec in cell.controllers:
        trace = run_episode(scenario, build_controller(spec, cell.fis), seed=cell.seed, plant=cell.plant)
        rows.append({"suite": cell.suite.name, "world": cell.suite.world_name(cell.index, cell.seed),
                     "seed": cell.seed, "controller": label,
                     **run_row(metrics(trace, scenario), shortest, reference)})
    return rows
