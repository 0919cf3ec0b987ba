"""Dead-end corridors whose start faces the closed end (the robot must back out): the worlds on
which ``astar-pp`` shows it backs out (its closed-loop test and ``benchmarks/astar_backing.py``)."""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.world.scenario import scenario_from_dict


def dead_end(width: float = 1.6, depth: float = 8.0, back: float = 1.0, goal=(8.0, 16.0), turn: float = 0.0,
             name: str = "dead-end") -> dict:
    """A corridor ``width`` m wide between the walls' faces and ``depth`` m deep, open to the
    west, across a 20 m × 20 m world (its axis y = 10, from x = 3); the robot ``back`` m from the
    closed end, facing it; the goal outside. Everything turned by ``turn`` rad about the world's centre."""
    c, s = math.cos(turn), math.sin(turn)
    at = lambda x, y: [10 + c * (x - 10) - s * (y - 10), 10 + s * (x - 10) + c * (y - 10)]
    h, x0 = width / 2 + 0.1, 3.0
    walls = [((x0, 10 - h), (x0 + depth, 10 - h)), ((x0, 10 + h), (x0 + depth, 10 + h)),
             ((x0 + depth, 10 - h), (x0 + depth, 10 + h))]
    (rx, ry), (gx, gy) = at(x0 + depth - 0.1 - back, 10.0), at(*goal)
    return {"name": name, "world": {"width": 20.0, "height": 20.0},
            "robot": {"x": rx, "y": ry, "theta": turn}, "goal": {"x": gx, "y": gy},
            "obstacles": [{"wall": {"start": at(*a), "end": at(*b), "thickness": 0.2}} for a, b in walls],
            "max_time": 120.0}


def dead_ends(n: int, seed: int = 0) -> list:
    """``n`` seeded dead ends: width 1.0–2.4 m, depth 4–9 m, the start 0.5–2 m from the closed
    end, the goal 4–8 m off the corridor on either side and at least 1 m inside the world, any
    orientation."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        width, depth, back = rng.uniform(1.0, 2.4), rng.uniform(4.0, 9.0), rng.uniform(0.5, 2.0)
        turn = rng.uniform(-math.pi, math.pi)
        while True:
            goal = (rng.uniform(2.0, 3.0 + depth), 10.0 + rng.choice([-1.0, 1.0]) * rng.uniform(4.0, 8.0))
            doc = dead_end(width, depth, min(back, depth - 1.0), goal, turn, name=f"dead-end-{seed}-{i}")
            if all(1.0 <= v <= 19.0 for v in (doc["goal"]["x"], doc["goal"]["y"])):
                break
        out.append(scenario_from_dict(doc))
    return out
