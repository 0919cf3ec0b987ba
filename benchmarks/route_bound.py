"""How long a route can a navigator that does not know the map hope for? An idealised bound for
the floor-plan families, beside the map-aware `astar-pp` (docs/results/default-navigator.md,
*How much of the gap is exploration?*).

An idealised robot without a map — a point in the configuration space (cells of ``--cell`` m, the
obstacles grown by the body's radius and ``--margin``), turning on the spot, with the default
lidar (271 beams over 270°, ``--range`` m, the thesis' D_max 4 m) — plans the shortest 8-connected
grid route to the goal on what it has seen, taking every unseen cell as free (the optimistic
assumption of D* Lite and of `fuzzy-5b`'s route guidance: S. Koenig, M. Likhachev, "D* Lite",
AAAI 2002), steps one cell along it, senses, and plans again whenever a newly seen obstacle cuts
the route. Its path over the shortest grid route on the whole map is the factor that
exploration alone costs, whatever the navigator's kinematics and speed; against it `fuzzy-5b`'s
path ratio (`summary.md` of `bench`) says how much its driving adds.

    python benchmarks/route_bound.py --family office --seed 1 --n 40
    python benchmarks/route_bound.py --family maze --seed 2 --n 40

Prints the median, quartiles and mean of the factor, and the worlds where the robot finds no
route on what it has seen (none expected: the families are solvable).
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys

import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from fuzzynav.robot.sensors import LIDAR_ANGLES
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.generate import generate_world

MOVES = [(dx, dy, math.hypot(dx, dy)) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]


class Grid:
    """The cells of a world, their 8-connected edges and the shortest distances to one cell."""

    def __init__(self, width: float, height: float, cell: float):
        self.cell, self.nx, self.ny = cell, int(round(width / cell)), int(round(height / cell))
        ix, iy = np.meshgrid(np.arange(self.nx), np.arange(self.ny), indexing="ij")
        self.centres = np.column_stack([(ix.ravel() + 0.5) * cell, (iy.ravel() + 0.5) * cell])
        tails, heads, weights = [], [], []
        for dx, dy, w in MOVES:
            ok = (ix + dx >= 0) & (ix + dx < self.nx) & (iy + dy >= 0) & (iy + dy < self.ny)
            tails.append((ix * self.ny + iy)[ok])
            heads.append(((ix + dx) * self.ny + iy + dy)[ok])
            weights.append(np.full(ok.sum(), w * cell))
        self.tails, self.heads, self.weights = (np.concatenate(v) for v in (tails, heads, weights))

    def index(self, point) -> int:
        return int(min(int(point[0] / self.cell), self.nx - 1) * self.ny + min(int(point[1] / self.cell), self.ny - 1))

    def distances(self, blocked: np.ndarray, goal: int) -> np.ndarray:
        """Shortest 8-connected distance of every cell to ``goal`` avoiding ``blocked`` cells."""
        keep = ~blocked[self.tails] & ~blocked[self.heads]
        n = self.nx * self.ny
        graph = csr_matrix((self.weights[keep], (self.tails[keep], self.heads[keep])), shape=(n, n))
        return dijkstra(graph, directed=False, indices=goal)

    def around(self, points: np.ndarray, grow: float) -> np.ndarray:
        """The cells whose centres lie within ``grow`` of any of ``points`` (P, 2)."""
        reach = int(math.ceil(grow / self.cell)) + 1
        offsets = np.array([(dx, dy) for dx in range(-reach, reach + 1) for dy in range(-reach, reach + 1)])
        base = np.floor(points / self.cell).astype(int)
        cells = (base[:, None, :] + offsets[None]).reshape(-1, 2)
        inside = (cells[:, 0] >= 0) & (cells[:, 0] < self.nx) & (cells[:, 1] >= 0) & (cells[:, 1] < self.ny)
        near = np.linalg.norm((cells + 0.5) * self.cell - np.repeat(points, len(offsets), axis=0), axis=1) < grow
        return np.unique(cells[inside & near, 0] * self.ny + cells[inside & near, 1])

    def neighbours(self, k: int):
        ix, iy = divmod(k, self.ny)
        for dx, dy, w in MOVES:
            if 0 <= ix + dx < self.nx and 0 <= iy + dy < self.ny:
                yield (ix + dx) * self.ny + iy + dy, w * self.cell


def route(grid: Grid, dist: np.ndarray, start: int) -> list[int]:
    """The cells from ``start`` down the distances to the goal."""
    cells, k = [start], start
    while dist[k] > 0 and len(cells) < grid.nx * grid.ny:
        k = min(grid.neighbours(k), key=lambda nw: nw[1] + dist[nw[0]])[0]
        cells.append(k)
    return cells


def explore(scenario, cell: float, margin: float, reach: float) -> tuple[float, float]:
    """(path of the idealised robot without a map, shortest grid route on the whole map), m."""
    world = scenario.world
    grid = Grid(world.width, world.height, cell)
    grow = DEFAULT_PARAMS.radius + margin
    truly = world.clearance(grid.centres) < grow
    start, goal = grid.index(scenario.start[:2]), grid.index(scenario.goal.position)
    truly[[start, goal]] = False
    full = grid.distances(truly, goal)[start]
    seen = np.zeros(len(truly), dtype=bool)
    here, heading, travelled = start, float(scenario.start[2]), 0.0
    plan: list[int] = []
    for _ in range(20 * (grid.nx + grid.ny)):
        if here == goal:
            return travelled, full
        position = grid.centres[here]
        ranges = world.ranges(np.array([[*position, heading]]), LIDAR_ANGLES, reach)[0]
        hits = ranges < reach - 1e-6
        angles = heading + LIDAR_ANGLES[hits]
        new = position + ranges[hits, None] * np.column_stack([np.cos(angles), np.sin(angles)])
        now = grid.around(new, grow)
        fresh = now[~seen[now]]
        seen[fresh] = True
        seen[[here, goal]] = False
        if not plan or np.isin(plan, fresh).any():
            dist = grid.distances(seen, goal)
            if not np.isfinite(dist[here]):
                return math.nan, full
            plan = route(grid, dist, here)[1:]
        step = plan.pop(0)
        delta = grid.centres[step] - position
        travelled += float(np.hypot(*delta))
        heading, here = math.atan2(delta[1], delta[0]), step
    return math.nan, full


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--family", default="office")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--n", type=int, default=40)
    parser.add_argument("--cell", type=float, default=0.1)
    parser.add_argument("--margin", type=float, default=0.05)
    parser.add_argument("--range", type=float, default=4.0, dest="reach")
    args = parser.parse_args(argv)
    factors, lost = [], []
    for i in range(args.n):
        path, full = explore(generate_world(args.family, args.seed, i), args.cell, args.margin, args.reach)
        if math.isnan(path):
            lost.append(i)
        else:
            factors.append(path / full)
        print(f"{args.family}-{args.seed}-{i:03d}: {path:.1f} m / {full:.1f} m", file=sys.stderr)
    q = statistics.quantiles(factors, n=4)
    print(f"{args.family} seed {args.seed}, {len(factors)} worlds: exploration factor median {statistics.median(factors):.2f} "
          f"(quartiles {q[0]:.2f}, {q[2]:.2f}; mean {statistics.mean(factors):.2f}); no route found: {lost}")


if __name__ == "__main__":
    main()
