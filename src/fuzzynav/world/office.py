"""The generated family ``office``: rooms along corridors, joined to them (and some to each other)
by doors hardly wider than the robot.

A floor plan of the double-loaded corridor kind: a corridor crosses the world from wall to wall
(with even odds a second one crosses it at right angles), and the bands on either side are cut
into rooms by partitions at right angles to the corridor. Each room has one door onto the
corridor, and each partition between two neighbouring rooms a door with odds ``CONNECTING``; the
rooms that face the second corridor open onto it with the same odds. Doors are ``DOORS`` wide
(a standard office door to a double one), never nearer than ``JAMB`` to a corner. The start and
the goal are the centres of two rooms at least ``MIN_START_GOAL`` apart, the start heading uniform.

A door leaves the robot's disc only a few centimetres each side, and turning into it from the
corridor may take the car a manoeuvre: with reverse, a car-like robot can follow any path of its
footprint that keeps some clearance (J.-P. Laumond, P. E. Jacobs, M. Taïx, R. M. Murray, *A
motion planner for nonholonomic mobile robots*, IEEE Trans. Robotics and Automation 10(5),
1994), so the family is checked solvable for the footprint plus ``MARGIN``, less than the room
the narrowest door leaves on the occupancy grid's cells.
"""

from __future__ import annotations

import numpy as np

THICKNESS = 0.15  # m, walls and partitions
CORRIDOR = (1.8, 2.4)  # m, a corridor's width between its walls' centre lines
CROSS = 0.5  # odds of a second corridor at right angles
ROOM = (3.0, 5.0)  # m, a room's width along the corridor (the last of a row takes what is left)
DOORS = (0.9, 1.5)  # m, a door's opening
JAMB = 0.3  # m, the least wall between a door and a corner
CONNECTING = 0.3  # odds of a door between two neighbouring rooms
MARGIN = 0.04  # m beyond the footprint's radius in the solvability check


def _wall(a, b) -> dict:
    return {"wall": {"start": np.round(a, 3).tolist(), "end": np.round(b, 3).tolist(), "thickness": THICKNESS}}


def with_doors(a, b, doors: list[tuple[float, float]]) -> list[dict]:
    """The pieces of the straight wall from ``a`` to ``b`` (points) left between ``doors``, each
    ``(centre, opening)`` in metres from ``a`` (the opening between the jambs' faces)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    length = float(np.hypot(*(b - a)))
    unit = (b - a) / length
    cuts = [0.0] + [t for centre, width in sorted(doors) for t in (centre - width / 2, centre + width / 2)] + [length]
    return [_wall(a + lo * unit, a + hi * unit) for lo, hi in zip(cuts[::2], cuts[1::2]) if hi - lo > 0.01]


def _door(rng, length: float) -> tuple[float, float]:
    """A door ``(centre, opening)`` somewhere along a wall of ``length`` m, ``JAMB`` from its ends."""
    width = min(float(rng.uniform(*DOORS)), length - 2 * JAMB)
    return float(rng.uniform(JAMB + width / 2, length - JAMB - width / 2)), width


def _widths(rng, length: float) -> list[float]:
    """Rooms' widths along a row of ``length`` m: drawn in ``ROOM`` while another fits."""
    widths: list[float] = []
    while length - sum(widths) >= 2 * ROOM[0]:
        widths.append(float(rng.uniform(ROOM[0], min(ROOM[1], length - sum(widths) - ROOM[0]))))
    return widths + [length - sum(widths)]


def _row(rng, x0: float, x1: float, y_wall: float, y_far: float, side_doors: tuple[bool, bool]):
    """The walls and room centres of one row of rooms between ``x0`` and ``x1``, from the
    corridor wall at ``y_wall`` to ``y_far``, in coordinates where the corridor runs along x.
    ``side_doors`` says which ends face a cross corridor (their end wall may get a door)."""
    xs = np.concatenate([[x0], x0 + np.cumsum(_widths(rng, x1 - x0))])
    depth = abs(y_far - y_wall)
    walls, doors = [], []
    for left, right in zip(xs[:-1], xs[1:]):
        centre, width = _door(rng, right - left)
        doors.append((left - x0 + centre, width))
    grow = [THICKNESS / 2 if face else 0.0 for face in side_doors]  # close the corner with an end wall
    walls += with_doors((x0 - grow[0], y_wall), (x1 + grow[1], y_wall), [(c + grow[0], w) for c, w in doors])
    for k, x in enumerate(xs):
        end = k in (0, len(xs) - 1)
        if end and not side_doors[0 if k == 0 else 1]:
            continue  # the world's boundary
        gap = rng.uniform() < CONNECTING
        walls += with_doors((x, y_wall), (x, y_far), [_door(rng, depth)] if gap else [])
    centres = [((left + right) / 2, (y_wall + y_far) / 2) for left, right in zip(xs[:-1], xs[1:])]
    return walls, centres


def _plan(rng, size: float) -> tuple[list[dict], list[tuple[float, float]]]:
    """Walls and room centres of one floor plan, the main corridor along x."""
    width = float(rng.uniform(*CORRIDOR))
    yc = float(rng.uniform(size * 0.35, size * 0.65))
    spans = [(0.0, size, (False, False))]
    if rng.uniform() < CROSS:
        xc = float(rng.uniform(size * 0.35, size * 0.65))
        spans = [(0.0, xc - width / 2, (False, True)), (xc + width / 2, size, (True, False))]
    walls, centres = [], []
    for y_wall, y_far in ((yc - width / 2, 0.0), (yc + width / 2, size)):
        for x0, x1, faces in spans:
            w, c = _row(rng, x0, x1, y_wall, y_far, faces)
            walls += w
            centres += c
    return walls, centres


def _turned(entry: dict, size: float) -> dict:
    """A wall entry mirrored about the diagonal (x ↔ y), for plans whose main corridor runs along y."""
    wall = dict(entry["wall"])
    wall["start"], wall["end"] = wall["start"][::-1], wall["end"][::-1]
    return {"wall": wall}


def office_document(rng: np.random.Generator, name: str, *, size: float, min_start_goal: float,
                    max_time: float) -> dict:
    """The scenario document of one ``office`` world of ``size`` × ``size`` m drawn from ``rng``
    (module docstring), start and goal at least ``min_start_goal`` m apart (when no two rooms
    are, the plan is drawn again)."""
    while True:
        walls, centres = _plan(rng, size)
        points = np.array(centres)
        apart = np.argwhere(np.hypot(*(points[:, None] - points[None]).transpose(2, 0, 1)) >= min_start_goal)
        if len(apart):
            break
    i, j = apart[int(rng.integers(len(apart)))]
    start, goal = points[i], points[j]
    if rng.uniform() < 0.5:
        walls, start, goal = [_turned(w, size) for w in walls], start[::-1], goal[::-1]
    return {
        "name": name,
        "description": "random office world: rooms along corridors, joined by doors",
        "world": {"width": size, "height": size},
        "robot": {"x": round(float(start[0]), 3), "y": round(float(start[1]), 3),
                  "theta": round(float(rng.uniform(-np.pi, np.pi)), 3)},
        "goal": {"x": round(float(goal[0]), 3), "y": round(float(goal[1]), 3)},
        "obstacles": walls,
        "max_time": max_time,
    }
