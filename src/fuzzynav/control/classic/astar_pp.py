"""``astar-pp``: the **map-aware** reference — it is given the whole map, which no other
navigator here has. A path the car can drive, planned on the map inflated by the body (hybrid
A*, Dolgov, Thrun, Montemerlo & Diebel 2008, :func:`fuzzynav.world.hybrid_astar.hybrid_astar`:
forward arcs at seven steering values, so it respects the turning radius l / tan α_max, with a
cost for passing closer than ``comfort`` to obstacles), followed with pure pursuit (R. C.
Coulter, CMU-RI-TR-92-01, 1992). Where no forward path exists — a start facing the closed end
of a dead end — hybrid A* plans again with backward arcs too (Reeds & Shepp, Pacific J. Math.
1990: ``reverse`` times the forward cost, ``gear`` per change of direction), and the tracker
drives the path's legs in turn, backwards where the path backs up (``reverse_speed``).

The planner runs once per world in :meth:`prepare` (the simulator calls it with the scenario
before the episode) and is cached per world within the process, so several seeds on one world
plan once. The planned disc is the body radius plus ``inflation`` (where that closes every way,
plus 2 cm), forward arcs first, then with backward arcs. When hybrid A* finds no path within its
node budget, the grid A* path (Hart,
Nilsson & Raphael 1968, :func:`fuzzynav.world.planning.shortest_path`, which ignores the
heading) is followed instead; :data:`PLANNERS` counts which planner each prepared world got.
Without either (the start cannot reach the goal on the map inflated by ``inflation``, nor by
2 cm) it stays put.

The tracker aims at the path point ``lookahead`` metres beyond the robot's projection on the
path (searched forward from the last one, so progress is monotonic) and drives at
V_max · max(cos η, 0.25), η the bearing of that point, and at most √(``lateral`` / κ) where the
path ahead (the next ``lookahead`` + 0.5 m) bends with curvature κ. The arc of the pure-pursuit
steering up to the aimed point is checked against the map: when the body would come within
``check_margin`` of an obstacle on it, the nearest steering on a grid of 15 whose arc stays clear
is taken instead, at a speed of at most 4/s times the arc's room (clearance less the radius;
0.5 m/s at least). When none is clear, the robot backs at ``reverse_speed`` on the clearest of
the grid's arcs ``BACK_CHECK`` m behind it if that one is clear (``-back-check``), else takes the
clearest arc ahead at half speed if the body stays off the map along it, else stands.

A path with backward legs (runs of one gear between cusps) is tracked leg by leg, each to its
cusp — left for the next leg once within ``CUSP`` of it, or within ``PASSED`` once the robot's
projection is there — by the Stanley law (S. Thrun et al., *Stanley: the robot that won the DARPA
Grand Challenge*, J. Field Robotics 2006) with the path's curvature fed forward: α = atan(l κ) +
gear · (heading error) − atan(k · cross-track offset / (V + 0.1)), at most ``reverse_speed``
backwards, slowing into a cusp; its arc is checked as above, behind the robot when backing (where
no arc behind is clear: the clearest at half speed if the body stays off the map along it, else
it stands). The last leg, forward to the goal, is driven by pure pursuit as a forward path is.

When the tracker cannot hold the plan — no checked arc is clear, or the robot is more than
``ASTRAY`` from its projection on the path (a full-lock turn cut wide, a leg begun off the path
after a cusp) — hybrid A* plans again from the robot's pose with backward arcs (the ``BACKING``
tries above, which leave the tracker a share of the steering), and the new path is tracked from
its start; at most ``REPLANS`` tries an episode, a try that finds nothing included
(replanning in the loop, as the local planners of Kuwata et al., *Real-time motion planning with
applications to autonomous urban driving*, IEEE Trans. Control Syst. Technol. 17(5), 2009). Where
hybrid A* finds nothing from there, the plan is kept. A new episode (:meth:`reset`) starts from the prepared plan.
"""

from __future__ import annotations

import json
import math
from collections import Counter

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.classic.local_map import Body, arcs
from fuzzynav.errors import InputError
from fuzzynav.kernels.angles import wrap_angle
from fuzzynav.settings import BODY, LENGTH, RATE, ROOM, SPEED, WEIGHT, checked
from fuzzynav.world.hybrid_astar import Car, Search, hybrid_astar
from fuzzynav.world.planning import shortest_path

_PLANS: dict[tuple, tuple] = {}  # key -> (planner, points, curvature, gear, heading)
_MAX_PLANS = 64
PLANNERS: Counter = Counter()  # planner used per prepared world: "hybrid-A*", "grid-A*" (fallback), "none"
SPACING = 0.05  # m between path points
CUSP = 0.1  # m: the tracker leaves a leg for the next within this of its end (or at its end, within PASSED)
PASSED = 0.4
STANLEY_GAIN = 1.0  # 1/s: the cross-track gain of the Stanley law on paths with backward legs
BACKING = {"reverse": 2.0, "gear": 5.0}  # hybrid A*'s backward arcs, when no forward path exists: few cusps
BACKING_ROOM = 0.1  # m more room tried first with backward arcs (the legs are tracked less closely)
BACKING_LOCK = 0.8  # share of the steering limit planned with backward arcs (the tracker keeps the rest)
REPLANS = 4  # replans tried from the robot's pose per episode at most (found or not)
BACK_CHECK = 0.3  # m of the arc behind checked before backing out of a pose with no arc ahead clear
ASTRAY = 0.2  # m from the path beyond which the tracker plans again


def _plan(scenario, body: Body, inflation: float, search: Search, hybrid: bool):
    """(planner, path points ``(m, 2)``, curvature ``(m,)``, gear ``(m,)`` and heading ``(m,)``,
    the last two None unless the path has backward legs (gear +1 forward, −1 backward)) on
    ``scenario`` (cached per world and parameters within the process); the points are None
    without a path."""
    key = (json.dumps(scenario.to_dict(), sort_keys=True), body, inflation, search, hybrid)
    if key not in _PLANS:
        if len(_PLANS) >= _MAX_PLANS:
            _PLANS.clear()
        _PLANS[key] = plan_path(scenario, body, inflation, search, hybrid)
    return _PLANS[key]


def plan_path(scenario, body: Body, inflation: float, search: Search, hybrid: bool = True, start=None,
              careful: bool = False):
    """Uncached (planner, points, curvature, gear, heading) of :func:`_plan`: hybrid A* (unless ``hybrid``
    is False) with forward arcs, then with backward arcs too, else grid A*; each on the map
    inflated by the body + ``inflation``, then by the body + 2 cm (with backward arcs, first by
    ``BACKING_ROOM`` more, and planned at ``BACKING_LOCK`` of the steering limit); from the
    pose ``start`` (default: the scenario's). ``careful``: the tries with backward arcs only (a replan)."""
    goal = scenario.goal.position
    start = scenario.start if start is None else np.asarray(start, dtype=float)
    reach = Search(**{**search.__dict__, "reach": min(search.reach, scenario.goal.tolerance)})
    radii = (body.radius + inflation, body.radius + 0.02)
    backing = Search(**{**reach.__dict__, **BACKING})
    tries = [] if careful else [(reach, radius, body.max_steering) for radius in radii]
    tries += [(backing, radius, BACKING_LOCK * body.max_steering) for radius in (radii[0] + BACKING_ROOM, *radii)]
    for setting, radius, lock in tries if hybrid else ():
        plan = hybrid_astar(scenario.world, start, goal, Car(radius, body.wheelbase, lock), setting)
        if plan is not None:
            tail = _densify(np.array([plan.poses[-1, :2], goal]), SPACING)[1:]  # on to the goal itself
            points, curvature = np.vstack([plan.poses[:, :2], tail]), np.append(plan.curvature, np.zeros(len(tail)))
            if (plan.gear > 0).all():
                return "hybrid-A*", points, curvature, None, None
            last = math.atan2(*(goal - plan.poses[-1, :2])[::-1])
            return ("hybrid-A*", points, curvature, np.append(plan.gear, np.ones(len(tail))),
                    np.append(plan.poses[:, 2], np.full(len(tail), last)))
    for radius in radii:
        path = shortest_path(scenario.world, start, goal, radius, weight=search.weight,
                             comfort=search.comfort)
        if path is not None:
            points = _densify(path, SPACING)
            return "grid-A*", points, np.zeros(len(points)), None, None
    return "none", None, None, None, None


def _densify(path: np.ndarray, step: float) -> np.ndarray:
    """Points every ``step`` metres or less along the polyline ``path``."""
    pieces = [path[:1]]
    for a, b in zip(path[:-1], path[1:]):
        k = max(1, int(math.ceil(np.hypot(*(b - a)) / step)))
        pieces.append(a + np.linspace(0, 1, k + 1)[1:, None] * (b - a))
    return np.vstack(pieces)


class AStarPurePursuit(Controller):
    """Map-aware hybrid A* + pure pursuit (module docstring). Options: robot ``radius``/
    ``wheelbase``/``max_steering``/``max_speed``, ``inflation``, ``comfort`` (m), ``weight``
    (clearance cost), ``lookahead`` (m), ``lateral`` (m/s², speed in bends), ``check_margin`` (m),
    ``reverse_speed`` (m/s, on backward legs), ``planner`` (``"hybrid"``, or ``"grid"``: grid A*
    only, to measure what hybrid A* adds)."""

    name = "astar-pp"
    map_aware = True

    @checked(**BODY, inflation=ROOM, comfort=ROOM, weight=WEIGHT, lookahead=LENGTH, lateral=RATE, check_margin=ROOM,
             reverse_speed=SPEED)
    def __init__(self, *, radius: float = Body.radius, wheelbase: float = Body.wheelbase,
                 max_steering: float = Body.max_steering, max_speed: float = Body.max_speed,
                 inflation: float = 0.05, comfort: float = 0.4, weight: float = 3.0, lookahead: float = 0.6,
                 lateral: float = 2.0, check_margin: float = 0.03, reverse_speed: float = 0.5,
                 planner: str = "hybrid"):
        if planner not in ("hybrid", "grid"):
            raise InputError(f"must be hybrid or grid, got {planner!r}", field="planner")
        self.body = Body(radius, wheelbase, max_steering, max_speed)
        self.inflation = float(inflation)
        self.search = Search(weight=float(weight), comfort=float(comfort))
        self.lookahead, self.lateral = float(lookahead), float(lateral)
        self.check_margin = float(check_margin)
        self.reverse_speed = float(reverse_speed)
        self.hybrid = planner == "hybrid"
        self.steering = np.linspace(-max_steering, max_steering, 15)
        self.world = self.scenario = None
        self.planner, self.path, self.curvature, self.gear, self.heading = "none", None, None, None, None
        self._prepared: tuple = (None, None, None, None)
        self._index = self._end = self.replans = 0

    def prepare(self, scenario) -> None:
        """Plan on ``scenario``'s map (goal tasks; other tasks are not planned for)."""
        self.world, self.scenario = scenario.world, scenario
        self.planner, self.path, self.curvature, self.gear, self.heading = "none", None, None, None, None
        if scenario.goal is not None:
            self.planner, self.path, self.curvature, self.gear, self.heading = _plan(
                scenario, self.body, self.inflation, self.search, self.hybrid)
            PLANNERS[self.planner] += 1
        self._prepared = (self.path, self.curvature, self.gear, self.heading)
        self.reset()

    def reset(self, rng=None) -> None:
        """Back to the prepared plan (an episode's replans are forgotten)."""
        self.path, self.curvature, self.gear, self.heading = self._prepared
        self.replans = 0
        self._follow()

    def _follow(self) -> None:
        """Track the present path from its start."""
        self._index = 0
        self._end = self._leg_end(0)

    def _leg_end(self, start: int) -> int:
        """The last index of the leg (a run of one gear) that goes on from path index ``start``."""
        if self.gear is None:
            return 0
        changes = np.flatnonzero(self.gear[start + 1:] != self.gear[start + 1 if start + 1 < len(self.gear) else start])
        return start + int(changes[0]) if len(changes) else len(self.gear) - 1

    def act(self, obs) -> Command:
        if self.path is None:
            return Command(0.0, 0.0, "A*-no-path")
        command = self._track(obs)
        if self.replans < REPLANS and self.hybrid and ("-check" in command.behaviour or self._astray(obs)):
            if self._replan(obs.pose):
                return self._track(obs)
        return command

    def _astray(self, obs) -> bool:
        """Is the robot farther than ``ASTRAY`` from its projection on the path?"""
        return math.hypot(*(self.path[self._index] - np.asarray(obs.pose[:2], dtype=float))) > ASTRAY

    def _replan(self, pose) -> bool:
        """Plan again from ``pose`` with backward arcs (module docstring); False, the plan kept, without a hybrid A* path."""
        planner, path, curvature, gear, heading = plan_path(self.scenario, self.body, self.inflation, self.search,
                                                            start=np.asarray(pose, dtype=float), careful=True)
        self.replans += 1  # a try that finds nothing counts too: a stalemate does not search at every step
        if planner != "hybrid-A*":
            return False
        self.path, self.curvature, self.gear, self.heading = path, curvature, gear, heading
        self._follow()
        return True

    def _track(self, obs) -> Command:
        """The tracker's command on the present path (module docstring)."""
        xy = np.asarray(obs.pose[:2], dtype=float)
        if self.heading is not None:
            self._next_leg(xy)
            if self._end < len(self.path) - 1 or self.gear[min(self._index + 1, self._end)] < 0:
                return self._legs(obs, xy)  # any leg but a last forward one, which pure pursuit drives
        ahead = self.path[self._index:self._index + 40]
        self._index += int(np.argmin(np.hypot(*(ahead - xy).T)))
        aim = min(self._index + int(round(self.lookahead / SPACING)), len(self.path) - 1)
        dx, dy = self.path[aim] - xy
        bearing = wrap_angle(math.atan2(dy, dx) - float(obs.pose[2]))
        steering = self.body.steer_towards(bearing, math.hypot(dx, dy))
        bend = float(np.abs(self.curvature[self._index:aim + int(0.5 / SPACING)]).max(initial=0.0))
        speed = min(self.body.max_speed * max(math.cos(bearing), 0.25), math.sqrt(self.lateral / max(bend, 1e-6)))
        return self._checked(obs.pose, steering, speed, math.hypot(dx, dy))

    def _next_leg(self, xy) -> None:
        """At the cusp ending the present leg (module docstring): on to the next leg."""
        to_cusp = math.hypot(*(self.path[self._end] - xy))
        if self._end < len(self.path) - 1 and (to_cusp < CUSP or (self._index >= self._end - 1 and to_cusp < PASSED)):
            self._index, self._end = self._end, self._leg_end(self._end)

    def _legs(self, obs, xy) -> Command:
        """A leg of a path with backward legs, tracked by the Stanley law (module docstring)."""
        to_cusp = math.hypot(*(self.path[self._end] - xy))
        ahead = self.path[self._index:min(self._index + 40, self._end + 1)]
        self._index += int(np.argmin(np.hypot(*(ahead - xy).T)))
        i = self._index
        gear = self.gear[min(i + 1, self._end)]
        psi, theta = float(self.heading[i]), float(obs.pose[2])
        offset = (xy[1] - self.path[i, 1]) * math.cos(psi) - (xy[0] - self.path[i, 0]) * math.sin(psi)  # left +
        speed = self.reverse_speed if gear < 0 else self.body.max_speed
        speed = min(speed, math.sqrt(self.lateral / max(abs(float(self.curvature[i])), 1e-6)))
        if self._end < len(self.path) - 1:  # slow down into a cusp
            speed = min(speed, max(0.2, 2.0 * to_cusp))
        turn = wrap_angle(psi - theta)
        steering = (math.atan(self.body.wheelbase * float(self.curvature[i])) + gear * turn
                    - math.atan(STANLEY_GAIN * offset / (speed + 0.1)))
        steering = min(max(steering, -self.body.max_steering), self.body.max_steering)
        command = self._checked(obs.pose, steering, speed, max(speed, 0.3), backwards=gear < 0)
        if gear < 0:
            return Command(command.steering, -command.speed, command.behaviour + "-back")
        return command

    def _arc_clearance(self, pose, candidates: np.ndarray, length: float, backwards: bool) -> np.ndarray:
        """The least clearance of the body's centre along each steering's arc of ``length`` metres
        from ``pose`` (behind the robot when ``backwards``), on the map."""
        lengths = np.linspace(0.1, 1.0, 10) * max(length, 0.3) * (-1.0 if backwards else 1.0)
        local = arcs(np.tan(candidates) / self.body.wheelbase, lengths)  # (A, K, 2) robot frame
        c, s = math.cos(float(pose[2])), math.sin(float(pose[2]))
        world = np.stack([pose[0] + c * local[..., 0] - s * local[..., 1],
                          pose[1] + s * local[..., 0] + c * local[..., 1]], axis=-1)
        return self.world.clearance(world.reshape(-1, 2)).reshape(local.shape[:2]).min(axis=1)

    def _checked(self, pose, steering: float, speed: float, length: float, backwards: bool = False) -> Command:
        """The command with its arc up to ``length`` metres (behind the robot when ``backwards``)
        checked against the map (module docstring)."""
        candidates = np.concatenate([[steering], self.steering])
        order = np.argsort(np.abs(candidates - steering), kind="stable")
        clearance = self._arc_clearance(pose, candidates, length, backwards)
        clear = clearance >= self.body.radius + self.check_margin
        label = "HA*+PP" if self.planner == "hybrid-A*" else "A*+PP"
        if clear[order].any():
            best = order[np.argmax(clear[order])]
            room = float(clearance[best]) - self.body.radius  # slow down where the arc passes close
            return Command(float(candidates[best]), min(speed, max(0.5, 4.0 * room)), label)
        if not backwards:  # no arc ahead is clear: back on the clearest arc behind, when that one is clear
            behind = self._arc_clearance(pose, self.steering, BACK_CHECK, backwards=True)
            if behind.max() >= self.body.radius + self.check_margin:
                return Command(float(self.steering[np.argmax(behind)]), -self.reverse_speed, label + "-back-check")
        clearest = int(np.argmax(clearance))  # at half speed while it keeps off the map, else stand
        return Command(float(candidates[clearest]), 0.5 * speed if clearance[clearest] > self.body.radius else 0.0,
                       label + "-check")


def make(**options) -> AStarPurePursuit:
    """Factory of ``astar-pp`` (options: see :class:`AStarPurePursuit`)."""
    return AStarPurePursuit(**options)
