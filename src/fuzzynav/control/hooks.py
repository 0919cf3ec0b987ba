"""The optional hooks of a controller: what the simulator looks for beyond ``act`` / ``act_batch``.

A controller (:class:`~fuzzynav.control.base.Controller`) needs only ``act`` (or, as every
controller of the package, ``act_batch``: :class:`~fuzzynav.control.base.BatchController`) and,
if it keeps state, ``reset(rng)``. The simulator (:class:`fuzzynav.sim.simulator.BatchSimulator`)
also uses each of these protocols a controller implements — checked with ``isinstance``, so a
controller implements one by defining its member, without deriving from it:

- :class:`MapAware` — ``prepare(scenario)``: shown the whole scenario (obstacles included) once
  before its episodes; a controller doing so is a map-aware reference, not a sensor-based
  navigator (``astar-pp``), and its spec says ``needs_map=True``;
- :class:`SizedForRobot` — ``for_robot(params)``: told the robot's size and limits
  (:class:`~fuzzynav.robot.tricycle.TricycleParams`) before the episodes, to size its clearances;
- :class:`KnowsLatency` — ``for_latency(seconds)``: told the robot's actuation latency (the
  scenario's ``robot.actuation.latency``, 0 without one; on a real robot, the figure its
  configuration gives) before the episodes, to decide for the pose where its commands will act
  (the default ``fuzzy-5b``, :mod:`fuzzynav.kernels.latency`);
- :class:`KnowsTraffic` — ``for_traffic(moving)``: told whether the scenario's obstacles move
  (its ``motion`` keys), to forget where they were (the default ``fuzzy-5b``,
  :mod:`fuzzynav.kernels.clearing`);
- :class:`KnowsGoal` — ``for_goal(tolerance)``: told how near the goal counts as reached (a
  goal task's ``goal.tolerance``), so that what it plans to stop at lies inside it (the default
  ``fuzzy-5b``'s car route, :meth:`~fuzzynav.control.robust.RobustNavigator.for_goal`);
- :class:`BringsSensors` — ``sensors``: the sensor ring it reads by default
  (:class:`~fuzzynav.robot.sensors.SensorRing`, ``None``: the thesis' seven rays); a scenario's
  ``sensors`` key, or ``--sensors``, overrides it;
- :class:`CompiledAct` — ``compiled(n, sensor_angles)``: the arguments of its decision inside
  the compiled step (:func:`fuzzynav.kernels.step.step`) for ``n`` robots, so that sensing,
  deciding and stepping are one compiled call (the thesis navigators,
  :class:`~fuzzynav.control.batched.CompiledNavigator`); one whose ``in_step`` is False once told
  the scenario (the default ``fuzzy-5b`` among moving obstacles, whose yield layer is Python) is
  called through ``act_batch`` instead;
- :class:`HasRoles` — ``roles``: the names of its replaceable rule bases in the order it reads
  them; its factory then takes ``systems={role: FuzzySystem}`` (``--fis ROLE=FILE``) and its spec
  lists the same roles (:mod:`fuzzynav.catalog.roles`).
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable


@runtime_checkable
class MapAware(Protocol):
    def prepare(self, scenario) -> None:
        """Read ``scenario`` (a :class:`~fuzzynav.world.scenario.Scenario`) before the episodes."""


@runtime_checkable
class SizedForRobot(Protocol):
    def for_robot(self, params) -> None:
        """Size what depends on the robot (its radius, wheelbase, limits) for ``params``."""


@runtime_checkable
class KnowsLatency(Protocol):
    def for_latency(self, latency: float) -> object:
        """Compensate an actuation latency of ``latency`` seconds (0: none)."""


@runtime_checkable
class KnowsTraffic(Protocol):
    def for_traffic(self, moving: bool) -> object:
        """Told whether the scenario has moving obstacles."""


@runtime_checkable
class KnowsGoal(Protocol):
    def for_goal(self, tolerance: float) -> object:
        """Told the goal's tolerance (m)."""


@runtime_checkable
class BringsSensors(Protocol):
    sensors: object  # a SensorRing, or None for the thesis' seven rays


@runtime_checkable
class CompiledAct(Protocol):
    def compiled(self, n: int, sensor_angles) -> tuple:
        """The navigator arguments of :func:`fuzzynav.kernels.step.step` for ``n`` robots."""


@runtime_checkable
class HasRoles(Protocol):
    roles: tuple[str, ...]
