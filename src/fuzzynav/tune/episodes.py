"""Many candidate rule bases × many worlds in one compiled call: the episodes of a generation.

:class:`~fuzzynav.sim.simulator.BatchSimulator` steps N robots of one scenario under one
controller, one compiled call per step. A population of rule bases is N controllers on W
worlds, so :func:`run_jobs` loops the simulator's own compiled step
(:func:`fuzzynav.kernels.step.reset`, :func:`fuzzynav.kernels.step.step`) over every job
(candidate, world) inside compiled calls, a chunk of jobs each, spread over the process' threads
(:func:`fuzzynav.threads.spread`; the jobs share nothing, so the result does not depend on how
many) — the same arithmetic, step for step, as
``BatchSimulator(world, controller).run()`` (``tests/tune/test_episodes.py`` checks outcomes, step
counts and final poses against it). Each job is one robot with its own navigator state, hit
memory and layer state; the layers' obstacle-point slots are sized up front (:data:`SLOTS`), and
a job that would outgrow them stops with :data:`OVERFLOW` and is run again with twice the room.

Noisy sensors, moving targets and moving obstacles are simulated by the Python loop only; :class:`Worlds` refuses
them, and a world that sets the robot's imperfections (``sensor_noise``, ``actuation``, ``odometry``).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from fuzzynav import threads
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.systems_navigation import WALL_D_M, WALL_D_S
from fuzzynav.jit import jit
from fuzzynav.kernels import layers, step as step_kernel
from fuzzynav.kernels.motion import RADIUS
from fuzzynav.kernels.records import Layers, Navigator, Robots, StepNavigator, Traffic

OUTCOME, STEPS, CLEARANCE, PATH, REMAINING, START_DISTANCE, TOO_CLOSE, OFF_BAND = range(8)  # columns of ``out``
N_OUT = 8
OVERFLOW = -1  # outcome of a job whose layer state ran out of obstacle-point slots
INVALID = -2  # outcome of a job whose state became non-finite
SLOTS = 64  # obstacle-point slots per sensor ray (+ 1) given to each job at first (the layers start at 16)


class Population(NamedTuple):
    """The navigator a generation tunes: its candidates' rule bases, and its constants per world."""

    kind: int  # the navigator (a kernels.navigators code)
    params: np.ndarray  # (W, P) its constants, sized for each world's robot and ring
    tables: np.ndarray  # (C, T) each candidate's rule bases (kernels.ts0.pack)
    memory_steps: int  # steps of its hit memory (kernels.guard)


class Packed(NamedTuple):
    """W worlds end to end: world ``w`` is ``setups[setup_at[w]:setup_at[w + 1]]`` (its step set-up,
    :meth:`fuzzynav.sim.tasks.TaskState.setup`), ``scenes[scene_at[w]:scene_at[w + 1]]`` (its scene,
    :mod:`fuzzynav.kernels.scene`) and ``starts[w]``."""

    setups: np.ndarray
    setup_at: np.ndarray  # (W + 1,) offsets
    scenes: np.ndarray
    scene_at: np.ndarray  # (W + 1,) offsets
    starts: np.ndarray  # (W, 3) m, m, rad


@jit
def _one(navigator, memory_steps, layer, setup, scene, start, out):
    """Run one robot of ``navigator`` (:class:`~fuzzynav.kernels.records.Navigator`) with the
    layers ``layer`` (:class:`~fuzzynav.kernels.records.Layers`: parameters and a fresh state
    row) from ``start`` to the end of its episode; write its row of ``out``."""
    kind, params, tables = navigator.kind, navigator.params, navigator.tables
    n_rays = int(setup[step_kernel.N_ANGLES])
    state = np.zeros((1, len(step_kernel.STATE_FIELDS)))
    state[0, :3] = start
    ranges = np.zeros((1, n_rays))
    status = np.zeros((1, 3), dtype=np.int64)
    cstate = np.zeros((1, 4), dtype=np.int64)
    cstate[0, 0] = -1
    memory = np.zeros((1, memory_steps, n_rays + 1, 3))
    lp = layer.params.copy()
    lstate = np.empty((1, layer.state.shape[0]))
    lstate[0] = layer.state
    radius = setup[RADIUS]
    gx, gy = setup[step_kernel.GOAL_X], setup[step_kernel.GOAL_Y]
    out[START_DISTANCE] = math.hypot(gx - start[0], gy - start[1])
    still, no_offsets = np.zeros((0, 4), dtype=np.int64), np.zeros((0, 2))  # tuning worlds stand still
    running = step_kernel.reset(setup, scene, state, ranges, status, None)
    clearance = min(state[0, step_kernel.OBSTACLE_DISTANCE], state[0, step_kernel.BOUNDARY]) - radius
    path, k, too_close, off_band = 0.0, 0, 0, 0.0
    while running:
        x, y = state[0, step_kernel.X], state[0, step_kernel.Y]
        k += 1
        running = step_kernel.step(params, lp, StepNavigator(kind, tables, cstate, memory, lstate, lp), setup,
                                   Traffic(scene, still, no_offsets, scene), k, Robots(state, ranges, status, True), None)
        path += math.hypot(state[0, step_kernel.X] - x, state[0, step_kernel.Y] - y)
        gap = min(state[0, step_kernel.OBSTACLE_DISTANCE], state[0, step_kernel.BOUNDARY]) - radius
        clearance = min(clearance, gap)
        if gap < WALL_D_M:
            too_close += 1
        off_band += min(1.0, max(WALL_D_M - gap, gap - WALL_D_S, 0.0))
        if lp[layers.PARAM.grow] != 0.0:
            out[OUTCOME] = OVERFLOW
            return
        if not (math.isfinite(state[0, step_kernel.X]) and math.isfinite(state[0, step_kernel.Y])):
            out[OUTCOME] = INVALID
            return
    out[OUTCOME] = status[0, step_kernel.OUTCOME]
    out[STEPS] = status[0, step_kernel.STEPS]
    out[CLEARANCE] = clearance
    out[PATH] = path
    out[REMAINING] = math.hypot(gx - state[0, step_kernel.X], gy - state[0, step_kernel.Y])
    out[TOO_CLOSE] = too_close
    out[OFF_BAND] = off_band


@jit(nogil=True)
def run_jobs(population, layer, worlds, jobs, out):
    """Every job j = ``jobs[j]`` = (c, w): candidate c of ``population`` (:class:`Population`: its
    ``tables`` row c, its ``params`` row w) on world w of ``worlds`` (:class:`Packed`), with the
    layers ``layer`` (:class:`~fuzzynav.kernels.records.Layers`: parameters and a fresh state
    row); ``out`` (J, :data:`N_OUT`) = outcome code, steps, least clearance of the body (m), path
    length (m), distance left to the goal (m), start distance to the goal (m), and for wall
    following the steps whose body clearance is below d_m (eq VI.21's penalty) and the sum over
    the steps of how far (m, at most 1 per step) the clearance lies outside [d_m, d_s] (the
    thesis' wall distances, Fig VI.17)."""
    for j in range(jobs.shape[0]):
        c, w = jobs[j, 0], jobs[j, 1]
        _one(Navigator(population.kind, population.params[w], population.tables[c]), population.memory_steps,
             layer, worlds.setups[worlds.setup_at[w]:worlds.setup_at[w + 1]],
             worlds.scenes[worlds.scene_at[w]:worlds.scene_at[w + 1]], worlds.starts[w], out[j])


class Worlds:
    """The compiled form of a list of scenarios for one controller: per world its navigator
    parameters (sized for its robot and ring), set-up array, scene and start, concatenated."""

    def __init__(self, scenarios, controller):
        from fuzzynav.catalog.controllers import check_task
        from fuzzynav.sim.simulator import default_ring
        from fuzzynav.sim.tasks import TaskState

        self.scenarios = list(scenarios)
        if not self.scenarios:
            raise InputError("no worlds to tune on", field="--worlds")
        params, setups, scenes, self.dt, self.max_time = [], [], [], [], []
        tolerances = [scenario.goal.tolerance for scenario in self.scenarios if scenario.goal is not None]
        if tolerances and callable(getattr(controller, "for_goal", None)):  # one layer row for all: the tightest
            controller.for_goal(min(tolerances))
        for scenario in self.scenarios:
            where = scenario.source or scenario.name  # the file, for a folder's world
            ring = default_ring(scenario, controller)
            if ring.noise_std > 0:
                raise InputError("tuning simulates noise-free sensors only", source=where, field="sensors")
            if not scenario.imperfections.off:  # they were ignored: the perfect robot was tuned on, and measured
                from fuzzynav.robot.imperfections import describe

                raise InputError(f"tuning simulates the perfect robot; this world sets its imperfections "
                                 f"({describe(scenario.imperfections)})", source=where, field="robot")
            if scenario.task == "target":
                raise InputError("tuning runs goal and path tasks, not moving targets", source=where,
                                 field="task")
            try:
                check_task(controller.name, scenario.task, field="task")
            except InputError as error:  # e.g. a goal seeker on a path: it would time out on every world
                raise InputError(error.problem, source=where, field="task") from None
            if len(scenario.world.moving):
                raise InputError("tuning runs worlds whose obstacles stand still", source=where,
                                 field="obstacles")
            robot = scenario.robot
            controller.for_robot(robot)
            arguments = controller.compiled(1, ring.angles)
            params.append(np.array(arguments[1], dtype=float))
            max_steps = max(1, math.ceil(scenario.max_time / robot.dt - 1e-9))
            setups.append(TaskState(scenario, 1).setup(robot.array(), ring.max_range, max_steps, ring.angles, 0.0,
                                                       0.5 * ring.beam_width))
            scenes.append(np.asarray(scenario.world.scene, dtype=float))
            self.dt.append(robot.dt)
            self.max_time.append(scenario.max_time)
        self.kind = int(arguments[0])
        self.memory_steps = int(arguments[4].shape[1])
        self.layer_params = np.array(arguments[5], dtype=float)
        if len({len(p) for p in params}) != 1:
            raise InputError("the worlds' navigator parameters differ in size", field="--worlds")
        self.params = np.ascontiguousarray(params)
        starts = np.ascontiguousarray([scenario.start for scenario in self.scenarios], dtype=float)
        self.packed = Packed(*_concatenate(setups), *_concatenate(scenes), starts)
        self.n_rays = len(ring.angles)
        self.dt, self.max_time = np.asarray(self.dt), np.asarray(self.max_time)

    def __len__(self) -> int:
        return len(self.scenarios)

    def layer_row(self, slots: int) -> tuple[np.ndarray, np.ndarray]:
        """(layer params, a fresh layer state row) with ``slots`` obstacle-point slots per ray + 1."""
        params = self.layer_params.copy()
        if params[layers.PARAM.on] != 0.0:
            points = slots * (self.n_rays + 1)
            at = layers.PARAM
            params[[at.points_slots, at.cell_slots, at.grow]] = points, 1 << (2 * points - 1).bit_length(), 0
        return params, layers.fresh_state(1, params)[0]

    def run(self, tables: np.ndarray, jobs: np.ndarray) -> np.ndarray:
        """``out`` of :func:`run_jobs` for ``jobs`` (J, 2) = (row of ``tables``, world index);
        jobs that ran out of point slots are run again with twice as many, until none does."""
        tables = np.ascontiguousarray(tables, dtype=float)
        out = np.zeros((len(jobs), N_OUT))
        todo, slots = np.arange(len(jobs)), SLOTS
        while len(todo):
            part = self._spread(tables, np.ascontiguousarray(jobs[todo], dtype=np.int64), slots)
            out[todo] = part
            todo, slots = todo[part[:, OUTCOME] == OVERFLOW], 2 * slots
        return out

    def _spread(self, tables: np.ndarray, jobs: np.ndarray, slots: int) -> np.ndarray:
        """``out`` of :func:`run_jobs` for ``jobs`` with ``slots`` point slots, chunks of jobs on
        the process' threads."""
        layer_params, row = self.layer_row(slots)
        population, layer = Population(self.kind, self.params, tables, self.memory_steps), Layers(layer_params, row)
        out = np.zeros((len(jobs), N_OUT))

        def chunk(first: int, last: int) -> None:
            run_jobs(population, layer, self.packed, jobs[first:last], out[first:last])

        threads.spread(chunk, len(jobs))
        return out


def _concatenate(arrays) -> tuple[np.ndarray, np.ndarray]:
    """(the arrays end to end, their offsets (len + 1,))."""
    at = np.concatenate([[0], np.cumsum([len(a) for a in arrays])]).astype(np.int64)
    return np.ascontiguousarray(np.concatenate(arrays), dtype=float), at
