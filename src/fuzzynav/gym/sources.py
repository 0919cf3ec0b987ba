"""Where an episode happens: each reset draws one :class:`~fuzzynav.world.scenario.Scenario`.

A source has ``draw(rng) -> Scenario`` (world, start pose, and a goal or a path) and takes all
its randomness from ``rng``, the environment's ``np_random``, so ``reset(seed=…)`` replays the
same episode.

- :class:`LayoutSource` — the chapter VI training layouts of :mod:`fuzzynav.learn.envs.layouts`
  (random starts and goals in the empty workspace, a new random obstacle world or wall course
  per episode);
- :class:`FamilySource` — a numbered pool of the generated world families of
  :mod:`fuzzynav.world.generate` (``circles``, ``mixed``): world i depends only on
  ``(family, world_seed, i)``, so another ``world_seed`` is a held-out set;
- :class:`ScenarioSource` — scenario files or built-in scenarios by name, with their own start
  and task (one of them drawn uniformly when several are given);
- :class:`RandomPaths` — random polylines to track in the empty workspace.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.learn.envs.layouts import EMPTY, RandomGoal, RandomObstacles, WallCourse
from fuzzynav.robot.imperfections import describe
from fuzzynav.sim.paths import path_scenario
from fuzzynav.world.generate import KINDS, check_kind, random_world
from fuzzynav.world.scenario import DEFAULT_GOAL_TOLERANCE, ROBOT_KEYS, ROBOT_UNITS, Goal, Scenario, load_scenario

LAYOUTS = {"random-goal": RandomGoal, "random-obstacles": RandomObstacles, "wall-course": WallCourse}


@dataclass
class LayoutSource:
    """One episode of a chapter VI layout (``random-goal``, ``random-obstacles``, ``wall-course``)."""

    name: str

    def __post_init__(self):
        if self.name not in LAYOUTS:
            family = str(self.name).partition(":")[0]
            hint = (f"; a family's size and seed are the n_worlds and world_seed arguments (worlds={family!r})"
                    if family in KINDS else "")
            raise InputError(f"unknown layout or family {self.name!r} (layouts: {', '.join(LAYOUTS)}, random-paths; "
                             f"families: {', '.join(KINDS)}){hint}", field="worlds")
        self.layout = LAYOUTS[self.name]()

    def draw(self, rng) -> Scenario:
        world, pose, target = self.layout.sample(rng, 1)
        goal = None if target is None else Goal(np.asarray(target[0], dtype=float), DEFAULT_GOAL_TOLERANCE)
        return Scenario(name=self.name, world=world, start=np.asarray(pose[0], dtype=float), goal=goal,
                        max_time=float("inf"))


@dataclass
class FamilySource:
    """World ``i`` of ``n_worlds`` of a generated family, i uniform; worlds built on first use."""

    family: str
    n_worlds: int = 1000
    world_seed: int = 0
    _cache: dict = field(default_factory=dict, repr=False)

    def __post_init__(self):
        check_kind(self.family, "worlds")
        if int(self.n_worlds) < 1:
            raise InputError(f"must be >= 1, got {self.n_worlds!r}", field="n_worlds")
        # world i from child i, as fuzzynav.world.generate.generate_worlds: the same worlds by index
        self._children = np.random.SeedSequence([int(self.world_seed), KINDS.index(self.family)]).spawn(
            int(self.n_worlds))

    def world(self, i: int) -> Scenario:
        """World ``i`` of the pool (the same as ``generate_worlds(family, n, world_seed)[i]``)."""
        if i not in self._cache:
            self._cache[i] = random_world(self.family, np.random.default_rng(self._children[i]),
                                          name=f"{self.family}-{self.world_seed}-{i:03d}")
        return self._cache[i]

    def draw(self, rng) -> Scenario:
        return self.world(int(rng.integers(len(self._children))))


@dataclass
class ScenarioSource:
    """Given scenarios (file paths, built-in names or :class:`Scenario` objects), one drawn per episode."""

    scenarios: tuple

    def __post_init__(self):
        items = self.scenarios if isinstance(self.scenarios, (list, tuple)) else (self.scenarios,)
        if not items:
            raise InputError("needs at least one scenario", field="scenario")
        self.scenarios = tuple(s if isinstance(s, Scenario) else load_scenario(s) for s in items)

    def draw(self, rng) -> Scenario:
        if len(self.scenarios) == 1:
            return self.scenarios[0]
        return self.scenarios[int(rng.integers(len(self.scenarios)))]


@dataclass
class RandomPaths:
    """A random polyline of 3–5 waypoints, 3–7 m legs turning by at most 120°, inside the
    workspace's [3, 17] m square, tracked at ``speed`` (the chapter V trackers' 1 m/s)."""

    speed: float = 1.0

    def draw(self, rng) -> Scenario:
        while True:
            n = int(rng.integers(3, 6))
            heading = rng.uniform(-np.pi, np.pi)
            points = [rng.uniform(5.0, 15.0, 2)]
            for k in range(n - 1):
                if k:
                    heading += rng.uniform(-2 * np.pi / 3, 2 * np.pi / 3)
                points.append(points[-1] + rng.uniform(3.0, 7.0) * np.array([np.cos(heading), np.sin(heading)]))
            points = np.array(points)
            if (points >= 3.0).all() and (points <= 17.0).all():  # one shared empty world: one batched call
                return replace(path_scenario(points.round(3), name="random-path", speed=self.speed), world=EMPTY)


def make_source(task: str, scenario=None, worlds: str | None = None, n_worlds: int = 1000, world_seed: int = 0):
    """The source of an environment: ``scenario`` if given, else the family or layout ``worlds``,
    else the task's default (random goals; random obstacle worlds; wall courses; random paths)."""
    if scenario is not None:
        if worlds is not None:
            raise InputError("give either scenario or worlds, not both", field="scenario")
        return ScenarioSource(scenario)
    if worlds is None:
        return RandomPaths() if task == "path" else LayoutSource(
            {"goal": "random-goal", "avoid": "random-obstacles", "wall": "wall-course"}[task])
    if worlds in KINDS:
        return FamilySource(worlds, n_worlds, world_seed)
    if worlds == "random-paths":
        return RandomPaths()
    return LayoutSource(worlds)


def check_task(task, source_scenario: Scenario) -> None:
    """A path task needs a path scenario and a goal task a goal (InputError otherwise)."""
    kind = source_scenario.task
    wanted = "path" if task.name == "path" else "goal" if task.goal else None
    if wanted is not None and kind != wanted:
        raise InputError(f"the {task.name} task needs a scenario with a {wanted}, "
                         f"{source_scenario.name!r} has a {kind} task", field="scenario")


def check_robot(params, scenario: Scenario) -> None:
    """The environments drive their own robot (``params``) with exact actuation and read the
    thesis' noise-free sensors: a scenario that says otherwise is refused (InputError), not run
    with what it says ignored."""
    other = [f"{key} {getattr(scenario.robot, key):g} {ROBOT_UNITS[key]}" for key in ROBOT_KEYS
             if getattr(scenario.robot, key) != getattr(params, key)]
    if other:
        raise InputError(f"{scenario.name!r} has a robot of its own ({', '.join(other)}), not the environment's "
                         "params: pass params=scenario.robot (of fuzzynav.load_scenario), or leave the robot's "
                         "keys out of the scenario", source=scenario.source, field="scenario")
    if not scenario.imperfections.off:
        raise InputError(f"{scenario.name!r} sets the robot's imperfections ({describe(scenario.imperfections)}): "
                         "the Gymnasium environments read noise-free sensors and drive exact actuation",
                         source=scenario.source, field="scenario")
    if scenario.sensors not in (None, "thesis"):
        raise InputError(f"{scenario.name!r} names the {scenario.sensors} sensor ring: the Gymnasium environments "
                         "read the thesis' 7 rays", source=scenario.source, field="scenario")
