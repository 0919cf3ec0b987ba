"""One unit of campaign work, run in a worker: a world under one seed, with every controller
still to run on it. The world is drawn (or read) and its shortest path computed once, then each
controller runs one episode. Workers keep their imports, loaded model files and cached shortest
paths between cells (:data:`_MODELS`, :mod:`.measures`), so a cell costs little beyond its episodes.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from pathlib import Path

from fuzzynav import validation
from fuzzynav.bench.measures import run_row, shortest_length
from fuzzynav.bench.suites import Suite
from fuzzynav.catalog.roles import ROLES, load_replacement, make_with_systems
from fuzzynav.errors import InputError
from fuzzynav.robot.imperfections import perturbed
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.plants import DEFAULT_PLANT
from fuzzynav.storage import is_model_file
from fuzzynav.world.scenario import Scenario

_MAKERS: dict[tuple, controller_maker] = {}  # (spec, its (role, file) pairs) -> its maker, kept by the worker


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


class controller_maker:  # noqa: N801 (a factory of controllers, called like a function)
    """Fresh controllers, one a call, for an evaluation or a campaign: the registered
    ``controller`` (its roles' rule bases replaced by ``systems``, its factory given ``options``),
    or the controller stored in ``model`` (loaded once; each call a copy of it, so no episode
    inherits another's state; refused unless its kind drives goal tasks, as every evaluation and
    campaign world is one; so is a registered controller that cannot do them,
    :func:`~fuzzynav.catalog.controllers.check_task`). Exactly one of the two; ``name`` is the controller's."""

    def __init__(self, controller: str | None = None, *, model: str | Path | None = None,
                 systems: dict | None = None, options: dict | None = None):
        if (controller is None) == (model is None):
            raise InputError("give exactly one of a controller name and a model file", field="controller")
        if model is not None:
            from fuzzynav.catalog.tasks import load_controller

            self._loaded = load_controller(Path(model), "goal")
            self.name = self._loaded.name
        else:
            from fuzzynav.catalog.controllers import check_task

            check_task(validation.text(controller, field="controller", max_length=200), "goal", field="controller")
            self._loaded, self.name = None, str(controller)
        self._systems, self._options = systems or {}, options or {}

    def __call__(self):
        if self._loaded is not None:
            return copy.deepcopy(self._loaded)
        return make_with_systems(self.name, self._systems, **self._options)


def build_controller(spec: str, fis: tuple[tuple[str, str], ...] = ()):
    """A fresh controller for ``spec`` (registered name, or model file loaded once per process),
    with the replacements ``fis`` ((role, file) pairs, read once per process) of the roles it has."""
    mine = () if is_model_file(spec) else tuple((role, path) for role, path in fis if role in ROLES.get(spec, {}))
    if (spec, mine) not in _MAKERS:
        if is_model_file(spec):
            _MAKERS[(spec, mine)] = controller_maker(model=spec)
        else:
            systems = {role: load_replacement(spec, role, path) for role, path in mine}
            _MAKERS[(spec, mine)] = controller_maker(spec, systems=systems)
    return _MAKERS[(spec, mine)]()


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
