"""Paths a car can drive: hybrid A* on a world's occupancy grid (forward arcs, and backward ones
when asked).

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
6. The search (:func:`fuzzynav.kernels.car_search.search`) stops at the first pose within
   ``reach`` of the goal, or gives up (None) after ``budget`` nodes.
7. With ``reverse`` > 0 every arc is also driven backwards, at ``reverse`` times its cost, plus
   ``gear`` per change of direction (the forward and backward arcs of Reeds & Shepp, Pacific
   J. Math. 1990), so a path may back out of a dead end; ``reverse`` 0 (the default): forward
   arcs only.

Everything is deterministic in the world and the parameters.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fuzzynav.kernels import car_search
from fuzzynav.kernels.records import CarSearch
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

    steerings: int = 7  # steering values in [−α_max, α_max], one arc each
    step: float = 0.2  # m, the length of an arc
    headings: int = 72  # heading bins of a search node
    node_cell: float = 0.1  # m, the cell of a search node
    weight: float = 3.0  # the weight of the clearance cost
    comfort: float = 0.4  # m, the clearance beyond which an arc costs no more
    turn_cost: float = 0.1  # the cost per metre of an arc at full lock
    switch_cost: float = 0.05  # m, the cost of a change of steering
    reach: float = 0.5  # m, the search ends this near the goal
    budget: int = 200_000  # search nodes before it gives up
    reverse: float = 0.0  # the cost factor of a backward arc (0: forward arcs only)
    gear: float = 0.0  # m, the cost of a change of direction

    def settings(self, car: Car, cell: float) -> CarSearch:
        """The compiled search's settings for ``car`` on a clearance grid of ``cell`` m."""
        steerings = np.linspace(-car.max_steering, car.max_steering, self.steerings)
        return CarSearch(curvatures=np.tan(steerings) / car.wheelbase, cell=float(cell), step=float(self.step),
                         node_cell=float(self.node_cell), headings=int(self.headings), weight=float(self.weight),
                         comfort=float(self.comfort), turn_cost=float(self.turn_cost),
                         switch_cost=float(self.switch_cost), reach=float(self.reach), budget=int(self.budget),
                         reverse=float(self.reverse), gear=float(self.gear), shot=0)


@dataclass(frozen=True)
class Plan:
    """A drivable path: poses ``(m, 3)`` every ``spacing`` metres or less, the curvature
    ``(m,)`` (1/m) driven from each pose to the next (0 at the last) and the gear ``(m,)`` that
    reaches each pose (+1 forward, −1 backward; the first pose's is its next's)."""

    poses: np.ndarray
    curvature: np.ndarray
    gear: np.ndarray


def hybrid_astar(world: World, start, goal, car: Car, search: Search = Search(), *,
                 cell: float | None = None, spacing: float = 0.05) -> Plan | None:
    """The hybrid A* path (module docstring) from the pose ``start`` ``(3,)`` to within
    ``search.reach`` of ``goal`` for ``car`` in ``world``, or None (no path within the budget)."""
    cell = cell or default_cell(world)
    grid = occupancy(world, car.radius, cell, car.radius + search.comfort)
    heuristic = cost_to_go(grid, goal, car.radius, weight=search.weight, comfort=search.comfort)
    if heuristic is None:
        return None
    settings = search.settings(car, cell)
    curvatures = settings.curvatures
    xs, ys, ths, parents, primitives, end = car_search.search(grid.clearance, heuristic,
                                                              np.asarray(start, dtype=float)[:3],
                                                              np.asarray(goal, dtype=float)[:2], float(car.radius),
                                                              settings)
    if end < 0:
        return None
    chain = [int(end)]
    while parents[chain[-1]] >= 0:
        chain.append(int(parents[chain[-1]]))
    chain.reverse()
    pieces = int(math.ceil(search.step / spacing))
    poses, kappas, gears = [np.array([xs[0], ys[0], ths[0]])], [], []
    for node in chain[1:]:
        kappa = float(curvatures[primitives[node] % len(curvatures)])
        gear = -1.0 if primitives[node] >= len(curvatures) else 1.0
        parent = parents[node]
        x, y, th = float(xs[parent]), float(ys[parent]), float(ths[parent])
        for j in range(1, pieces + 1):
            poses.append(np.array(car_search.arc_point(x, y, th, kappa, gear * search.step * j / pieces)))
            kappas.append(kappa)
            gears.append(gear)
    kappas.append(0.0)
    return Plan(np.array(poses), np.array(kappas), np.array(gears[:1] + gears if gears else [1.0]))
