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

**The robot's size and limits** come from the observation (``extras["robot"]``, the
scenario's ``robot:`` keys): the navigator is built with the robot's wheelbase (the anti-orbit
guard of goal seeking) and top speed, and — its tables, turning room and safety stop being
written for the thesis' 0.3 m body — sees every range reading and D_ro shortened by the
difference between the robot's radius and 0.3 m (the obstacles grown by it, as in a
configuration space). With the default robot nothing changes, so the ``-thesis`` variants
(:func:`fuzzy_5b_thesis`, :func:`fuzzy_2b_thesis`, no layers) drive exactly as published.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.escape import BoundaryFollowing, LoopDetector
from fuzzynav.control.recovery import ObstacleMemory, Recovery
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

THESIS_BODY = DEFAULT_PARAMS.radius  # the footprint the thesis navigators' distances are written for (m)


def sized(obs, robot):
    """``obs`` (one robot or a batch) as a robot of the thesis' body sees it: readings and D_ro
    shortened by ``robot.radius`` − 0.3 m (a reading at the range stays "nothing seen")."""
    grow = robot.radius - THESIS_BODY
    if grow == 0.0:
        return obs
    changes = {}
    if obs.ranges is not None:
        ranges = np.asarray(obs.ranges, dtype=float)
        changes["ranges"] = np.where(ranges < obs.max_range - 1e-9, np.clip(ranges - grow, 0.0, obs.max_range), ranges)
    if obs.obstacle_distance is not None:
        distance = np.asarray(obs.obstacle_distance, dtype=float) - grow
        changes["obstacle_distance"] = float(distance) if distance.ndim == 0 else distance
    return replace(obs, **changes)


class SizedNavigator(Controller):
    """A thesis navigator ``factory(**options)`` built for the robot of the observation and fed
    :func:`sized` observations; one robot (:meth:`act`) or a batch (:meth:`act_batch`)."""

    def __init__(self, factory, name: str, speed_option: str | None = None, **options):
        self.factory, self.name, self.speed_option, self.options = factory, name, speed_option, options
        self.navigator, self._built_for = None, None

    def reset(self, rng=None) -> None:
        if self.navigator is not None:
            self.navigator.reset(rng)

    def _navigator_for(self, robot):
        """The thesis navigator built for ``robot`` (rebuilt when its wheelbase or top speed change)."""
        key = (robot.wheelbase, robot.max_speed)
        if self.navigator is None or self._built_for != key:
            sizes = {"wheelbase": robot.wheelbase}
            if self.speed_option:
                sizes[self.speed_option] = robot.max_speed
            self.navigator, self._built_for = self.factory(**{**sizes, **self.options}), key
        return self.navigator

    def act(self, obs) -> Command:
        robot = obs.extras.get("robot", DEFAULT_PARAMS)
        return self._navigator_for(robot).act(sized(obs, robot))

    def act_batch(self, obs):
        robot = obs.extras.get("robot", DEFAULT_PARAMS)
        return self._navigator_for(robot).act_batch(sized(obs, robot))


class RobustNavigator(Controller):
    """A :class:`SizedNavigator` with the recovery and loop-escape layers (either can be switched
    off: ``recovery=False``, ``escape=False``)."""

    def __init__(self, navigator: SizedNavigator, *, recovery: bool = True, escape: bool = True,
                 stop_wait: float = 1.0):
        self.navigator, self.name = navigator, navigator.name
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


def _five(**options):
    from fuzzynav.control.five_behaviours import FiveBehaviourNavigator

    return FiveBehaviourNavigator(**options)


def _two(**options):
    from fuzzynav.control.avoidance import TwoBehaviourNavigator

    return TwoBehaviourNavigator(**options)


def fuzzy_5b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-5b``: the five-behaviour navigator of §IV.7 with recovery and loop escape."""
    return RobustNavigator(SizedNavigator(_five, "fuzzy-5b", "v_max", **options), recovery=recovery, escape=escape)


def fuzzy_2b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-2b``: the two-behaviour navigator of Fig IV.9 with recovery and loop escape."""
    return RobustNavigator(SizedNavigator(_two, "fuzzy-2b", **options), recovery=recovery, escape=escape)


def fuzzy_5b_thesis(**options) -> SizedNavigator:
    """``fuzzy-5b-thesis``: the five-behaviour navigator of §IV.7 as published (no layers)."""
    return SizedNavigator(_five, "fuzzy-5b-thesis", "v_max", **options)


def fuzzy_2b_thesis(**options) -> SizedNavigator:
    """``fuzzy-2b-thesis``: the two-behaviour navigator of Fig IV.9 as published (no layers)."""
    return SizedNavigator(_two, "fuzzy-2b-thesis", **options)
