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

import math
import statistics
import sys

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.robot.sensors import LIDAR_ANGLES
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.generate import generate_world
from fuzzynav.world.planning import Grid, cost_to_go

MOVES = [(dr, dc, math.hypot(dr, dc)) for dr in (-1, 0, 1) for dc in (-1, 0, 1) if dr or dc]


def cells_near(shape, cell: float, points: np.ndarray, grow: float) -> tuple[np.ndarray, np.ndarray]:
    """(rows, columns) of the cells of a grid of ``shape`` whose centres lie within ``grow`` of
    any of ``points`` (P, 2)."""
    reach = int(math.ceil(grow / cell)) + 1
    offsets = np.array([(dr, dc) for dr in range(-reach, reach + 1) for dc in range(-reach, reach + 1)])
    base = np.floor(points[:, ::-1] / cell).astype(int)  # (row, column) = (y, x) / cell
    cells = (base[:, None, :] + offsets[None]).reshape(-1, 2)
    inside = (cells >= 0).all(axis=1) & (cells[:, 0] < shape[0]) & (cells[:, 1] < shape[1])
    near = np.linalg.norm((cells[:, ::-1] + 0.5) * cell - np.repeat(points, len(offsets), axis=0), axis=1) < grow
    return tuple(np.unique(cells[inside & near], axis=0).T)


def route(cost: np.ndarray, free: np.ndarray, start: tuple[int, int], cell: float) -> list[tuple[int, int]]:
    """The cells from ``start`` down ``cost`` (the cost to go over the ``free`` cells, the moves of
    :func:`fuzzynav.world.planning.cost_to_go`: no corner cutting) to the goal."""
    cells, (r, c) = [start], start
    ny, nx = cost.shape
    while cost[r, c] > 0 and len(cells) < cost.size:
        steps = [(cost[r + dr, c + dc] + w * cell, (r + dr, c + dc)) for dr, dc, w in MOVES
                 if 0 <= r + dr < ny and 0 <= c + dc < nx and free[r + dr, c + dc]
                 and (not (dr and dc) or (free[r + dr, c] and free[r, c + dc]))]
        r, c = min(steps)[1]
        cells.append((r, c))
    return cells


def explore(scenario, cell: float, margin: float, reach: float) -> tuple[float, float]:
    """(path of the idealised robot without a map, shortest grid route on the whole map), m."""
    world = scenario.world
    grow = DEFAULT_PARAMS.radius + margin
    ny, nx = int(round(world.height / cell)), int(round(world.width / cell))
    rows, cols = np.mgrid[0:ny, 0:nx]
    centres = np.column_stack([(cols.ravel() + 0.5) * cell, (rows.ravel() + 0.5) * cell])
    truly = (world.clearance(centres) >= grow).reshape(ny, nx)
    flat = np.zeros((ny, nx))
    goal = np.asarray(scenario.goal.position, dtype=float)
    whole = Grid(truly, flat, cell)
    here = whole.index(scenario.start[:2])
    full = cost_to_go(whole, goal, 0.0)[here]
    known = np.ones((ny, nx), dtype=bool)  # unseen cells are free
    heading, travelled, plan = float(scenario.start[2]), 0.0, []
    for _ in range(20 * (nx + ny)):
        position = whole.centre([here[0]], [here[1]])[0]
        if np.hypot(*(position - goal)) < cell:
            return travelled, full
        ranges = world.ranges(np.array([[*position, heading]]), LIDAR_ANGLES, reach)[0]
        hits = ranges < reach - 1e-6
        angles = heading + LIDAR_ANGLES[hits]
        seen = position + ranges[hits, None] * np.column_stack([np.cos(angles), np.sin(angles)])
        near = cells_near(known.shape, cell, seen, grow) if len(seen) else (np.array([], int), np.array([], int))
        fresh = known[near]
        known[near] = False
        known[here] = True
        cut = {(int(r), int(c)) for r, c, f in zip(*near, fresh) if f} & set(plan)
        if not plan or cut:
            cost = cost_to_go(Grid(known, flat, cell), goal, 0.0)
            if cost is None or not np.isfinite(cost[here]):
                return math.nan, full
            plan = route(cost, known, here, cell)[1:]
            if not plan:
                return travelled, full
        step = plan.pop(0)
        delta = whole.centre([step[0]], [step[1]])[0] - position
        travelled += float(np.hypot(*delta))
        heading, here = math.atan2(delta[1], delta[0]), step
    return math.nan, full


def main(argv=None) -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
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
