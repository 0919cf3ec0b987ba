"""The moving obstacles of the generated family ``dynamic`` (:mod:`fuzzynav.world.generate`):
people and vehicles around the route from the start to the goal, as the moving cylinders of
DynaBARN (Nair et al., "DynaBARN: Benchmarking Metric Ground Navigation in Dynamic
Environments", SSRR 2022) and the crossing / overtaking / oncoming encounters of crowd-navigation
benchmarks. Speeds are uniform in [0.3, 1.5] m/s.

- **crossing pedestrians** (2–4): discs of radius 0.25–0.4 m starting on the route (at 25–75 %
  of its length) on a ``line`` along the world axis closer to the route's normal, reflecting at
  the world's border: they walk the whole street back and forth across the route;
- **patrols** (1–2): discs or squares on a ``waypoints`` loop between a point on each side of the
  route (at 30–70 % of its length, 2–5 m off it);
- **oncoming traffic** (1–2): discs of radius 0.3–0.5 m coming down the route from 85 % to 15 % of
  its length, 1.5–3 m beside it, and back (a ``waypoints`` loop).

:func:`keeps_clear` is the family's extra test of solvability: no moving obstacle ever comes
within a margin of the start or of the goal, so the robot is never trapped where it stands and
the goal is never covered.
"""

from __future__ import annotations

import numpy as np

SPEEDS = (0.3, 1.5)  # m/s
CLEAR_OF_ENDS = 1.0  # m: the smallest gap from any moving obstacle to the start or the goal, at any time
CHECK_STEP = 0.2  # s between the times at which that gap is checked (≤ 0.3 m of travel at 1.5 m/s)


def _circle(center, radius) -> dict:
    return {"circle": {"center": np.round(center, 2).tolist(), "radius": round(float(radius), 2)}}


def _square(center, half) -> dict:
    corners = np.array(center) + half * np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])
    return {"polygon": {"points": corners.round(2).tolist()}}


def _speed(rng) -> float:
    return round(float(rng.uniform(*SPEEDS)), 2)


def moving_obstacles(rng: np.random.Generator, start, goal) -> list[dict]:
    """The moving obstacles of one ``dynamic`` world (scenario-file entries with a ``motion``)."""
    route = goal - start
    ahead = route / np.hypot(*route)
    normal = np.array([-ahead[1], ahead[0]])
    across = np.eye(2)[int(abs(route[0]) > abs(route[1]))]  # the world axis closer to the route's normal
    entries = []
    for _ in range(int(rng.integers(2, 5))):  # crossing pedestrians
        centre = start + rng.uniform(0.25, 0.75) * route
        velocity = _speed(rng) * across * (1 if rng.uniform() < 0.5 else -1)
        entries.append({**_circle(centre, rng.uniform(0.25, 0.4)),
                        "motion": {"type": "line", "velocity": velocity.round(3).tolist()}})
    for _ in range(int(rng.integers(1, 3))):  # patrols
        middle = start + rng.uniform(0.3, 0.7) * route
        ends = [np.clip(middle + side * rng.uniform(2.0, 5.0) * normal, 1.0, 19.0) for side in (-1, 1)]
        shape = _circle(ends[0], rng.uniform(0.3, 0.5)) if rng.uniform() < 0.5 else _square(ends[0], rng.uniform(0.25, 0.4))
        entries.append({**shape, "motion": {"type": "waypoints", "points": np.round(ends, 2).tolist(),
                                            "speed": _speed(rng), "loop": True}})
    for _ in range(int(rng.integers(1, 3))):  # oncoming traffic
        beside = (1 if rng.uniform() < 0.5 else -1) * rng.uniform(1.5, 3.0) * normal
        ends = [np.clip(start + f * route + beside, 1.0, 19.0) for f in (0.85, 0.15)]
        entries.append({**_circle(ends[0], rng.uniform(0.3, 0.5)),
                        "motion": {"type": "waypoints", "points": np.round(ends, 2).tolist(), "speed": _speed(rng),
                                   "loop": True}})
    return entries


def keeps_clear(world, points, max_time: float, margin: float = CLEAR_OF_ENDS) -> bool:
    """True when every moving obstacle of ``world`` keeps at least ``margin`` (m) from each of
    ``points`` (start, goal) at every :data:`CHECK_STEP` until ``max_time`` (the static obstacles
    and the border, also measured, keep farther by the family's construction)."""
    from fuzzynav.world.moving import offsets

    times = np.arange(0.0, max_time + CHECK_STEP, CHECK_STEP)
    moved = offsets(world, times)
    return all(world.clearance_over_time(np.tile(point, (len(times), 1)), moved).min() >= margin for point in points)
