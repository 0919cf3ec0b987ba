"""The generated family ``forest``: thin posts scattered over the whole world, every two of them
far enough apart for the robot to pass between.

The posts' centres are a Poisson-disc sample of the world (R. Bridson, *Fast Poisson disk
sampling in arbitrary dimensions*, ACM SIGGRAPH 2007 sketches): no two closer than a spacing
drawn per world in ``SPACING``, and the sample maximal (no further post fits), so the posts
cover the world evenly, with no clearing but round the start and the goal. Each post is a disc
of radius drawn in ``RADII`` (thin, as the posts of a BARN world: D. Perille, A. Truong, X. Xiao,
P. Stone, *Benchmarking metric ground navigation*, IEEE SSRR 2020). The narrowest gap between
two posts, spacing less two of the largest radii, is wider than the robot's footprint; the
family is checked solvable for that footprint plus ``MARGIN``. Start and goal are drawn as the
other families' are (:mod:`fuzzynav.world.generate`), and posts near them are left out.
"""

from __future__ import annotations

import numpy as np

SPACING = (1.1, 1.8)  # m, the least distance between two posts' centres, drawn per world
RADII = (0.05, 0.15)  # m, a post's radius
MARGIN = 0.1  # m beyond the footprint's radius in the solvability check
CANDIDATES = 30  # Bridson's k: tries round an active point before it is retired


def poisson_disc(rng: np.random.Generator, width: float, height: float, spacing: float) -> np.ndarray:
    """Bridson's maximal Poisson-disc sample ``(m, 2)`` of the ``width`` × ``height`` rectangle:
    points at least ``spacing`` apart, each new one tried in the annulus [spacing, 2 spacing]
    round an active point, ``CANDIDATES`` tries before that point is retired."""
    cell = spacing / np.sqrt(2)  # a background-grid cell holds at most one point
    nx, ny = int(np.ceil(width / cell)), int(np.ceil(height / cell))
    grid = -np.ones((ny, nx), int)
    points = [rng.uniform((0.0, 0.0), (width, height))]
    grid[int(points[0][1] / cell), int(points[0][0] / cell)] = 0
    active = [0]
    while active:
        k = int(rng.integers(len(active)))
        angle = rng.uniform(0.0, 2 * np.pi, CANDIDATES)
        reach = spacing * np.sqrt(rng.uniform(1.0, 4.0, CANDIDATES))  # uniform over the annulus' area
        tries = points[active[k]] + reach[:, None] * np.column_stack([np.cos(angle), np.sin(angle)])
        for p in tries:
            if not (0.0 <= p[0] < width and 0.0 <= p[1] < height):
                continue
            c, r = int(p[0] / cell), int(p[1] / cell)
            near = grid[max(r - 2, 0):r + 3, max(c - 2, 0):c + 3]
            near = near[near >= 0]
            if near.size and (np.hypot(*(np.asarray(points)[near] - p).T) < spacing).any():
                continue
            grid[r, c] = len(points)
            active.append(len(points))
            points.append(p)
            break
        else:
            active.pop(k)
    return np.array(points)


def forest_entries(rng: np.random.Generator, width: float, height: float, keep_clear, clearance: float) -> list[dict]:
    """The posts (scenario entries) of one forest of ``width`` × ``height`` m drawn from ``rng``,
    none within ``clearance`` m of a point of ``keep_clear`` ``(k, 2)``."""
    centres = poisson_disc(rng, width, height, float(rng.uniform(*SPACING)))
    radii = rng.uniform(*RADII, len(centres))
    away = np.hypot(*(centres[:, None, :] - np.asarray(keep_clear)[None, :, :]).transpose(2, 0, 1)).min(axis=1)
    keep = away - radii >= clearance
    return [{"circle": {"center": c.round(3).tolist(), "radius": round(float(r), 3)}}
            for c, r in zip(centres[keep], radii[keep])]
