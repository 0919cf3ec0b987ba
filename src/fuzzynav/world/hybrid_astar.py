"""Paths a car can drive: hybrid A* on a world's occupancy grid (forward driving only).

D. Dolgov, S. Thrun, M. Montemerlo, J. Diebel, *Practical search techniques in path planning
for autonomous driving*, AAAI workshop on search in AI and robotics, 2008. The map-aware
reference navigator ``astar-pp`` plans with it once per world.

1. States are continuous poses (x, y, θ); two states are the same search node when they share a
   cell of side ``node_cell`` and one of ``headings`` heading bins (the first state to reach a
   node keeps it, unless a cheaper one comes, as in Dolgov et al.).
2. Motion primitives: from a pose, drive ``step`` metres forward on the arc of each of
   ``steerings`` steering values in [−α_max, α_max] (curvature tan α / l, eq IV.1 with α fixed) —
   so every path respects the turning radius l / tan α_max.
3. An arc is collision-free when every sample along it (every half grid cell) lies in a cell
   whose centre clearance is at least ``radius`` (the body plus a margin): the disc swept along
   the arc, checked on the map inflated by ``radius``.
4. Cost: arc length times ``1 + weight · max(0, comfort − (clearance − radius))`` averaged over
   its samples (the clearance cost of :mod:`fuzzynav.world.planning`), plus ``turn_cost`` per metre
   at full lock (scaled by |α| / α_max) and ``switch_cost`` when the steering changes.
5. Heuristic: the cost-to-go of the 2-D grid search with the same radius and clearance cost
   (:func:`fuzzynav.world.planning.cost_to_go`), which knows the obstacles but not the heading
   (Dolgov et al.'s "non-holonomic-without-obstacles" heuristic is not used).
6. The search stops at the first pose within ``reach`` of the goal, or gives up (None) after
   ``budget`` nodes.

Everything is deterministic in the world and the parameters.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.world.planning import cost_to_go, default_cell, occupancy
from fuzzynav.world.world import World


@dataclass(frozen=True)
class Car:
    """The planned body: disc ``radius`` (m, the robot's plus a margin), ``wheelbase`` l (m) and
    steering limit ``max_steering`` α_max (rad)."""

    radius: float
    wheelbase: float
    max_steering: float

    @property
    def max_curvature(self) -> float:
        """1 / turning radius = tan α_max / l (1/m)."""
        return math.tan(self.max_steering) / self.wheelbase


@dataclass(frozen=True)
class Search:
    """Search parameters (module docstring)."""

    steerings: int = 7
    step: float = 0.2
    headings: int = 72
    node_cell: float = 0.1
    weight: float = 3.0
    comfort: float = 0.4
    turn_cost: float = 0.1
    switch_cost: float = 0.05
    reach: float = 0.5
    budget: int = 200_000


@jit
def _arc_point(x, y, theta, kappa, s):
    """The pose after driving ``s`` metres on the arc of curvature ``kappa`` from (x, y, θ)."""
    if abs(kappa) < 1e-9:
        return x + s * math.cos(theta), y + s * math.sin(theta), theta
    end = theta + kappa * s
    return x + (math.sin(end) - math.sin(theta)) / kappa, y - (math.cos(end) - math.cos(theta)) / kappa, end


@jit
def _push(heap_f, heap_n, size, f, node):
    i = size
    heap_f[i], heap_n[i] = f, node
    while i > 0:
        parent = (i - 1) // 2
        if heap_f[parent] <= heap_f[i]:
            break
        heap_f[parent], heap_f[i] = heap_f[i], heap_f[parent]
        heap_n[parent], heap_n[i] = heap_n[i], heap_n[parent]
        i = parent
    return size + 1


@jit
def _pop(heap_f, heap_n, size):
    node = heap_n[0]
    size -= 1
    heap_f[0], heap_n[0] = heap_f[size], heap_n[size]
    i = 0
    while True:
        left, smallest = 2 * i + 1, i
        if left < size and heap_f[left] < heap_f[smallest]:
            smallest = left
        if left + 1 < size and heap_f[left + 1] < heap_f[smallest]:
            smallest = left + 1
        if smallest == i:
            break
        heap_f[smallest], heap_f[i] = heap_f[i], heap_f[smallest]
        heap_n[smallest], heap_n[i] = heap_n[i], heap_n[smallest]
        i = smallest
    return node, size


@jit
def _search(clearance, cell, heuristic, start, goal, curvatures, numbers):
    """The hybrid A* search of the module docstring. ``numbers``: radius, step, node_cell,
    headings, weight, comfort, turn_cost, switch_cost, reach, budget. Returns the node arrays
    (x, y, θ, parent, primitive) and the goal node (−1: none within the budget)."""
    radius, step, node_cell, headings, weight, comfort, turn_cost, switch_cost, reach, budget = numbers
    bins, budget = int(headings), int(budget)
    ny, nx = clearance.shape
    node_rows, node_cols = int(ny * cell / node_cell) + 1, int(nx * cell / node_cell) + 1
    best = np.full(node_rows * node_cols * bins, np.inf)
    closed = np.zeros(node_rows * node_cols * bins, dtype=np.bool_)
    xs, ys, ths, gs = np.empty(budget), np.empty(budget), np.empty(budget), np.empty(budget)
    parents, primitives, keys = np.empty(budget, np.int64), np.empty(budget, np.int64), np.empty(budget, np.int64)
    heap_f, heap_n = np.empty(budget), np.empty(budget, np.int64)
    samples = max(2, int(math.ceil(step / (0.5 * cell))))
    kmax = np.abs(curvatures).max()
    xs[0], ys[0], ths[0], gs[0], parents[0], primitives[0] = start[0], start[1], start[2], 0.0, -1, -1
    keys[0] = -1
    count, size = 1, _push(heap_f, heap_n, 0, 0.0, 0)
    while size > 0:
        node, size = _pop(heap_f, heap_n, size)
        if keys[node] >= 0:
            if closed[keys[node]] or gs[node] > best[keys[node]]:
                continue
            closed[keys[node]] = True
        x, y, theta, g = xs[node], ys[node], ths[node], gs[node]
        if math.hypot(x - goal[0], y - goal[1]) <= reach:
            return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], node
        for a in range(len(curvatures)):
            kappa = curvatures[a]
            penalty, blocked = 0.0, False
            for j in range(1, samples + 1):
                px, py, _ = _arc_point(x, y, theta, kappa, step * j / samples)
                row, col = int(math.floor(py / cell)), int(math.floor(px / cell))
                if row < 0 or col < 0 or row >= ny or col >= nx or clearance[row, col] < radius:
                    blocked = True
                    break
                penalty += 1.0 + weight * max(0.0, comfort - (clearance[row, col] - radius))
            if blocked:
                continue
            px, py, pth = _arc_point(x, y, theta, kappa, step)
            pth = pth % (2.0 * math.pi)
            h = heuristic[int(math.floor(py / cell)), int(math.floor(px / cell))]
            if not math.isfinite(h):
                continue
            cost = step * (penalty / samples + turn_cost * abs(kappa) / kmax)
            if primitives[node] >= 0 and primitives[node] != a:
                cost += switch_cost
            key = ((int(py / node_cell) * node_cols + int(px / node_cell)) * bins
                   + int(pth / (2.0 * math.pi) * bins) % bins)
            if closed[key] or g + cost >= best[key]:
                continue
            if count >= budget:
                return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], -1
            best[key] = g + cost
            xs[count], ys[count], ths[count], gs[count] = px, py, pth, g + cost
            parents[count], primitives[count], keys[count] = node, a, key
            size = _push(heap_f, heap_n, size, g + cost + h, count)
            count += 1
    return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], -1


@dataclass(frozen=True)
class Plan:
    """A drivable path: poses ``(m, 3)`` every ``spacing`` metres or less and the curvature
    ``(m,)`` (1/m) driven from each pose to the next (0 at the last)."""

    poses: np.ndarray
    curvature: np.ndarray


def hybrid_astar(world: World, start, goal, car: Car, search: Search = Search(), *,
                 cell: float | None = None, spacing: float = 0.05) -> Plan | None:
    """The hybrid A* path (module docstring) from the pose ``start`` ``(3,)`` to within
    ``search.reach`` of ``goal`` for ``car`` in ``world``, or None (no path within the budget)."""
    cell = cell or default_cell(world)
    grid = occupancy(world, car.radius, cell, car.radius + search.comfort)
    heuristic = cost_to_go(grid, goal, car.radius, weight=search.weight, comfort=search.comfort)
    if heuristic is None:
        return None
    steerings = np.linspace(-car.max_steering, car.max_steering, search.steerings)
    curvatures = np.tan(steerings) / car.wheelbase
    numbers = np.array([car.radius, search.step, search.node_cell, search.headings, search.weight, search.comfort,
                        search.turn_cost, search.switch_cost, search.reach, search.budget], dtype=float)
    xs, ys, ths, parents, primitives, end = _search(grid.clearance, cell, heuristic,
                                                    np.asarray(start, dtype=float)[:3],
                                                    np.asarray(goal, dtype=float)[:2], curvatures, numbers)
    if end < 0:
        return None
    chain = [int(end)]
    while parents[chain[-1]] >= 0:
        chain.append(int(parents[chain[-1]]))
    chain.reverse()
    pieces = int(math.ceil(search.step / spacing))
    poses, kappas = [np.array([xs[0], ys[0], ths[0]])], []
    for node in chain[1:]:
        kappa = float(curvatures[primitives[node]])
        parent = parents[node]
        x, y, th = float(xs[parent]), float(ys[parent]), float(ths[parent])
        for j in range(1, pieces + 1):
            poses.append(np.array(_arc_point(x, y, th, kappa, search.step * j / pieces)))
            kappas.append(kappa)
    kappas.append(0.0)
    return Plan(np.array(poses), np.array(kappas))
