"""The episode loop: sense → act → clip → step → record, until done (DESIGN.md, issue 3).

:class:`BatchSimulator` steps N robots of one scenario together, NumPy-vectorised: sensing
(rays of all robots against all obstacles in one call), kinematics and task logic. Each step:

1. sense: range rings, nearest obstacle (D_ro, θ_o), the task's target → :class:`BatchObservation`;
2. act: ``controller.act_batch(batch_obs)`` if the controller has it, returning
   ``(steering (N,), speed (N,))`` or ``(steering, speed, behaviours)``; otherwise
   ``controller.act(obs)`` per robot (one deep copy of the controller per robot when N > 1);
3. clip the command to the robot's limits (path tasks: speed = the path's constant speed);
4. kinematic step (eq IV.2 or the exact arc) of the robots still running;
5. stop tests on the new state, in this order: collision (footprint disc vs obstacles and
   boundary), task done (goal within tolerance / last waypoint / target captured), max_time.

:class:`Simulator` is the one-robot case, returning a :class:`Trace`; :func:`run_episode` is
the one-call form. The robot's parameters (size, wheelbase, limits) are the scenario's
(:attr:`Scenario.robot`) unless ``robot_params`` overrides them; controllers find them in
``observation.extras["robot"]``.
"""

from __future__ import annotations

import copy
import math

import numpy as np

from fuzzynav.control.base import Controller
from fuzzynav.robot import tricycle
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import TricycleParams
from fuzzynav.sim.observation import BatchObservation
from fuzzynav.sim.tasks import TaskState
from fuzzynav.sim.trace import Trace
from fuzzynav.world.geometry import wrap_angle
from fuzzynav.world.scenario import Scenario

RUNNING, REACHED, COLLISION, TIMEOUT = 0, 1, 2, 3
OUTCOME_NAMES = {REACHED: "reached", COLLISION: "collision", TIMEOUT: "timeout"}


class BatchSimulator:
    """N robots on one scenario, stepped together.

    ``starts`` are the start poses ``(N, 3)`` (default: ``n`` copies of the scenario start).
    ``controller`` is one controller (batch-capable, or copied per robot) or a sequence of N.
    ``seed`` seeds the sensor noise and the controllers' ``reset(rng)``. ``max_time`` overrides
    the scenario's. ``record=False`` keeps only outcomes (for benchmarks).
    """

    def __init__(self, scenario: Scenario, controller, *, n: int = 1, starts=None,
                 robot_params: TricycleParams | None = None, sensors: SensorRing | None = None,
                 seed: int | None = None, max_time: float | None = None, record: bool = True):
        self.scenario = scenario
        self.params = robot_params if robot_params is not None else scenario.robot
        self.sensors = sensors if sensors is not None else SensorRing()
        self.starts = (np.asarray(starts, dtype=float).reshape(-1, 3) if starts is not None
                       else np.tile(scenario.start, (n, 1)))
        self.n = len(self.starts)
        self.max_time = float(max_time if max_time is not None else scenario.max_time)
        self.max_steps = max(1, math.ceil(self.max_time / self.params.dt - 1e-9))
        self.seed = seed
        self.record = record
        if hasattr(controller, "act") or hasattr(controller, "act_batch"):
            self.batch = callable(getattr(controller, "act_batch", None))
            copies = [controller] if self.batch or self.n == 1 else [copy.deepcopy(controller) for _ in range(self.n)]
        else:
            copies = list(controller)
            if len(copies) != self.n:
                raise ValueError(f"{len(copies)} controllers for {self.n} robots")
            self.batch = False
        self.controllers = copies
        self.controller_name = getattr(copies[0], "name", type(copies[0]).__name__)
        self.reset()

    # -- episode -----------------------------------------------------------------------------
    def reset(self) -> None:
        """Start poses, zero commands, task state at t = 0; controllers reset with seeded rngs."""
        seeds = np.random.SeedSequence(self.seed).spawn(1 + len(self.controllers))
        self.rng = np.random.default_rng(seeds[0])
        for controller, child in zip(self.controllers, seeds[1:]):
            controller.reset(np.random.default_rng(child))
        self.k = 0
        self.pose = self.starts.copy()
        self.steering = np.zeros(self.n)
        self.speed = np.zeros(self.n)
        self.task = TaskState(self.scenario, self.n)
        self._goal = np.array(self.task.target()) if self.task.kind == "goal" else None  # fixed target
        self.status = np.full(self.n, RUNNING)
        self._all_running = True  # no robot has finished: the masks of step() can be skipped
        self.steps = np.zeros(self.n, dtype=int)
        self._proximity = self.scenario.world.proximity(self.pose[:, :2])
        self._judge(active=np.ones(self.n, dtype=bool))
        self.observation = self.sense()
        self._history = {key: [] for key in ("pose", "ranges", "target", "waypoint", "steering", "speed", "behaviour")}
        self._record_state()

    @property
    def active(self) -> np.ndarray:
        return self.status == RUNNING

    @property
    def done(self) -> bool:
        return not self._all_running and not self.active.any()

    def sense(self) -> BatchObservation:
        """The :class:`BatchObservation` of the current state."""
        ranges = self.sensors.read(self.scenario.world, self.pose, self.rng)
        distance, nearest, _, _ = self._proximity
        if self.n == 1:  # θ_o of one robot with floats (NumPy's per-call cost would dominate)
            (px, py), (x, y, theta) = nearest[0].tolist(), self.pose[0].tolist()
            finite = math.isfinite(distance[0])
            bearing = np.array([wrap_angle(float(np.arctan2(py - y, px - x)) - theta) if finite else 0.0])
        else:
            rel = nearest - self.pose[:, :2]
            bearing = np.where(np.isfinite(distance), wrap_angle(np.arctan2(rel[:, 1], rel[:, 0]) - self.pose[:, 2]), 0.0)
        active = self.active
        return BatchObservation(
            t=self.k * self.params.dt,
            dt=self.params.dt,
            pose=self.pose,
            speed=self.speed,
            steering=self.steering,
            target=self._goal.copy() if self._goal is not None else np.array(self.task.target()),
            ranges=ranges,
            sensor_angles=self.sensors.angles,
            max_range=self.sensors.max_range,
            obstacle_distance=distance,
            obstacle_bearing=bearing,
            active=active,
            path=self.task.path,
            waypoint_index=self.task.waypoint_index.copy(),
            target_velocity=self.task.target_velocity(),
            extras={"task": self.task.kind, "robot": self.params},
        )

    def _act(self, obs: BatchObservation):
        if self.batch:
            out = self.controllers[0].act_batch(obs)
            steering, speed = np.asarray(out[0], dtype=float), np.asarray(out[1], dtype=float)
            labels = list(out[2]) if len(out) > 2 else [""] * self.n
            return steering, speed, labels
        steering, speed, labels = np.zeros(self.n), np.zeros(self.n), [""] * self.n
        for i in np.flatnonzero(obs.active):
            command = self.controllers[0 if self.n == 1 else i].act(obs.single(i))
            steering[i], speed[i], labels[i] = command.steering, command.speed, command.behaviour
        return steering, speed, labels

    def step(self) -> BatchObservation:
        """One step of every running robot; returns the new observation."""
        active = self.active
        steering, speed, labels = self._act(self.observation)
        steering, speed = self.params.clip(steering, speed)  # new arrays, never the controller's
        if self.task.forced_speed is not None:
            speed = np.full(self.n, self.task.forced_speed)
        if self._all_running and steering.shape == speed.shape == (self.n,):
            self.steering, self.speed = steering, speed  # nothing to mask
            self.pose = tricycle.step(self.pose, steering, speed, self.params)
        else:
            self.steering = np.where(active, steering, self.steering)
            self.speed = np.where(active, speed, 0.0)
            moved = tricycle.step(self.pose, self.steering, self.speed, self.params)
            self.pose = np.where(active[:, None], moved, self.pose)
        self.k += 1
        self.steps += active
        self._proximity = self.scenario.world.proximity(self.pose[:, :2])
        self._judge(active)
        self.observation = self.sense()
        if self.record:
            self._history["steering"].append(self.steering.copy())
            self._history["speed"].append(self.speed.copy())
            self._history["behaviour"].append(labels)
            self._record_state()
        return self.observation

    def _judge(self, active: np.ndarray) -> None:
        """Stop tests on the current state for the robots in ``active`` (collision first)."""
        distance, _, _, boundary = self._proximity
        collided = np.minimum(distance, boundary) < self.params.radius
        done = self.task.update(self.pose[:, :2], self.k * self.params.dt, active)
        if self._all_running and self.k < self.max_steps and not (collided | done).any():
            return  # every robot runs on
        status = np.where(collided, COLLISION, np.where(done, REACHED, RUNNING))
        if self.k >= self.max_steps:
            status = np.where(status == RUNNING, TIMEOUT, status)
        self.status = np.where(active, status, self.status)
        self._all_running = not self.status.any()  # RUNNING is 0

    def _record_state(self) -> None:
        if self.record:
            self._history["pose"].append(self.pose.copy())
            self._history["ranges"].append(self.observation.ranges)
            self._history["target"].append(self.observation.target)
            self._history["waypoint"].append(self.task.waypoint_index.copy())

    def run(self) -> "BatchSimulator":
        """Step until every robot has finished; returns ``self`` (see :meth:`outcomes`, :meth:`trace`)."""
        while not self.done:
            self.step()
        return self

    # -- results -----------------------------------------------------------------------------
    def outcomes(self) -> list[str]:
        """Outcome of each robot: ``"reached"``, ``"collision"``, ``"timeout"`` (or ``"running"``)."""
        return [OUTCOME_NAMES.get(int(s), "running") for s in self.status]

    def trace(self, i: int = 0) -> Trace:
        """The :class:`Trace` of robot ``i`` (needs ``record=True``)."""
        if not self.record:
            raise RuntimeError("trace() needs a simulator built with record=True")
        k = int(self.steps[i])
        h = self._history
        return Trace(
            scenario=self.scenario.name,
            controller=self.controller_name,
            task=self.task.kind,
            dt=self.params.dt,
            t=np.arange(k + 1) * self.params.dt,
            pose=np.array([p[i] for p in h["pose"][: k + 1]]),
            ranges=np.array([r[i] for r in h["ranges"][: k + 1]]),
            target=np.array([g[i] for g in h["target"][: k + 1]]),
            waypoint_index=np.array([w[i] for w in h["waypoint"][: k + 1]], dtype=int),
            steering=np.array([s[i] for s in h["steering"][:k]]),
            speed=np.array([v[i] for v in h["speed"][:k]]),
            behaviour=np.array([b[i] for b in h["behaviour"][:k]], dtype=str),
            sensor_angles=self.sensors.angles,
            max_range=self.sensors.max_range,
            outcome=self.outcomes()[i],
            robot_radius=self.params.radius,
        )


class Simulator:
    """One robot, one episode: ``Simulator(scenario, controller, ...).run() -> Trace``."""

    def __init__(self, scenario: Scenario, controller: Controller, *,
                 robot_params: TricycleParams | None = None, sensors: SensorRing | None = None,
                 seed: int | None = None, max_time: float | None = None, start=None):
        self._batch = BatchSimulator(scenario, controller, starts=start, robot_params=robot_params,
                                     sensors=sensors, seed=seed, max_time=max_time)

    def run(self) -> Trace:
        """Reset and run the episode to its end; returns its :class:`Trace`."""
        self._batch.reset()
        return self._batch.run().trace(0)


def run_episode(scenario: Scenario, controller: Controller, **options) -> Trace:
    """``Simulator(scenario, controller, **options).run()``."""
    return Simulator(scenario, controller, **options).run()
