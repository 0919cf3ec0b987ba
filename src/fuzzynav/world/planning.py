"""Shortest collision-free paths of a disc robot on a world's occupancy grid.

Used twice, written once: by the map-aware reference navigator ``astar-pp`` (which plans on the
map inflated by its body and a margin, with a cost for passing close to obstacles) and by the
benchmark's path-length ratio (the plain shortest path of the robot's disc, no extra cost).

1. Grid: square cells of side ``cell``; a cell is free when a disc of ``radius`` around its
   centre touches neither an obstacle nor the boundary (:meth:`World.clearance`).
2. Search: 8-connected moves between free cells (a diagonal move only when both cells it cuts
   past are free), each costing its length times ``1 + weight · max(0, comfort − clearance)``
   (``weight = 0``: plain length). The optimal grid path is the one A* returns (P. E. Hart,
   N. J. Nilsson, B. Raphael, *A formal basis for the heuristic determination of minimum cost
   paths*, IEEE Trans. SSC 4(2), 1968); it is found here with the compiled Dijkstra search of
   :func:`scipy.sparse.csgraph.dijkstra`, which is A* with a zero heuristic and gives the same path.
3. Any-angle shortening ("string pulling"): from each vertex, jump to the furthest later vertex
   whose straight segment stays in free cells. The result is within a few percent of the true
   shortest path of the disc, and never shorter than the straight line.

Everything is deterministic in the world and the parameters (no randomness).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fuzzynav.world.world import World

MAX_GRID_CELLS = 1_000_000  # cells of a planning grid at most (default_cell coarsens larger worlds)


@dataclass(frozen=True)
class Grid:
    """Occupancy grid of a world for a disc: ``free (ny, nx)``, ``clearance (ny, nx)`` (m, cell
    centres to the nearest obstacle or boundary), cell side ``cell`` (m)."""

    free: np.ndarray
    clearance: np.ndarray
    cell: float

    def index(self, point) -> tuple[int, int]:
        """(row, column) of the cell holding ``point`` (clipped to the grid)."""
        ny, nx = self.free.shape
        return (min(max(int(point[1] / self.cell), 0), ny - 1), min(max(int(point[0] / self.cell), 0), nx - 1))

    def centre(self, rows, cols) -> np.ndarray:
        """World coordinates ``(k, 2)`` of the centres of cells ``(rows, cols)``."""
        return np.column_stack([(np.asarray(cols) + 0.5) * self.cell, (np.asarray(rows) + 0.5) * self.cell])


def default_cell(world: World) -> float:
    """Grid cell (m): 0.1 m, or 0.05 m among posts thinner than 0.3 m (BARN's), where the free
    strips between posts are narrow. (A thin wall needs no finer cell: inflated by the robot's
    radius it blocks a band wider than a cell's diagonal.) A world so large that the grid would
    pass :data:`MAX_GRID_CELLS` (about: the rows round up) gets cells just large enough to stay
    within it — over 100 m × 100 m at 0.1 m, over 50 m × 50 m at 0.05 m: its memory and time stay
    bounded, passages narrower than about a cell may be seen as closed, and a cell's clearance,
    measured at its centre, may overstate its corners' by up to half its diagonal."""
    radii = [float(o.radius) for o in world.obstacles if o.kind == "circle"]
    fine = 0.05 if radii and min(radii) < 0.15 else 0.1
    return max(fine, math.sqrt(world.width * world.height / MAX_GRID_CELLS))


def clearance_grid(world: World, cell: float, floor: float, cap: float) -> np.ndarray:
    """Clearance (m) of every cell centre ``(ny, nx)``, exact where it lies in [``floor``, ``cap``]:
    a cell below ``floor`` gets an upper bound (< ``floor``), one above ``cap`` a lower bound
    (≥ ``cap``). Clearance is 1-Lipschitz, so it is first measured on cells 4× larger (within half
    a coarse diagonal h of every fine cell) and only the fine cells whose coarse value c has
    c + h ≥ ``floor`` and c − h < ``cap`` are measured exactly: a band along the obstacles' edges."""
    xs = np.arange(cell / 2, world.width, cell)
    ys = np.arange(cell / 2, world.height, cell)
    ny, nx = len(ys), len(xs)
    k = 4
    coarse_y = (np.arange(-(-ny // k)) * k + k / 2) * cell
    coarse_x = (np.arange(-(-nx // k)) * k + k / 2) * cell
    cy, cx = np.meshgrid(coarse_y, coarse_x, indexing="ij")
    coarse = world.clearance(np.column_stack([cx.ravel(), cy.ravel()])).reshape(cy.shape)
    coarse = np.repeat(np.repeat(coarse, k, axis=0), k, axis=1)[:ny, :nx]
    h = k * cell / np.sqrt(2)
    result = np.where(coarse + h < floor, coarse + h, coarse - h)
    band = (coarse + h >= floor) & (coarse - h < cap)
    if band.any():
        rows, cols = np.nonzero(band)
        result[band] = world.clearance(np.column_stack([xs[cols], ys[rows]]))
    return result


def occupancy(world: World, radius: float, cell: float, cap: float | None = None) -> Grid:
    """The :class:`Grid` of ``world`` for a disc of ``radius`` (m); clearances exact up to ``cap``
    (default ``radius``: enough to tell free cells from blocked ones)."""
    clearance = clearance_grid(world, cell, radius, radius if cap is None else max(cap, radius))
    return Grid(clearance >= radius, clearance, float(cell))


_MOVES = ((0, 1), (1, 0), (1, 1), (1, -1))  # the other four are their reverses (undirected graph)


def _graph(grid: Grid, radius: float, weight: float, comfort: float):
    ny, nx = grid.free.shape
    penalty = 1.0 + weight * np.maximum(0.0, comfort - (grid.clearance - radius))
    ids = np.arange(ny * nx).reshape(ny, nx)
    rows, cols, costs = [], [], []
    for dr, dc in _MOVES:
        r0, r1 = max(0, -dr), ny - max(0, dr)
        c0, c1 = max(0, -dc), nx - max(0, dc)
        a = (slice(r0, r1), slice(c0, c1))
        b = (slice(r0 + dr, r1 + dr), slice(c0 + dc, c1 + dc))
        ok = grid.free[a] & grid.free[b]
        if dr and dc:  # no corner cutting: both cells the diagonal passes must be free
            ok &= grid.free[r0 + dr:r1 + dr, c0:c1] & grid.free[r0:r1, c0 + dc:c1 + dc]
        length = grid.cell * float(np.hypot(dr, dc))
        rows.append(ids[a][ok])
        cols.append(ids[b][ok])
        costs.append(length * 0.5 * (penalty[a][ok] + penalty[b][ok]))
    from scipy import sparse  # imported when first needed (not at start-up)

    n = ny * nx
    return sparse.coo_matrix((np.concatenate(costs), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(n, n)).tocsr()


def _nearest_free(grid: Grid, point) -> tuple[int, int] | None:
    """The free cell closest to ``point`` within two cells of it (None when there is none)."""
    r, c = grid.index(point)
    best, best_d = None, np.inf
    for dr in range(-2, 3):
        for dc in range(-2, 3):
            rr, cc = r + dr, c + dc
            if 0 <= rr < grid.free.shape[0] and 0 <= cc < grid.free.shape[1] and grid.free[rr, cc]:
                d = float(np.hypot(*(grid.centre([rr], [cc])[0] - point)))
                if d < best_d:
                    best, best_d = (rr, cc), d
    return best


def _visible(grid: Grid, a, b_points) -> np.ndarray:
    """For each end point in ``b_points`` ``(k, 2)``: whether the segment from ``a`` stays in free cells."""
    lengths = np.hypot(*(b_points - a).T)
    samples = max(2, int(np.ceil(lengths.max() / (grid.cell / 2))) + 1)
    u = np.linspace(0.0, 1.0, samples)
    points = a + u[None, :, None] * (b_points - a)[:, None, :]
    ny, nx = grid.free.shape
    rows = np.clip((points[..., 1] / grid.cell).astype(int), 0, ny - 1)
    cols = np.clip((points[..., 0] / grid.cell).astype(int), 0, nx - 1)
    return grid.free[rows, cols].all(axis=1)


def shorten(grid: Grid, path: np.ndarray) -> np.ndarray:
    """String pulling (module docstring, step 3): the vertices kept from ``path`` ``(n, 2)``."""
    kept, i = [path[0]], 0
    while i < len(path) - 1:
        later = path[i + 1:]
        seen = np.flatnonzero(_visible(grid, path[i], later))
        i = i + 1 + (int(seen[-1]) if seen.size else 0)
        kept.append(path[i])
    return np.array(kept)


def shortest_path(world: World, start, goal, radius: float, *, cell: float | None = None,
                  weight: float = 0.0, comfort: float = 0.0, grid: Grid | None = None) -> np.ndarray | None:
    """The shortened shortest path ``(m, 2)`` from ``start`` to ``goal`` of a disc of ``radius``
    in ``world`` (its first point is ``start``, its last ``goal``), or None when none exists.

    ``weight`` and ``comfort`` (m) add the clearance cost of the module docstring; with a
    weight the path is shortened only where that keeps it at ``comfort`` from obstacles.
    """
    start, goal = np.asarray(start, dtype=float)[:2], np.asarray(goal, dtype=float)[:2]
    if grid is None:
        grid = occupancy(world, radius, cell or default_cell(world), radius + comfort if weight > 0 else None)
    a, b = _nearest_free(grid, start), _nearest_free(grid, goal)
    if a is None or b is None:
        return None
    nx = grid.free.shape[1]
    source, target = a[0] * nx + a[1], b[0] * nx + b[1]
    from scipy.sparse import csgraph  # imported when first needed (not at start-up)

    graph = _graph(grid, radius, weight, comfort)
    distance, previous = csgraph.dijkstra(graph, directed=False, indices=source, return_predecessors=True)
    if not np.isfinite(distance[target]):
        return None
    chain = [target]
    while chain[-1] != source:
        chain.append(int(previous[chain[-1]]))
    ids = np.array(chain[::-1])
    path = np.vstack([start, grid.centre(ids // nx, ids % nx), goal])
    if weight > 0:  # shortcuts keep the comfort distance (vertices that lack it are kept)
        return shorten(Grid(grid.clearance >= radius + comfort, grid.clearance, grid.cell), path)
    return shorten(grid, path)


def cost_to_go(grid: Grid, goal, radius: float, *, weight: float = 0.0, comfort: float = 0.0) -> np.ndarray | None:
    """The search cost (m, with the clearance cost of the module docstring) from every cell of
    ``grid`` ``(ny, nx)`` to the free cell nearest ``goal`` (inf where unreachable), or None
    when no free cell lies near the goal: the heuristic of :mod:`fuzzynav.world.hybrid_astar`."""
    target = _nearest_free(grid, np.asarray(goal, dtype=float)[:2])
    if target is None:
        return None
    from scipy.sparse import csgraph  # imported when first needed (not at start-up)

    nx = grid.free.shape[1]
    distance = csgraph.dijkstra(_graph(grid, radius, weight, comfort), directed=False,
                                indices=target[0] * nx + target[1])
    return distance.reshape(grid.free.shape)
