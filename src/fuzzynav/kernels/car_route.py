"""A route the car can drive round the obstacles seen so far, compiled: the car route of the
route guidance of ``fuzzy-5b`` (the default) (:mod:`fuzzynav.kernels.guidance`).

Hybrid A* (D. Dolgov, S. Thrun, M. Montemerlo, J. Diebel, AAAI workshop 2008;
:func:`fuzzynav.kernels.car_search.search`) with forward and backward arcs at the navigator's
full lock (J. A. Reeds, L. A. Shepp, Pacific J. Math. 1990), planned from the robot's pose on
the remembered obstacle points (:mod:`fuzzynav.kernels.sightings`), every unseen place assumed
free (the freespace assumption of D*, A. Stentz, ICRA 1994):

1. Grid: cells of ``cell`` m over the box holding the robot, the target and the points, plus
   ``MARGIN``; each cell's clearance is the distance from its centre to the nearest point
   (capped at the radius plus ``comfort``).
2. Heuristic: the cost-to-go of each cell to the target's over 8 neighbours on the cells that
   keep the radius, each move's length times ``1 + weight · max(0, comfort − (clearance −
   radius))`` — the search's own clearance cost, without the heading — settled only as far as
   the search looks it up, by an A* from the target towards the robot's cell
   (:func:`fuzzynav.kernels.car_search.wavefront`; the costs Dijkstra gives).
3. The search keeps the radius given (the body's plus a margin), or the robot's present
   clearance less ``SLACK`` when that is smaller (a robot already close to a post may still
   drive away from it), never less than the body's.

:func:`plan` returns the plan's poses, :func:`leg` what the guidance needs of it from any of its
poses on (the guidance keeps a plan and reuses it): the leg's gear, whether it is part of a
manoeuvre (a K-turn), the point ``ahead`` m along it (or its end, the first cusp), the curvature
of its first arc and how far the plan keeps that arc.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import car_search, sightings
from fuzzynav.kernels.motion import turn_remainder
from fuzzynav.kernels.route import MAX_CELLS

MARGIN = 1.5  # m of grid round the robot, the target and the points
SLACK = 0.02  # m: the plan keeps the robot's present clearance less this, when below the radius asked


@jit
def clearance_grid(points, count, low_x, low_y, nx, ny, cell, cap):
    """(ny, nx): the distance from each cell's centre to the nearest of the first ``count``
    ``points``, capped at ``cap``."""
    grid = np.full((ny, nx), cap)
    reach = int(cap / cell) + 1
    for p in range(count):
        px, py = points[p, 0] - low_x, points[p, 1] - low_y
        ci, cj = int(px / cell), int(py / cell)
        for j in range(max(cj - reach, 0), min(cj + reach, ny - 1) + 1):
            dy = (j + 0.5) * cell - py
            for i in range(max(ci - reach, 0), min(ci + reach, nx - 1) + 1):
                dx, near = (i + 0.5) * cell - px, grid[j, i]
                if dx * dx + dy * dy < near * near * (1.0 + 1e-9):  # else math.hypot ≥ the value there
                    d = math.hypot(dx, dy)
                    if d < near:
                        grid[j, i] = d
    return grid


@jit
def cost_to_go(clearance, cell, goal_row, goal_col, radius, weight, comfort):
    """(ny, nx): the heuristic of the module docstring over the whole grid (inf where the target
    cannot be reached); :func:`plan` settles only the cells its search looks up."""
    front = car_search.wavefront(clearance, cell, goal_row, goal_col, radius, weight, comfort, (-1, -1))
    car_search.settle(front, -1)
    return front.cost.reshape(clearance.shape)


@jit
def kept(seen, robot, radius, body):
    """The radius :func:`plan` keeps (module docstring, 3.): ``radius``, or the robot's present
    clearance from the points ``seen`` less ``SLACK`` when that is smaller, never below ``body``."""
    return max(body, min(radius, sightings.clearance(seen.points, seen.count, robot.x, robot.y) - SLACK))


@jit
def frame(seen, robot, radius, body, cell):
    """(radius kept, low x, low y, nx, ny) of :func:`plan`'s search: the radius of :func:`kept`
    and the grid (1.) of ``cell`` m round the robot, its target and the points ``seen``."""
    points, count, x, y, tx, ty = seen.points, seen.count, robot.x, robot.y, robot.tx, robot.ty
    radius = kept(seen, robot, radius, body)
    low_x, low_y, high_x, high_y = min(x, tx), min(y, ty), max(x, tx), max(y, ty)
    for p in range(count):
        low_x, low_y = min(low_x, points[p, 0]), min(low_y, points[p, 1])
        high_x, high_y = max(high_x, points[p, 0]), max(high_y, points[p, 1])
    low_x, low_y = low_x - MARGIN, low_y - MARGIN
    nx, ny = int(math.ceil((high_x + MARGIN - low_x) / cell)), int(math.ceil((high_y + MARGIN - low_y) / cell))
    return radius, low_x, low_y, nx, ny


@jit
def plan(seen, robot, radius, body, search):
    """(found, poses (m, 3), primitives (m,)): the plan of ``robot`` (a
    :class:`~fuzzynav.kernels.records.Robot`) from the pose (x, y, θ) to within ``reach`` of
    (tx, ty) round the points ``seen`` (a :class:`~fuzzynav.kernels.records.Sightings`), world
    frame, its first pose the start (primitive −1), each next one reached by the arc of
    ``primitives`` (:func:`fuzzynav.kernels.car_search.search` with the settings ``search``, a
    :class:`~fuzzynav.kernels.records.CarSearch`, keeping ``radius``, or less as the module
    docstring says, never below ``body``); ``found`` False when the search gives up, or when
    its grid would exceed :data:`fuzzynav.kernels.route.MAX_CELLS`."""
    points, count, x, y, theta, tx, ty = seen.points, seen.count, robot.x, robot.y, robot.theta, robot.tx, robot.ty
    cell, comfort = search.cell, search.comfort
    radius, low_x, low_y, nx, ny = frame(seen, robot, radius, body, cell)
    if nx * ny > MAX_CELLS:  # a target too far for a grid: no plan (the search gives up)
        return False, np.array([[x, y, theta]]), np.full(1, -1, np.int64)
    clearance = clearance_grid(points, count, low_x, low_y, nx, ny, cell, radius + comfort)
    start = np.array([x - low_x, y - low_y, turn_remainder(theta)])
    front = car_search.wavefront(clearance, cell, int((ty - low_y) / cell), int((tx - low_x) / cell), radius,
                                 search.weight, comfort, (int(math.floor(start[1] / cell)),
                                                          int(math.floor(start[0] / cell))))
    goal = np.array([tx - low_x, ty - low_y])
    xs, ys, ths, parents, primitives, end = car_search.search(clearance, front.cost.reshape(ny, nx), start, goal, radius,
                                                              search, front)
    chain = [max(end, 0)]
    while parents[chain[-1]] >= 0:
        chain.append(parents[chain[-1]])
    poses, kinds = np.empty((len(chain), 3)), np.empty(len(chain), np.int64)
    for k in range(len(chain)):
        node = chain[len(chain) - 1 - k]
        poses[k, 0], poses[k, 1], poses[k, 2] = xs[node] + low_x, ys[node] + low_y, ths[node]
        kinds[k] = primitives[node]
    return end >= 0, poses, kinds


@jit
def leg(route, start, end, seen, search, body, ahead, tight):
    """(manoeuvre, backwards, px, py, kappa, run) of the plan ``route`` (poses x, y, θ and the
    primitive reaching each, a row each, as :func:`plan` gives them) from its pose ``start`` to
    its pose ``end`` − 1, given at least two: ``backwards`` tells the first leg's gear and
    ``manoeuvre`` whether it is part of a K-turn (backward, or forward to a cusp less than
    ``ahead`` m away) or passes within ``body`` + ``tight`` of a point ``seen``; (px, py) is the
    point ``ahead`` m along the first leg or its end, and ``kappa`` the curvature of the first
    arc, which the plan keeps for ``run`` m (``search``: the :class:`~fuzzynav.kernels.records.CarSearch`
    of the plan)."""
    points, count, curvatures = seen.points, seen.count, search.curvatures
    kinds, step = len(curvatures), search.step
    first = int(route[start + 1, 3])
    backwards = first >= kinds
    kappa = curvatures[first % kinds]
    run, same, travelled, cusp, narrow = 0.0, True, 0.0, False, False
    px, py = route[start + 1, 0], route[start + 1, 1]
    for k in range(start + 1, end):
        if (route[k, 3] >= kinds) != backwards:
            cusp = True
            break
        same = same and int(route[k, 3]) == first
        if same:
            run += step
        if travelled < ahead:
            px, py, travelled = route[k, 0], route[k, 1], travelled + step
            narrow = narrow or sightings.clearance(points, count, px, py) < body + tight
    return backwards or (cusp and travelled < ahead) or narrow, backwards, px, py, kappa, run
