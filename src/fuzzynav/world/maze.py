"""The generated family ``maze``: a grid maze filling the world, its corridors wide enough for the
car to turn round in.

The maze is carved by the randomised depth-first search ("recursive backtracker", J. Buck,
*Mazes for Programmers*, Pragmatic Bookshelf 2015, ch. 8) on a square grid of ``CELLS`` cells a
side, which gives a perfect maze (one way between any two cells, many dead ends); then a share
``BRAID`` of the walls left standing between cells is knocked down, which opens loops (a "braid"
maze, Buck ch. 9), so a navigator that picks a wrong branch may find another way round.

The corridor between two walls is a cell's side less a wall's thickness; the coarsest grid is
chosen so that it exceeds twice the robot's footprint radius plus its turning radius at the
navigators' steering limit (:data:`fuzzynav.world.generate.TURNING_MARGIN`): the tricycle can
turn round in any corridor and at any dead end without reversing, and the family is checked
solvable with that margin. The world's boundary is the maze's outer wall. The start and the goal
are the centres of two cells at least ``MIN_START_GOAL`` apart, the start heading uniform.
"""

from __future__ import annotations

import numpy as np

CELLS = (6, 7, 8)  # cells a side, drawn per world (the corridors of the finest grid are the narrowest)
THICKNESS = 0.15  # m, the walls between cells
BRAID = 0.15  # share of the inner walls left by the carving that are then knocked down


def carve(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The walls still standing after the randomised depth-first carving of an ``n`` × ``n`` grid:
    ``(east (n, n − 1), north (n − 1, n))`` booleans, ``east[r, c]`` the wall between cells
    ``(r, c)`` and ``(r, c + 1)``, ``north[r, c]`` the wall between ``(r, c)`` and ``(r + 1, c)``."""
    east, north = np.ones((n, n - 1), bool), np.ones((n - 1, n), bool)
    seen = np.zeros((n, n), bool)
    stack = [(int(rng.integers(n)), int(rng.integers(n)))]
    seen[stack[0]] = True
    while stack:
        r, c = stack[-1]
        options = [(r + dr, c + dc) for dr, dc in ((0, 1), (0, -1), (1, 0), (-1, 0))
                   if 0 <= r + dr < n and 0 <= c + dc < n and not seen[r + dr, c + dc]]
        if not options:
            stack.pop()
            continue
        rr, cc = options[int(rng.integers(len(options)))]
        if rr == r:
            east[r, min(c, cc)] = False
        else:
            north[min(r, rr), c] = False
        seen[rr, cc] = True
        stack.append((rr, cc))
    for walls in (east, north):
        standing = np.flatnonzero(walls)
        knocked = rng.choice(standing, size=int(round(BRAID * len(standing))), replace=False)
        walls.flat[knocked] = False
    return east, north


def _runs(line: np.ndarray) -> list[tuple[int, int]]:
    """The runs ``[first, last + 1)`` of True in a boolean row."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], line.astype(int), [0]])))
    return list(zip(edges[::2].tolist(), edges[1::2].tolist()))


def wall_entries(east: np.ndarray, north: np.ndarray, side: float) -> list[dict]:
    """The scenario entries of the standing walls, collinear neighbours merged into one wall
    (each run lengthened by half a thickness at both ends, so walls meeting at a corner overlap,
    but not past the world's boundary)."""
    half = THICKNESS / 2
    walls = []
    for c in range(east.shape[1]):  # the vertical line x = (c + 1) side
        x = round((c + 1) * side, 3)
        walls += [((x, a * side - half), (x, b * side + half)) for a, b in _runs(east[:, c])]
    for r in range(north.shape[0]):  # the horizontal line y = (r + 1) side
        y = round((r + 1) * side, 3)
        walls += [((a * side - half, y), (b * side + half, y)) for a, b in _runs(north[r])]
    size = side * east.shape[0]
    return [{"wall": {"start": np.clip(p, 0.0, size).round(3).tolist(), "end": np.clip(q, 0.0, size).round(3).tolist(),
                      "thickness": THICKNESS}} for p, q in walls]


def maze_document(rng: np.random.Generator, name: str, *, size: float, min_start_goal: float,
                  max_time: float) -> dict:
    """The scenario document of one ``maze`` world of ``size`` × ``size`` m drawn from ``rng``
    (module docstring), start and goal at least ``min_start_goal`` m apart."""
    n = int(rng.choice(CELLS))
    side = size / n
    east, north = carve(rng, n)
    centres = (np.stack(np.meshgrid(np.arange(n), np.arange(n)), axis=-1).reshape(-1, 2) + 0.5) * side
    while True:
        start, goal = centres[rng.choice(len(centres), 2, replace=False)]
        if np.hypot(*(goal - start)) >= min_start_goal:
            break
    return {
        "name": name,
        "description": f"random maze world: {n} x {n} cells of {side:.2f} m",
        "world": {"width": size, "height": size},
        "robot": {"x": round(float(start[0]), 3), "y": round(float(start[1]), 3),
                  "theta": round(float(rng.uniform(-np.pi, np.pi)), 3)},
        "goal": {"x": round(float(goal[0]), 3), "y": round(float(goal[1]), 3)},
        "obstacles": wall_entries(east, north, side),
        "max_time": max_time,
    }
