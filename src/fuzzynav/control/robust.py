"""The default chapter IV navigators, ``fuzzy-5b`` and ``fuzzy-2b``: the thesis' navigators with
a supervisor layer that never lets them freeze, sized to the scenario's robot.

:class:`RobustNavigator` wraps a thesis navigator (:mod:`fuzzynav.control.five_behaviours`,
:mod:`fuzzynav.control.avoidance`) through the :class:`Controller` interface and adds two
behaviours to its supervisor:

- **recovery** (:mod:`fuzzynav.control.recovery`): when the navigator's safety stop has held the
  robot for ``stop_wait`` seconds away from the goal, the robot backs out on an arc and turns the
  other way (``REC-BACK``, ``REC-TURN``), then the navigator drives again;
- **loop escape** (:mod:`fuzzynav.control.escape`): when the robot circles without getting
  nearer the goal, the navigator follows the boundary of what traps it towards a virtual goal
  beside it (``BF``) until the goal is nearer than where following began and its direction is
  free (the Bug algorithms' rule).

The thesis navigator runs every step (its hit memory and behaviour switch stay current); a
layer in charge replaces its command. The labels in the trace are the navigator's, or
``REC-BACK``, ``REC-TURN``, ``BF``.

**The robot's size and limits** (the scenario's ``robot:`` keys) reach the navigators through
their compiled parameter vector: the simulator calls :meth:`CompiledNavigator.for_robot
<fuzzynav.control.batched.CompiledNavigator.for_robot>` with its robot, which sets the wheelbase
(the anti-orbit guard of goal seeking, the full-lock turn radius), the body radius (turning room
and safety stop) and the top speed; the layers read the robot from ``extras["robot"]``. With the
default robot nothing changes, so the ``-thesis`` variants (:func:`fuzzy_5b_thesis`,
:func:`fuzzy_2b_thesis`, the compiled navigators without layers) drive exactly as published.
"""

from __future__ import annotations

from dataclasses import replace

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.escape import BoundaryFollowing, LoopDetector
from fuzzynav.control.recovery import ObstacleMemory, Recovery
from fuzzynav.robot.tricycle import DEFAULT_PARAMS


class RobustNavigator(Controller):
    """A thesis navigator (a :class:`~fuzzynav.control.batched.CompiledNavigator`) with the
    recovery and loop-escape layers (either can be switched off: ``recovery=False``,
    ``escape=False``); ``systems`` of the navigator are its rule bases by role."""

    def __init__(self, navigator, name: str, *, recovery: bool = True, escape: bool = True,
                 stop_wait: float = 1.0):
        self.navigator, self.name = navigator, name
        self.recovery = Recovery() if recovery else None
        self.follow = BoundaryFollowing() if escape else None
        self.loops = LoopDetector()
        self.memory = ObstacleMemory()
        self.stop_wait = float(stop_wait)
        self.reset()

    def reset(self, rng=None) -> None:
        self.navigator.reset(rng)
        for part in (self.recovery, self.follow, self.loops, self.memory):
            if part is not None:
                part.reset()
        self._stopped = 0.0

    @property
    def systems(self) -> dict:
        """The navigator's rule bases by role."""
        return self.navigator.systems

    @property
    def roles(self) -> tuple[str, ...]:
        """The names of the navigator's rule bases."""
        return self.navigator.roles

    def for_robot(self, robot) -> "RobustNavigator":
        """Size the navigator for ``robot`` (:class:`TricycleParams`)."""
        self.navigator.for_robot(robot)
        return self

    def act(self, obs) -> Command:
        robot = obs.extras.get("robot", DEFAULT_PARAMS)
        self.memory.add(obs)
        x, y = float(obs.pose[0]), float(obs.pose[1])
        seen = obs
        if self.follow is not None:
            if self.follow.active and (self.follow.should_leave(obs) or self.follow.timed_out(obs)):
                self.follow.stop(succeeded=not self.follow.timed_out(obs))
                self.loops.reset()
            if self.loops.update(obs.t, x, y, obs.target_distance) and (self.recovery is None or self.recovery.phase is None):
                self.follow.start(obs, self.loops.best)
                self.loops.reset()
            if self.follow.active:
                seen = replace(obs, target=self.follow.target(obs, self.memory.points, robot.radius))
        command = self.navigator.act(seen)
        label = "BF" if self.follow is not None and self.follow.active else command.behaviour
        if self.recovery is None or robot.max_reverse_speed <= 0:
            return Command(command.steering, command.speed, label)
        if self.recovery.phase is not None:
            manoeuvre = self.recovery.command(obs, self.memory, robot)
            if manoeuvre is not None:
                return Command(*manoeuvre)
        stopped = command.speed == 0.0 and obs.target_distance > 0.5
        self._stopped = self._stopped + obs.dt if stopped else 0.0
        if self._stopped >= self.stop_wait - 1e-9:
            self._stopped = 0.0
            self.recovery.start(obs, self.memory, robot)
            manoeuvre = self.recovery.command(obs, self.memory, robot)
            if manoeuvre is not None:
                return Command(*manoeuvre)
        return Command(command.steering, command.speed, label)


def _five(name: str, **options):
    from fuzzynav.control.five_behaviours import FiveBehaviourNavigator

    navigator = FiveBehaviourNavigator(**options)
    navigator.name = name
    return navigator


def _two(name: str, **options):
    from fuzzynav.control.avoidance import TwoBehaviourNavigator

    navigator = TwoBehaviourNavigator(**options)
    navigator.name = name
    return navigator


def fuzzy_5b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-5b``: the five-behaviour navigator of §IV.7 with recovery and loop escape
    (``options``, e.g. ``systems=``, go to the navigator)."""
    return RobustNavigator(_five("fuzzy-5b", **options), "fuzzy-5b", recovery=recovery, escape=escape)


def fuzzy_2b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-2b``: the two-behaviour navigator of Fig IV.9 with recovery and loop escape
    (``options``, e.g. ``systems=``, go to the navigator)."""
    return RobustNavigator(_two("fuzzy-2b", **options), "fuzzy-2b", recovery=recovery, escape=escape)


def fuzzy_5b_thesis(**options):
    """``fuzzy-5b-thesis``: the five-behaviour navigator of §IV.7 as published (no layers)."""
    return _five("fuzzy-5b-thesis", **options)


def fuzzy_2b_thesis(**options):
    """``fuzzy-2b-thesis``: the two-behaviour navigator of Fig IV.9 as published (no layers)."""
    return _two("fuzzy-2b-thesis", **options)
