"""``astar-pp``: the **map-aware** reference — it is given the whole map, which no other
navigator here has. Shortest path on the map inflated by the body (A*, Hart, Nilsson & Raphael
1968, :func:`fuzzynav.world.planning.shortest_path`, with a cost for passing closer than
``comfort`` to obstacles), followed with pure pursuit (R. C. Coulter, CMU-RI-TR-92-01, 1992).

The planner runs once per world in :meth:`prepare` (the simulator calls it with the scenario
before the episode) and is cached per world within the process, so several seeds on one world
plan once. The planned disc is the body radius plus ``inflation``; the tracker aims at the path
point ``lookahead`` metres beyond the robot's projection on the path (searched forward from the
last one, so progress is monotonic) and drives at V_max · max(cos η, 0.25), η the bearing of
that point. The path ignores the heading (A*, not hybrid A*), and a car turning round onto it
sweeps a circle of radius l / tan α_max: so each step, the arc of the pure-pursuit steering over
the next ``check`` seconds is checked against the map, and when the body would come within
``check_margin`` of an obstacle on it, the nearest steering on the grid of 15 whose arc stays
clear is taken instead (none: the clearest, at half speed), at a speed of at most 4/s times the
arc's room (clearance less the radius; 0.5 m/s at least). The margin is smaller than the
planning ``inflation``: the path itself may run at the inflated radius in narrow passages, and
a check that demanded the inflation there would push the robot off its path. Without a path (the start cannot reach the goal on the
map inflated by ``inflation``, nor by 2 cm) it stays put.
"""

from __future__ import annotations

import json
import math

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.classic.local_map import Body, arcs, positive
from fuzzynav.world.planning import shortest_path


_PLANS: dict[tuple, np.ndarray | None] = {}  # (scenario, planner parameters) -> densified path
_MAX_PLANS = 64


def _plan(scenario, radius: float, comfort: float, weight: float) -> np.ndarray | None:
    """The densified path on ``scenario`` (cached per world and parameters within the process)."""
    key = (json.dumps(scenario.to_dict(), sort_keys=True), radius, comfort, weight)
    if key not in _PLANS:
        if len(_PLANS) >= _MAX_PLANS:
            _PLANS.clear()
        path = shortest_path(scenario.world, scenario.start, scenario.goal.position, radius,
                             weight=weight, comfort=comfort)
        _PLANS[key] = None if path is None else _densify(path, 0.1)
    return _PLANS[key]


def _densify(path: np.ndarray, step: float) -> np.ndarray:
    """Points every ``step`` metres or less along the polyline ``path``."""
    pieces = [path[:1]]
    for a, b in zip(path[:-1], path[1:]):
        k = max(1, int(math.ceil(np.hypot(*(b - a)) / step)))
        pieces.append(a + np.linspace(0, 1, k + 1)[1:, None] * (b - a))
    return np.vstack(pieces)


class AStarPurePursuit(Controller):
    """Map-aware A* + pure pursuit (module docstring). Options: robot ``radius``/``wheelbase``/
    ``max_steering``/``max_speed``, ``inflation``, ``comfort`` (m), ``weight`` (clearance cost),
    ``lookahead`` (m), ``check`` (s), ``check_margin`` (m)."""

    name = "astar-pp"
    map_aware = True

    def __init__(self, *, radius: float = Body.radius, wheelbase: float = Body.wheelbase,
                 max_steering: float = Body.max_steering, max_speed: float = Body.max_speed,
                 inflation: float = 0.1, comfort: float = 0.4, weight: float = 3.0, lookahead: float = 1.0,
                 check: float = 1.0, check_margin: float = 0.03):
        self.body = Body(radius, wheelbase, max_steering, max_speed)
        self.inflation, self.comfort, self.weight = float(inflation), float(comfort), float(weight)
        self.lookahead, self.check = positive(lookahead, "lookahead"), positive(check, "check")
        self.check_margin = float(check_margin)
        self.steering = np.linspace(-max_steering, max_steering, 15)
        self.world = None
        self.path = None
        self._index = 0

    def prepare(self, scenario) -> None:
        """Plan on ``scenario``'s map (goal tasks; other tasks are not planned for)."""
        self.path = None
        self.world = scenario.world
        if scenario.goal is not None:  # inflated first; where that closes every way, the body + 2 cm
            for radius in (self.body.radius + self.inflation, self.body.radius + 0.02):
                self.path = _plan(scenario, radius, self.comfort, self.weight)
                if self.path is not None:
                    break
        self._index = 0

    def reset(self, rng=None) -> None:
        self._index = 0

    def act(self, obs) -> Command:
        if self.path is None:
            return Command(0.0, 0.0, "A*-no-path")
        xy = np.asarray(obs.pose[:2], dtype=float)
        ahead = self.path[self._index:self._index + 40]
        self._index += int(np.argmin(np.hypot(*(ahead - xy).T)))
        steps = np.hypot(*np.diff(self.path[self._index:], axis=0).T)
        along = np.concatenate([[0.0], np.cumsum(steps)])
        goal_point = self.path[self._index + min(int(np.searchsorted(along, self.lookahead)), len(along) - 1)]
        dx, dy = goal_point - xy
        bearing = math.remainder(math.atan2(dy, dx) - float(obs.pose[2]), math.tau)
        steering = self.body.steer_towards(bearing, math.hypot(dx, dy))
        speed = self.body.max_speed * max(math.cos(bearing), 0.25)
        return self._checked(obs.pose, steering, speed)

    def _checked(self, pose, steering: float, speed: float) -> Command:
        """The command with its arc checked against the map (module docstring)."""
        candidates = np.concatenate([[steering], self.steering])
        order = np.argsort(np.abs(candidates - steering), kind="stable")
        lengths = np.linspace(0.1, 1.0, 10) * max(speed, 0.5) * self.check
        local = arcs(np.tan(candidates) / self.body.wheelbase, lengths)  # (A, K, 2) robot frame
        c, s = math.cos(float(pose[2])), math.sin(float(pose[2]))
        world = np.stack([pose[0] + c * local[..., 0] - s * local[..., 1],
                          pose[1] + s * local[..., 0] + c * local[..., 1]], axis=-1)
        clearance = self.world.clearance(world.reshape(-1, 2)).reshape(local.shape[:2]).min(axis=1)
        clear = clearance >= self.body.radius + self.check_margin
        if clear[order].any():
            best = order[np.argmax(clear[order])]
            room = float(clearance[best]) - self.body.radius  # slow down where the arc passes close
            return Command(float(candidates[best]), min(speed, max(0.5, 4.0 * room)), "A*+PP")
        return Command(float(candidates[np.argmax(clearance)]), 0.5 * speed, "A*+PP-check")


def make(**options) -> AStarPurePursuit:
    """Factory of ``astar-pp`` (options: see :class:`AStarPurePursuit`)."""
    return AStarPurePursuit(**options)
