"""The episode loop: sense → act → clip → step → record, until done (docs/ARCHITECTURE.md, "Data flow of one run").

:class:`BatchSimulator` steps N robots of one scenario together, one compiled call per step
(:func:`fuzzynav.kernels.step.step`) over the robots still running — a large batch in row
blocks on the process' threads (:func:`fuzzynav.sim.blocks.step_in_blocks`). Each step:

1. act: a navigator with a compiled ``act`` (``controller.compiled(n, sensor_angles)``, the
   optional hooks of :mod:`fuzzynav.control.hooks`) decides inside that call; otherwise ``controller.act_batch(batch_obs)`` if the controller has it,
   returning ``(steering (N,), speed (N,))`` or ``(steering, speed, behaviours)``, or
   ``controller.act(obs)`` per robot (one deep copy of the controller per robot when N > 1);
2. clip the command to the robot's limits (path tasks: speed = the path's constant speed);
3. kinematic step (eq IV.2 or the exact arc) of the robots still running;
4. stop tests on the new state, in this order: collision (footprint disc vs obstacles and
   boundary), task done (goal within tolerance / last waypoint / target captured), max_time;
   a robot whose command is NaN or infinite is stopped before it moves, with the outcome
   ``"invalid_command"`` and the reason in its trace (:mod:`fuzzynav.sim.commands`);
5. sense: range rings, nearest obstacle (D_ro, θ_o), the task's target; the
   :class:`BatchObservation` is built when asked for.

Moving obstacles (:mod:`fuzzynav.sim.movers`) are placed at their step's offsets by the same
compiled call, before the robots move; a collision records who moved into whom (:mod:`fuzzynav.sim.fault`).
Steps 3–5 are the transition every stepping loop shares (:func:`fuzzynav.kernels.step.move`; the
training and Gymnasium environments step by it too, :class:`fuzzynav.world.fleet.Fleet`).

The plant (``plant``, :mod:`fuzzynav.sim.plants`) moves the robots and reads their sensors: the
kinematic model inside the compiled step by default; another plant (``mujoco``) gets the clipped
commands of step 2 and moves the robots, and its readings replace those of step 5.

Finished robots are not stepped, judged nor sensed. :class:`Simulator` is the one-robot case,
returning a :class:`Trace`; :func:`run_episode` is the one-call form.
The robot's parameters (size, wheelbase, limits, reverse speed) are the scenario's
(:attr:`Scenario.robot`) unless ``robot_params`` overrides them; they reach the compiled step
in its ``setup`` array, and Python controllers find them in ``observation.extras["robot"]``.
"""

from __future__ import annotations

import copy
import math

import numpy as np

from fuzzynav import validation
from fuzzynav.control.base import BatchObservation, Controller
from fuzzynav.control.hooks import CompiledAct, KnowsGoal, KnowsLatency, KnowsTraffic, MapAware, SizedForRobot
from fuzzynav.errors import InputError
from fuzzynav.kernels import imperfect, layers, step as step_kernel
from fuzzynav.kernels.records import Robots
from fuzzynav.kernels.step import COLLISION, REACHED, RUNNING, TIMEOUT
from fuzzynav.robot.imperfections import with_ring_noise
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import TricycleParams
from fuzzynav.sim import arguments, blocks
from fuzzynav.sim.arguments import default_ring
from fuzzynav.sim.commands import (
    INVALID_COMMAND,
    check_starts,
    controller_commands,
    invalid_reason,
    invalid_states,
)
from fuzzynav.sim.fault import collision_by
from fuzzynav.sim.movers import MovingObstacles
from fuzzynav.sim.plants import DEFAULT_PLANT, make_plant
from fuzzynav.sim.tasks import TaskState
from fuzzynav.sim.trace import Trace
from fuzzynav.world.columns import Column
from fuzzynav.world.limits import MAX_TIME, steps_see_collisions
from fuzzynav.world.scenario import Scenario

# a compiled navigator decides inside the compiled step: its commands are checked in the state
# every _CHECK_EVERY steps and at the end (each check costs about half a compiled step)
_CHECK_EVERY = 32
OUTCOME_NAMES = {REACHED: "reached", COLLISION: "collision", TIMEOUT: "timeout", INVALID_COMMAND: "invalid_command"}


class BatchSimulator:
    """N robots on one scenario, stepped together.

    ``starts`` are the start poses ``(N, 3)`` (default: ``n`` copies of the scenario start).
    ``controller`` is one controller (batch-capable, or copied per robot) or a sequence of N.
    ``seed`` seeds the sensor noise and the controllers' ``reset(rng)``. ``max_time`` overrides
    the scenario's. ``record=False`` keeps only outcomes (for benchmarks). ``plant`` names the
    plant (:data:`fuzzynav.sim.plants.PLANTS`; default ``kinematic``).
    """

    def __init__(self, scenario: Scenario, controller, *, n: int = 1, starts=None,
                 robot_params: TricycleParams | None = None, sensors: SensorRing | None = None,
                 seed: int | None = None, max_time: float | None = None, record: bool = True,
                 plant: str = DEFAULT_PLANT):
        self.scenario = arguments.check_scenario(scenario)
        self.starts = (check_starts(starts, scenario.world) if starts is not None
                       else np.tile(scenario.start, (arguments.check_robots(n), 1)))
        if starts is not None and n != 1 and n != len(self.starts):
            raise InputError(f"{n} robots, but {len(self.starts)} start poses: give one or the other", field="n")
        self.n = len(self.starts)
        listed = arguments.check_controllers(controller, self.n)
        robot_params, sensors = arguments.check_params(robot_params), arguments.check_sensors(sensors)
        seed = arguments.check_seed(seed)
        self.params = (arguments.check_robot(robot_params, "robot_params") if robot_params is not None
                       else arguments.check_robot(scenario.robot, "scenario.robot"))
        if robot_params is not None:  # the scenario's own robot was checked with it
            steps_see_collisions(scenario.world, robot_params, robot_params.radius)
        self.sensors = sensors if sensors is not None else default_ring(scenario, controller)
        self.max_time = validation.number(max_time if max_time is not None else scenario.max_time,
                                          field="max_time", lo=0.0, lo_open=True, hi=MAX_TIME)
        self.max_steps = max(1, math.ceil(self.max_time / self.params.dt - 1e-9))
        self.seed = seed
        self.record = record
        if listed is None:
            self.batch = callable(getattr(controller, "act_batch", None))
            copies = [controller] if self.batch or self.n == 1 else [copy.deepcopy(controller) for _ in range(self.n)]
        else:
            copies = arguments.check_controllers(listed, self.n)
            self.batch = False
        for copied in copies:  # map-aware controllers (``astar-pp``) are shown the map once
            if isinstance(copied, MapAware):
                copied.prepare(scenario)
        self.controllers = copies
        for each in copies:  # navigators sized for this robot (CompiledNavigator.for_robot)
            if isinstance(each, SizedForRobot):
                each.for_robot(self.params)
        self.controller_name = getattr(copies[0], "name", type(copies[0]).__name__)
        self.task = TaskState(scenario, self.n)
        self._setup = self.task.setup(self.params.array(), self.sensors.max_range, self.max_steps,
                                      self.sensors.angles, 0.0, 0.5 * self.sensors.beam_width)
        self.imperfections = with_ring_noise(scenario.imperfections, self.sensors.noise_std)
        for each in copies:  # told the robot's actuation latency (RobustNavigator.for_latency)
            if isinstance(each, KnowsLatency):
                each.for_latency(self.imperfections.latency)
            if isinstance(each, KnowsTraffic):  # told whether obstacles move (RobustNavigator.for_traffic)
                each.for_traffic(bool(scenario.world.moving))
            if isinstance(each, KnowsGoal):  # RobustNavigator.for_goal (no goal: no bound, whatever ran before)
                each.for_goal(scenario.goal.tolerance if scenario.goal is not None else math.inf)
        self._traffic = MovingObstacles(scenario.world, self.params.dt)
        self.plant = make_plant(plant, scenario, self.params, self.sensors, self.n)
        compiled = (len(copies) == 1 and self.batch and isinstance(copies[0], CompiledAct)
                    and getattr(copies[0], "in_step", True))  # False: a layer of it runs in Python now
        self._compiled = copies[0].compiled if compiled else None
        self.reset()

    # -- episode -----------------------------------------------------------------------------
    def reset(self) -> None:
        """Start poses, zero commands, task state at t = 0; controllers reset with seeded rngs."""
        seeds = np.random.SeedSequence(self.seed).spawn(2 + len(self.controllers))
        self.rng = np.random.default_rng(seeds[0])
        for controller, child in zip(self.controllers, seeds[1:-1]):
            reset = getattr(controller, "reset", None)  # optional for an object of one's own with act
            if callable(reset):
                reset(np.random.default_rng(child))
        self._imperfect = imperfect.record(self.imperfections, self.params.dt, self.n, seeds[-1])
        self._navigator = (self._compiled(self.n, self.sensors.angles) if self._compiled is not None
                           else step_kernel.idle_arguments())
        self._layer_params = self._navigator[-2]  # its GROW flag: a layer's arrays need room
        self.k = 0
        self._state = np.zeros((self.n, len(step_kernel.STATE_FIELDS)))
        self._state[:, :3] = self.starts
        self._ranges = np.zeros((self.n, self.sensors.count))
        self._status = np.zeros((self.n, 3), dtype=np.int64)
        self._moving_target = self.task.kind == "target"
        if self._moving_target:
            self._setup[step_kernel.GOAL_X:step_kernel.GOAL_Y + 1] = self.task.position(0.0)
        self._fault = np.full(self.n, "robot", dtype=object)
        self._invalid: list[str | None] = [None] * self.n  # why a robot stopped on a non-finite command
        self._traffic.reset()
        self._running = step_kernel.reset(self._setup, self._traffic.scene, self._state, self._ranges, self._status,
                                          self._imperfect)
        if not self.plant.in_kernel:
            self.plant.reset(self._state, self._ranges, self.active)
            if self._imperfect is not None:
                imperfect.plant_sense(self._imperfect, self._ranges, self.active, self.sensors.max_range)
        self._observation = None
        self._history = {key: [] for key in ("state", "ranges", "waypoint", "behaviour", "obstacles")}
        self._record_state()

    # views of the stepping core's arrays (copy to keep)
    pose = Column("_state", slice(step_kernel.X, step_kernel.THETA + 1),
                  "``(N, 3)`` current poses (a view: copy to keep).")
    steering = Column("_state", step_kernel.STEERING, "``(N,)`` steering applied at the last step (a view).")
    speed = Column("_state", step_kernel.SPEED, "``(N,)`` speed applied at the last step, 0 once finished (a view).")
    status = Column("_status", step_kernel.OUTCOME,
                    "``(N,)`` outcome codes: RUNNING, REACHED, COLLISION, TIMEOUT, INVALID_COMMAND.")
    steps = Column("_status", step_kernel.STEPS, "``(N,)`` steps each robot has taken.")

    @property
    def active(self) -> np.ndarray:
        """``(N,)`` bool: still running."""
        return self.status == RUNNING

    @property
    def done(self) -> bool:
        """Has every robot finished?"""
        return self._running == 0

    @property
    def observation(self) -> BatchObservation:
        """The :class:`BatchObservation` of the current state (built on first use)."""
        if self._observation is None:
            self._observation = self.sense()
        return self._observation

    def sense(self) -> BatchObservation:
        """A new :class:`BatchObservation` of the current state (its arrays are its own)."""
        state, t = self._state.copy(), self.k * self.params.dt
        if self._imperfect is not None:  # the controller's believed position
            state[:, step_kernel.X:step_kernel.Y + 1] += self._imperfect[1][:, imperfect.ERROR_X:imperfect.ERROR_Y + 1]
        return BatchObservation(
            t=t,
            dt=self.params.dt,
            pose=state[:, step_kernel.X:step_kernel.THETA + 1],
            speed=state[:, step_kernel.SPEED],
            steering=state[:, step_kernel.STEERING],
            target=state[:, step_kernel.TARGET_X:step_kernel.TARGET_Y + 1],
            ranges=self._ranges.copy(),
            sensor_angles=self.sensors.angles,
            max_range=self.sensors.max_range,
            obstacle_distance=state[:, step_kernel.OBSTACLE_DISTANCE],
            obstacle_bearing=state[:, step_kernel.OBSTACLE_BEARING],
            active=self.active,
            path=self.task.path,
            waypoint_index=self._status[:, step_kernel.WAYPOINT].copy(),
            target_velocity=self.task.target_velocity(t),
            extras={"task": self.task.kind, "robot": self.params},
        )

    def _act(self, obs: BatchObservation):
        """Commands of the Python controllers, written into the state of the running robots."""
        steering, speed, labels = controller_commands(self.controllers, self.batch, obs, self.controller_name, self.k)
        finite = np.isfinite(steering) & np.isfinite(speed)
        for i in np.flatnonzero(obs.active & ~finite):  # stopped before the command reaches the robot
            self._stop(int(i), self.k, invalid_reason(f"step {self.k}", steering[i], speed[i]))
        steering, speed = np.where(finite, steering, 0.0), np.where(finite, speed, 0.0)
        if self._running == self.n:
            self._state[:, step_kernel.STEERING], self._state[:, step_kernel.SPEED] = steering, speed
        else:
            running = obs.active
            for column, value in ((step_kernel.STEERING, steering), (step_kernel.SPEED, speed)):
                self._state[running, column] = np.broadcast_to(np.asarray(value, dtype=float), (self.n,))[running]
        return labels

    def step(self) -> None:
        """One step of every running robot (the new observation is :attr:`observation`)."""
        labels = None if self._compiled is not None else self._act(self.observation)
        moving = self._traffic.count
        if moving:
            before, offsets_before, running_before = self._state[:, :2].copy(), self._traffic.offsets(self.k), self._running
        if self._moving_target:
            self._setup[step_kernel.GOAL_X:step_kernel.GOAL_Y + 1] = self.task.position((self.k + 1) * self.params.dt)
        self.k += 1
        try:
            world = self._traffic.at(self.k)
            if self.plant.in_kernel:
                self._running = blocks.step_in_blocks(self._running, *step_kernel.lean_arguments(self._navigator),
                                                      self._setup, world, self.k,
                                                      Robots(self._state, self._ranges, self._status, True),
                                                      self._imperfect)
            else:
                self._plant_step(world)
        except ValueError as error:  # a compiled navigator refusing a non-finite input: stop who fed it
            live = np.flatnonzero(self.active)
            broken = [i for i in live if not np.isfinite(self._state[i, step_kernel.X:step_kernel.SPEED + 1]).all()]
            for i in broken or live:
                self._stop(int(i), int(self.steps[i]), f"step {self.k - 1}: {error}")
        self._observation = None
        if moving and self._running < running_before:  # someone stopped: a collision this step?
            hit = (self._status[:, step_kernel.OUTCOME] == COLLISION) & (self._status[:, step_kernel.STEPS] == self.k)
            if hit.any():
                self._fault[hit] = collision_by(self._state[hit], before[hit], world.offsets - offsets_before,
                                                self._traffic.mover_of_column, self.params.radius)
        if self._layer_params[layers.GROW]:  # the navigator makes room (the parameter array stays the same)
            self._navigator = self._compiled(self.n, self.sensors.angles)
        if self.record:
            self._history["behaviour"].append(labels)
            self._record_state()
        if self._compiled is not None and (self.k % _CHECK_EVERY == 0 or not self._running):
            found = invalid_states(self._state, self.k, self._history["state"] if self.record else None)
            for i, (steps, reason) in found.items():
                if self._invalid[i] is None:
                    self._stop(i, steps, reason)

    def _stop(self, i: int, steps: int, reason: str) -> None:
        """End robot ``i``'s episode after ``steps`` commands: its command was not finite (``reason``)."""
        self._status[i, step_kernel.OUTCOME], self._status[i, step_kernel.STEPS] = INVALID_COMMAND, steps
        self._invalid[i] = reason
        self._running = int(np.count_nonzero(self._status[:, step_kernel.OUTCOME] == RUNNING))

    def _plant_step(self, world) -> None:
        """The step of a plant outside the compiled step: act and clip (compiled), the plant
        moves the running robots, then the stop tests and sensing (compiled) and the plant's
        readings; the robot's imperfections around the plant (:mod:`fuzzynav.kernels.imperfect`)."""
        moved, real = self.active.copy(), self._imperfect
        step_kernel.step(*step_kernel.lean_arguments(self._navigator), self._setup, world, self.k,
                         Robots(self._state, self._ranges, self._status, False), real)
        if real is not None:
            imperfect.plant_commands(real, self.k, self._state, moved, self._setup, step_kernel.STEERING,
                                     step_kernel.SPEED)
        before = self._state[:, step_kernel.X:step_kernel.THETA + 1].copy()
        self.plant.move(self._state, moved)
        if real is not None:
            imperfect.plant_moved(real, before, self._state, moved)
        self._running = step_kernel.settle_moved(self._setup, world.scene, self.k, self._state, self._ranges,
                                                 self._status, moved, before)
        self.plant.sense(self._state, self._ranges, self.active)
        if real is not None:
            imperfect.plant_sense(real, self._ranges, self.active, self.sensors.max_range)

    def _record_state(self) -> None:
        if self.record:
            self._history["state"].append(self._state.copy())
            self._history["ranges"].append(self._ranges.copy())
            self._history["waypoint"].append(self._status[:, step_kernel.WAYPOINT].copy())
            self._history["obstacles"].append(self._traffic.offsets(self.k))

    def run(self) -> BatchSimulator:
        """Step until every robot has finished; returns ``self`` (see :meth:`outcomes`, :meth:`trace`)."""
        while not self.done:
            self.step()
        return self

    # -- results -----------------------------------------------------------------------------
    def outcomes(self) -> list[str]:
        """Outcome of each robot: ``"reached"``, ``"collision"``, ``"timeout"``, ``"invalid_command"``
        (or ``"running"``)."""
        return [OUTCOME_NAMES.get(int(s), "running") for s in self.status]

    def collisions_by(self) -> list[str | None]:
        """Who moved into whom in each robot's collision (:mod:`fuzzynav.sim.fault`): ``"robot"``,
        ``"obstacle"``, or ``None`` for a robot that did not collide."""
        return [str(by) if s == COLLISION else None for s, by in zip(self.status, self._fault)]

    def invalid_commands(self) -> list[str | None]:
        """Why each robot stopped on a non-finite command (``"step 3: steering nan, speed 1.0"``), or None."""
        return list(self._invalid)

    def trace(self, i: int = 0) -> Trace:
        """The :class:`Trace` of robot ``i`` (needs ``record=True``)."""
        if not self.record:
            raise RuntimeError("trace() needs a simulator built with record=True")
        if isinstance(i, bool) or not isinstance(i, (int, np.integer)) or not 0 <= i < self.n:
            raise IndexError(f"trace(): robot must be a whole number from 0 to {self.n - 1}, got {i!r}")
        k = int(self.steps[i])
        states = np.array([s[i] for s in self._history["state"][: k + 1]]).reshape(k + 1, -1)
        commands = states[1:]
        if self._compiled is not None:
            behaviour = np.asarray(self.controllers[0].labels)[commands[:, step_kernel.BEHAVIOUR].astype(int)]
        else:
            behaviour = np.array([b[i] for b in self._history["behaviour"][:k]], dtype=str)
        return Trace(
            scenario=self.scenario.name,
            controller=self.controller_name,
            task=self.task.kind,
            dt=self.params.dt,
            t=np.arange(k + 1) * self.params.dt,
            pose=states[:, step_kernel.X:step_kernel.THETA + 1],
            ranges=np.array([r[i] for r in self._history["ranges"][: k + 1]]),
            target=states[:, step_kernel.TARGET_X:step_kernel.TARGET_Y + 1],
            waypoint_index=np.array([w[i] for w in self._history["waypoint"][: k + 1]], dtype=int),
            steering=commands[:, step_kernel.STEERING],
            speed=commands[:, step_kernel.SPEED],
            behaviour=behaviour.astype(str),
            sensor_angles=self.sensors.angles,
            max_range=self.sensors.max_range,
            outcome=self.outcomes()[i],
            robot_radius=self.params.radius,
            collision_by=self.collisions_by()[i],
            invalid_command=self._invalid[i],
            obstacle_offsets=(np.array(self._history["obstacles"][: k + 1]) if self._traffic.count else None),
        )


class Simulator:
    """One robot, one episode: ``Simulator(scenario, controller, ...).run() -> Trace``."""

    def __init__(self, scenario: Scenario, controller: Controller, *, robot_params: TricycleParams | None = None,
                 sensors: SensorRing | None = None, seed: int | None = None, max_time: float | None = None, start=None,
                 plant: str = DEFAULT_PLANT):
        if start is not None and np.ndim(np.asarray(start, dtype=object)) > 1:
            raise InputError("one robot takes one start pose (x, y, θ); BatchSimulator runs several", field="start")
        self._batch = BatchSimulator(scenario, controller, starts=start, robot_params=robot_params,
                                     sensors=sensors, seed=seed, max_time=max_time, plant=plant)

    def run(self) -> Trace:
        """Reset and run the episode to its end; returns its :class:`Trace`."""
        self._batch.reset()
        return self._batch.run().trace(0)


def run_episode(scenario: Scenario, controller: Controller, *, robot_params: TricycleParams | None = None,
                sensors: SensorRing | None = None, seed: int | None = None, max_time: float | None = None,
                start=None, plant: str = DEFAULT_PLANT) -> Trace:
    """One episode of ``controller`` on ``scenario``, to its end (:class:`Simulator`): its :class:`Trace`.

    :param robot_params: the robot's limits (default: the scenario's robot)
    :param sensors: the range ring (default: the scenario's ``sensors``, else the controller's)
    :param seed: seeds the sensor noise and the controller's random draws
    :param max_time: simulated seconds before a timeout (default: the scenario's ``max_time``)
    :param start: a start pose (x, y, θ) in place of the scenario's
    :param plant: what moves the robot, ``kinematic`` (the thesis' model) or ``mujoco``"""
    return Simulator(scenario, controller, robot_params=robot_params, sensors=sensors, seed=seed, max_time=max_time,
                     start=start, plant=plant).run()
