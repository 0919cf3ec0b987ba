"""The generated family ``dynabarn``: worlds set up as DynaBARN's (A. Nair, F. Jiang, K. Hou,
Z. Xu, S. Li, X. Xiao, P. Stone, "DynaBARN: Benchmarking Metric Ground Navigation in Dynamic
Environments", IEEE SSRR 2022), the moving-obstacle worlds 300–359 of the BARN Challenge.

DynaBARN's 60 worlds are a download from a file host, not in its repository (which holds only
its generator and no licence), so none is imported: this family redraws worlds by the same
recipe, written anew from the generator's description (docs/dynamic.md):

- the arena: 20 m × 20 m (x, y ∈ [−10, 10]) walled on three sides (x = −10, y = ±10) and open at
  x = +10; the robot starts outside it at (11, 0) heading π, the goal is (−9, 0) (the challenge's
  ``run.py``: start + (−20, 0)), reached within 1 m, in 100 s;
- 2 to 5 cylinders of radius 0.5 m, each on a trajectory that crosses the arena from border to
  border along the graph of a polynomial y = p(x) of order 1 to 4 fitted through order + 1
  random whole-metre points (the generator's ``get_random_traj_points``), driven one way or the
  other at random;
- speeds: DynaBARN draws each segment's speed around a mean drawn per obstacle; here each
  obstacle keeps its mean, uniform in [0.3, 1.5] m/s in 0.1 m/s steps (one ``waypoints``
  speed);
- at the end of its track a DynaBARN cylinder jumps back to the start (a looping Gazebo
  animation); here it walks back along the same track (a ``waypoints`` loop out and back), so
  no obstacle appears out of nowhere.

Coordinates: the world is the arena's inside, x from the back wall's face (−9.75) to 1 m beyond
the start, y between the side walls' faces (±9.75), its lower-left corner the origin; the walls
are the world's border. Centres of the cylinders stay 0.5 m inside the walls, and no track
starts within 1.5 m of the goal (a scenario's goal may not lie inside an obstacle at t = 0).

:data:`REFERENCE` is the BARN score's reference of every world: the true optimal path, 20 m
(the straight line from the start to the goal: nothing stands in the way), and the challenge's
own value, ``GOAL_POSITION[0] − INIT_POSITION[0]`` = −20 − 11 = −31 m, with which its score is
0.125 for every success whatever its time (docs/dynamic.md).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.world.polylines import arc_lengths, at_arc

ARENA = 10.0  # m: half-width of DynaBARN's arena
WALL_FACE = 9.75  # m: the walls are 0.5 m thick, centred on ±10
START, HEADING, GOAL = (11.0, 0.0), float(np.pi), (-9.0, 0.0)  # run.py, worlds 300–359
TOLERANCE, TIME_LIMIT = 1.0, 100.0  # m, s
RADIUS = 0.5  # m, DynaBARN's cylinders
COUNT = (2, 5)  # cylinders per world (the generator's default numpy randint(2, 6))
ORDERS = (1, 4)  # polynomial orders
SPEEDS = (0.3, 1.5)  # m/s: mean speed of an obstacle
TRACK_POINTS = 16  # waypoints of a track
MIN_TRACK = 5.0  # m: shorter crossings (a corner clipped) are redrawn
REFERENCE = {"barn_optimal_path_m": 20.0, "barn_challenge_path_m": -31.0}

_ORIGIN = np.array([-WALL_FACE, -WALL_FACE])  # the world's lower-left corner in arena coordinates
WIDTH, HEIGHT = START[0] + 1.0 + WALL_FACE, 2 * WALL_FACE


def _world(point) -> list[float]:
    return (np.asarray(point, dtype=float) - _ORIGIN).round(3).tolist()


def track(rng: np.random.Generator) -> np.ndarray:
    """``(TRACK_POINTS, 2)`` points (arena coordinates) of one crossing: the longest piece of the
    graph of a random polynomial inside the arena, from border to border, either way round."""
    while True:
        order = int(rng.integers(ORDERS[0], ORDERS[1] + 1))
        knots = rng.integers(-10, 11, size=(order + 1, 2)).astype(float)
        if len(np.unique(knots[:, 0])) <= order:
            continue  # the fit needs order + 1 distinct abscissae
        poly = np.polynomial.Polynomial.fit(knots[:, 0], knots[:, 1], order)
        x = np.linspace(-ARENA, ARENA, 2001)
        inside = np.abs(poly(x)) <= ARENA
        runs = np.flatnonzero(np.diff(np.concatenate([[0], inside.astype(int), [0]])))
        if not len(runs):
            continue
        first, last = max(zip(runs[::2], runs[1::2]), key=lambda run: run[1] - run[0])
        xs = x[first:last]
        curve = np.column_stack([xs, poly(xs)])
        arc = arc_lengths(curve)
        if arc[-1] < MIN_TRACK:
            continue
        points = at_arc(curve, arc, np.linspace(0.0, arc[-1], TRACK_POINTS))
        inner = WALL_FACE - RADIUS
        points = np.column_stack([np.clip(points[:, 0], -inner, ARENA), np.clip(points[:, 1], -inner, inner)])
        return points[::-1] if rng.uniform() < 0.5 else points


def dynabarn_document(rng: np.random.Generator, name: str) -> dict:
    """The scenario document of one ``dynabarn`` world drawn from ``rng`` (module docstring)."""
    obstacles = []
    for _ in range(int(rng.integers(COUNT[0], COUNT[1] + 1))):
        points = track(rng)
        while np.hypot(*(points[0] - GOAL)) < RADIUS + TOLERANCE:  # a scenario's goal may not start covered
            points = track(rng)
        there_and_back = np.vstack([points, points[-2:0:-1]])
        speed = round(float(rng.choice(np.arange(SPEEDS[0], SPEEDS[1] + 0.05, 0.1))), 1)
        obstacles.append({"circle": {"center": _world(points[0]), "radius": RADIUS},
                          "motion": {"type": "waypoints", "points": [_world(p) for p in there_and_back],
                                     "speed": speed, "loop": True}})
    x, y = _world(START)
    gx, gy = _world(GOAL)
    return {
        "name": name,
        "description": "DynaBARN-like world: moving cylinders on polynomial tracks across a walled 20 m arena",
        "world": {"width": WIDTH, "height": HEIGHT},
        "robot": {"x": x, "y": y, "theta": round(HEADING, 6)},
        "goal": {"x": gx, "y": gy, "tolerance": TOLERANCE},
        "obstacles": obstacles,
        "max_time": TIME_LIMIT,
    }
