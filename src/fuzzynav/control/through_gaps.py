"""The gap-aware five-behaviour navigator inside the recovery and loop-escape layers, guided by
a route round the obstacles seen so far: ``fuzzy-5b-gap-robust``.

- The inner navigator is the compiled ``fuzzy-5b-gap`` (:mod:`fuzzynav.control.five_behaviours`:
  the lidar ring, readings by sector, VFH+-style gap finding with follow-the-gap's choice nearest
  to the goal).
- :class:`RouteGuidance` aims it along the shortest route to the goal round the obstacle points
  remembered so far, unseen space assumed free (:func:`fuzzynav.control.route.route_target`, the
  freespace assumption of D*, Stentz 1994): the navigator is given a goal in the direction of the
  point ``ahead`` m along that route, at the goal's distance, so Table IV.1 and the gap finder
  steer towards the passage the route takes instead of the straight line's, while the fuzzy
  behaviours keep the body off what the memory has not seen yet. This is the split of the
  ROS navigation stack that the BARN challenge's DWA baseline runs (a global planner on the
  sensed costmap, a local controller following it). The route keeps the body's radius plus
  ``clearances`` (the first that leaves a route; none: the real goal). Where the straight line
  to the goal keeps that room from every remembered point for ``direct`` m, the goal itself is
  given (the grid route's 8-neighbour steps wander off the straight line in open space).
- :class:`~fuzzynav.control.robust.RobustNavigator` around both adds the reversing recovery
  (``REC-BACK``, ``REC-TURN``) that leaves a pocket the car cannot leave forwards, and the loop
  escape (``BF``) when the robot circles anyway.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.robust import RobustNavigator
from fuzzynav.control.route import route_target
from fuzzynav.robot.tricycle import DEFAULT_PARAMS


class RouteGuidance(Controller):
    """``navigator`` driven towards the route round the points of ``memory`` (an
    :class:`~fuzzynav.control.recovery.ObstacleMemory` filled by the caller) — module docstring;
    planned again every ``replan`` s on a grid of ``cell`` m."""

    def __init__(self, navigator, memory, *, clearances=(0.1, 0.05, 0.0), cell: float = 0.15, ahead: float = 1.5,
                 replan: float = 1.0, direct: float = 3.0):
        self.navigator, self.memory, self.name = navigator, memory, navigator.name
        self.sensors = navigator.sensors
        self.clearances, self.cell, self.ahead, self.replan = tuple(clearances), float(cell), float(ahead), float(replan)
        self.direct = float(direct)
        self.reset()

    def reset(self, rng=None) -> None:
        self.navigator.reset(rng)
        self._waypoint, self._planned = None, -math.inf

    systems = property(lambda self: self.navigator.systems, doc="The navigator's rule bases by role.")
    roles = property(lambda self: self.navigator.roles, doc="The names of the navigator's rule bases.")

    def for_robot(self, robot) -> "RouteGuidance":
        """The navigator sized for ``robot`` (:class:`TricycleParams`), guided by this."""
        self.navigator.for_robot(robot)
        return self

    def waypoint(self, obs) -> np.ndarray | None:
        """The point ``ahead`` m along the route from the robot to ``obs.target`` (None: no route)."""
        if obs.t - self._planned >= self.replan - 1e-9:
            radius = obs.extras.get("robot", DEFAULT_PARAMS).radius
            self._waypoint, self._planned = None, obs.t
            if self._line_free(obs, radius + self.clearances[0]):
                return None
            for clearance in self.clearances:
                self._waypoint = route_target(self.memory.points, obs.pose, obs.target, radius + clearance,
                                              self.ahead, self.cell)
                if self._waypoint is not None:
                    break
        return self._waypoint

    def _line_free(self, obs, room: float) -> bool:
        """Does the straight line from the robot towards the goal keep ``room`` from every
        remembered point for ``direct`` m (or up to the goal)?"""
        points = self.memory.points
        if not len(points):
            return True
        start = np.asarray(obs.pose[:2], dtype=float)
        way = np.asarray(obs.target, dtype=float) - start
        length = float(np.hypot(*way))
        if length < 1e-9:
            return True
        unit, reach = way / length, min(length, self.direct)
        along = np.clip((points - start) @ unit, 0.0, reach)
        nearest = start + along[:, None] * unit
        return bool(np.min(np.hypot(*(points - nearest).T)) >= room)

    def act(self, obs) -> Command:
        point = self.waypoint(obs)
        if point is None:
            return self.navigator.act(obs)
        offset = point - obs.pose[:2]
        length = float(np.hypot(*offset))
        if length < 1e-9:
            return self.navigator.act(obs)
        reach = max(obs.target_distance, length)
        return self.navigator.act(replace(obs, target=obs.pose[:2] + offset * (reach / length)))


def fuzzy_5b_gap_robust(*, recovery: bool = True, escape: bool = True, guidance: dict | None = None,
                        **options) -> RobustNavigator:
    """``fuzzy-5b-gap-robust``: ``fuzzy-5b-gap`` (``options`` go to it), route-guided
    (``guidance``: :class:`RouteGuidance` options), with recovery and loop escape (either can be
    switched off)."""
    from fuzzynav.control.five_behaviours import FiveBehaviourNavigator

    navigator = FiveBehaviourNavigator(gap=True, **options)
    navigator.name = "fuzzy-5b-gap-robust"
    robust = RobustNavigator(navigator, navigator.name, recovery=recovery, escape=escape)
    robust.navigator = RouteGuidance(navigator, robust.memory, **(guidance or {}))
    robust.sensors = navigator.sensors  # the simulator gives the wrapper the navigator's lidar
    return robust
