"""Hybrid A* search for a car, compiled: the search of :mod:`fuzzynav.world.hybrid_astar` (the
map-aware planner of ``astar-pp``) and of the car route of ``fuzzy-5b`` (the default)
(:mod:`fuzzynav.kernels.car_route`, on the obstacles the robot has seen).

D. Dolgov, S. Thrun, M. Montemerlo, J. Diebel, *Practical search techniques in path planning
for autonomous driving*, AAAI workshop on search in AI and robotics, 2008: continuous poses,
search nodes of a cell and a heading bin, motion primitives that are arcs of fixed curvature.
With ``reverse`` > 0 every arc is also driven backwards, at ``reverse`` times its cost, plus
``gear`` per change of direction — the forward and backward arcs of the shortest car paths of
J. A. Reeds and L. A. Shepp, *Optimal paths for a car that goes both forwards and backwards*,
Pacific J. Math. 145(2), 1990 — so a plan may hold the cusps of a K-turn.

The heuristic is a grid of costs-to-go (Dolgov et al.'s obstacle-aware, heading-blind
heuristic), given whole, or as a :func:`wavefront` that the search runs only as far as the cells
it looks up (:func:`settle`). The wavefront is an A* from the goal towards the search's start
cell (P. E. Hart, N. J. Nilsson, B. Raphael, IEEE Trans. SSC 4(2), 1968): it settles cells in the
order of their cost plus the octile distance to that cell, a consistent estimate (every move
costs at least its length), so each cell it settles has its final cost, the same as a Dijkstra
over the whole grid gives; the estimate is shrunk by ``DIRECTED`` so that rounding cannot close a
cell before a neighbour that would lower it. Dijkstra alone settles the disc of cells nearer the
goal than the start; the A* keeps to the band between the goal and the start that the search's
arcs look up (one target < 0: no direction, the plain Dijkstra of :func:`fuzzynav.kernels.car_route.cost_to_go`).
The wavefront keeps its open cells in a heap of four children an entry, quicker to pop than a
binary one (D. B. Johnson, Inf. Process. Lett. 4(2), 1975): a settled cell's cost, the least over
its neighbours', does not depend on the order of equal keys. The search keeps its nodes in a
binary heap, whose order of equal keys its routes were made with.

With ``shot`` > 0 the search tries Dolgov et al.'s analytic expansion every ``shot`` expanded
nodes (:func:`shot`: the turn and straight line a car takes to the goal on open ground) and ends
with it when it is clear of obstacles and costs no more than the cost-to-go of the node it starts
from, whose key (cost so far plus cost-to-go) is the lowest of the search: no route the search
could still find is cheaper, by the heuristic's account; it stops as soon as its cost so far plus
the distance left to the goal's reach exceeds that bound (:func:`dearer`), when it could only be
refused. The heading-blind heuristic lets a search that starts facing
away from its goal spread over every heading round the start; the expansion ends it once a node
points the right way.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.motion import turn_remainder
from fuzzynav.kernels.records import SearchNodes, Wavefront

FIRST_SLOTS = 4096  # slots of the search's hash table at the start (a power of two)
DIRECTED = 1.0 - 1e-9  # the wavefront's octile estimate is shrunk by this (module docstring)
DIAGONAL = 1.4142135623730951  # a diagonal move's length in cells
FANOUT = 2  # the wavefront's heap: 2 ** 2 children an entry (:func:`push`; the search's: binary)
TOLERANCE = 1e-6  # m, more than the rounding of an arc's end or of a path's cost (:func:`dearer`)


@jit
def arc_point(x, y, theta, kappa, s):
    """The pose after driving ``s`` metres (backwards when ``s`` < 0) on the arc of curvature
    ``kappa`` from (x, y, θ)."""
    return arc_from(x, y, theta, math.cos(theta), math.sin(theta), kappa, s)


@jit
def arc_from(x, y, theta, cos_theta, sin_theta, kappa, s):
    """:func:`arc_point` given cos θ and sin θ (the search computes them once per node, not per
    point of each arc)."""
    if abs(kappa) < 1e-9:
        return x + s * cos_theta, y + s * sin_theta, theta
    end = theta + kappa * s
    return x + (math.sin(end) - sin_theta) / kappa, y - (math.cos(end) - cos_theta) / kappa, end


@jit
def arc_cost(clear, kappa, kmax, backwards, came_by, by, settings):
    """The cost of an arc of curvature ``kappa`` (``kmax`` the largest) whose points' mean
    clearance factor is ``clear`` (≥ 1), driven ``backwards`` or not, by primitive ``by`` after
    ``came_by`` (−1: the start), with the costs of ``settings`` (:func:`search`). Every operation
    rounds monotonically, so a lower ``clear`` never gives a higher cost."""
    cost = settings.step * (clear + settings.turn_cost * abs(kappa) / kmax)
    if backwards:
        cost *= settings.reverse
    if came_by >= 0 and came_by != by:
        cost += settings.switch_cost
        if (came_by >= len(settings.curvatures)) != backwards:
            cost += settings.gear
    return cost


@jit
def shot(clearance, goal, radius, settings, nodes, node, count, spare):
    """(end node, cost): Dolgov et al.'s analytic expansion, on the search's own arcs. From search
    node ``node``, forward arcs, each the one whose end heading points nearest the goal — a full
    lock turn, then the straight line, the shortest path on open ground where the goal lies outside
    the turning circle on its side (inside it the arcs circle until the loop's bound: −1) — while
    every sample of every arc keeps ``radius`` plus ``settings.comfort`` (so each arc costs its
    length and turn only, :func:`arc_cost` with a clearance factor of 1). The arcs are written into
    ``nodes`` (a :class:`~fuzzynav.kernels.records.SearchNodes`) from index ``count`` on; the end
    node is the one within ``reach`` of ``goal``, −1 when an arc is blocked, the arrays are full,
    the goal is not reached within the straight line plus a full circle, or the path would cost
    more than ``spare`` (:func:`dearer`)."""
    curvatures, cell, step, reach = settings.curvatures, settings.cell, settings.step, settings.reach
    ny, nx = clearance.shape
    kinds, samples, kmax = len(curvatures), max(2, int(math.ceil(step / (0.5 * cell)))), np.abs(curvatures).max()
    end_sampled = step * samples / samples == step  # the last sample is then exactly the arc's end
    wanted = radius + settings.comfort
    xs, ys, ths, parents, primitives = nodes
    x, y, theta = xs[node], ys[node], ths[node]
    parent, came_by, cost = node, primitives[node], 0.0
    for k in range(int((math.hypot(goal[0] - x, goal[1] - y) + 2.0 * math.pi / kmax) / step) + 2):
        distance = math.hypot(x - goal[0], y - goal[1])
        if distance <= reach:
            return parent, cost
        if count + k >= xs.shape[0] or dearer(cost, distance - reach, step, spare):
            return -1, cost
        error = math.atan2(goal[1] - y, goal[0] - x) - theta
        best, by = math.inf, 0
        for a in range(kinds):
            miss = abs(turn_remainder(error - curvatures[a] * step + math.pi) - math.pi)
            if miss < best:
                best, by = miss, a
        cos_theta, sin_theta = math.cos(theta), math.sin(theta)
        ex, ey, eth = arc_from(x, y, theta, cos_theta, sin_theta, curvatures[by], step)
        for j in range(1, samples + 1):
            if j == samples and end_sampled:  # the last sample is the end
                px, py = ex, ey
            else:
                px, py, _ = arc_from(x, y, theta, cos_theta, sin_theta, curvatures[by], step * j / samples)
            row, col = int(math.floor(py / cell)), int(math.floor(px / cell))
            if row < 0 or col < 0 or row >= ny or col >= nx or clearance[row, col] < wanted:
                return -1, cost
        cost += arc_cost(1.0, curvatures[by], kmax, False, came_by, by, settings)
        x, y, theta, came_by = ex, ey, turn_remainder(eth), by
        xs[count + k], ys[count + k], ths[count + k] = x, y, theta
        parents[count + k], primitives[count + k], parent = parent, by, count + k
    return -1, cost


@jit
def dearer(cost, gap, step, spare):
    """Would a path that has cost ``cost`` so far, and is still ``gap`` m short of the reach of
    its goal, cost more than ``spare`` in the end, whatever arcs it adds? Each arc costs at least
    its length ``step`` (:func:`arc_cost`, a clearance factor ≥ 1) and brings its end at most
    ``step`` nearer, give or take ``TOLERANCE`` (rounding, an arc's end computed from sines), so
    the rest costs at least ``gap · step / (step + TOLERANCE)``; ``TOLERANCE`` more on ``spare``
    covers the rounding of the sums. A branch-and-bound cut (A. H. Land, A. G. Doig,
    Econometrica 28(3), 1960): it drops no path the search would take."""
    return cost + gap * step / (step + TOLERANCE) > spare + TOLERANCE


@jit
def push(heap_f, heap_n, size, f, node, shift):
    """Add ``node`` with key ``f`` to the heap of ``size`` entries, each with ``2 ** shift``
    children (a d-ary heap, D. B. Johnson, Inf. Process. Lett. 4(2), 1975; ``shift`` 1: the binary
    heap); returns the new size. The entry is sifted up as a hole (the parents moved down, the
    entry written once where it stops): the comparisons and the heap they leave are those of
    swapping it up step by step."""
    i = size
    while i > 0:
        parent = (i - 1) >> shift
        if heap_f[parent] <= f:
            break
        heap_f[i], heap_n[i] = heap_f[parent], heap_n[parent]
        i = parent
    heap_f[i], heap_n[i] = f, node
    return size + 1


@jit
def pop(heap_f, heap_n, size, shift):
    """(node, new size): the entry of the smallest key, taken off the heap of :func:`push`; the
    last entry is sifted down from the root as a hole, to the first of the smallest children."""
    node = heap_n[0]
    size -= 1
    f, last = heap_f[size], heap_n[size]
    i = 0
    while True:
        first, smallest, low = (i << shift) + 1, i, f
        for child in range(first, min(first + (1 << shift), size)):
            if heap_f[child] < low:
                smallest, low = child, heap_f[child]
        if smallest == i:
            break
        heap_f[i], heap_n[i] = heap_f[smallest], heap_n[smallest]
        i = smallest
    heap_f[i], heap_n[i] = f, last
    return node, size


@jit
def slot(table, key):
    """The slot of ``key`` in the open-addressing hash set ``table`` (size a power of two, −1:
    empty): where it is, else the empty slot where it goes."""
    mask = table.shape[0] - 1
    s = (key * 2654435761) & mask
    while table[s] != key and table[s] >= 0:
        s = (s + 1) & mask
    return s


@jit
def grown(table, best, closed):
    """The search's hash table (keys, best costs, closed flags) with twice the slots, every entry kept."""
    size = 2 * table.shape[0]
    keys, costs, shut = np.full(size, -1, np.int64), np.full(size, np.inf), np.zeros(size, np.bool_)
    for s in range(table.shape[0]):
        if table[s] >= 0:
            at = slot(keys, table[s])
            keys[at], costs[at], shut[at] = table[s], best[s], closed[s]
    return keys, costs, shut


@jit
def uniform(clearance, cell, start, end, length, kappa):
    """The clearance shared by every cell of ``clearance`` (of ``cell`` m) that a point of the arc
    of ``length`` m and curvature ``kappa`` from ``start`` to ``end`` can lie in; −1 when they
    differ or reach past the grid. The arc keeps within its sagitta, at most length²·|κ|/8, of its
    chord, so within that of the box the chord spans (plus ``TOLERANCE`` for the rounding of each
    end, twice): where those cells share one clearance, the search need not compute the samples to know
    their cost."""
    ny, nx = clearance.shape
    margin = length * length * abs(kappa) / 8.0 + 2.0 * TOLERANCE
    low_row = int(math.floor((min(start[1], end[1]) - margin) / cell))
    high_row = int(math.floor((max(start[1], end[1]) + margin) / cell))
    low_col = int(math.floor((min(start[0], end[0]) - margin) / cell))
    high_col = int(math.floor((max(start[0], end[0]) + margin) / cell))
    if low_row < 0 or low_col < 0 or high_row >= ny or high_col >= nx:
        return -1.0
    value = clearance[low_row, low_col]
    for row in range(low_row, high_row + 1):
        for col in range(low_col, high_col + 1):
            if clearance[row, col] != value:
                return -1.0
    return value


NEIGHBOURS = ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1))


@jit
def octile(row, col, toward_row, toward_col, cell):
    """The wavefront's estimate of the cost from cell (row, col) to (``toward_row``,
    ``toward_col``): the length of the shortest 8-neighbour move chain between them on an empty
    grid of ``cell`` m, shrunk by ``DIRECTED``; 0 without a direction (``toward_row`` < 0)."""
    if toward_row < 0:
        return 0.0
    dr, dc = abs(row - toward_row), abs(col - toward_col)
    return DIRECTED * cell * (max(dr, dc) + (DIAGONAL - 1.0) * min(dr, dc))


@jit
def wavefront(clearance, cell, goal_row, goal_col, radius, weight, comfort, toward):
    """A :class:`~fuzzynav.kernels.records.Wavefront` from the goal's cell over ``clearance``
    (ny, nx) of ``cell`` m, nothing settled yet: by A* towards the cell ``toward`` (row, column)
    (module docstring; a row < 0: Dijkstra) over 8 neighbours on the cells that keep ``radius``,
    each move's length times ``1 + weight · max(0, comfort − (clearance − radius))`` (the
    search's own clearance cost, without the heading)."""
    toward_row, toward_col = toward
    ny, nx = clearance.shape
    cost = np.full(ny * nx, np.inf)
    heap_f, heap_n = np.empty(8 * ny * nx + 1), np.empty(8 * ny * nx + 1, np.int64)
    goal = goal_row * nx + goal_col
    cost[goal] = 0.0
    size = np.full(1, push(heap_f, heap_n, 0, octile(goal_row, goal_col, toward_row, toward_col, cell), goal, FANOUT),
                   np.int64)
    return Wavefront(clearance, cell, radius, weight, comfort, cost, np.zeros(ny * nx, dtype=np.bool_), heap_f,
                     heap_n, size, toward_row, toward_col)


@jit
def settle(front, target):
    """Run the wavefront ``front`` until cell ``target`` (row · nx + column) is settled, its cost
    final (inf: no way to the goal), or, with ``target`` < 0, over the whole grid."""
    clearance, cell, radius, weight, comfort = front.clearance, front.cell, front.radius, front.weight, front.comfort
    cost, done, heap_f, heap_n = front.cost, front.done, front.heap_f, front.heap_n
    toward_row, toward_col = front.toward_row, front.toward_col
    ny, nx = clearance.shape
    size = front.size[0]
    while size > 0 and (target < 0 or not done[target]):
        here, size = pop(heap_f, heap_n, size, FANOUT)
        if done[here]:
            continue
        done[here] = True
        row, col = here // nx, here % nx
        for dr, dc in NEIGHBOURS:
            r, c = row + dr, col + dc
            if r < 0 or c < 0 or r >= ny or c >= nx or done[r * nx + c] or clearance[r, c] < radius:
                continue  # off the grid, settled (its cost final: no move lowers it) or blocked
            there = r * nx + c
            step = cell * (DIAGONAL if dr != 0 and dc != 0 else 1.0)
            total = cost[here] + step * (1.0 + weight * max(0.0, comfort - (clearance[r, c] - radius)))
            if total < cost[there]:
                cost[there] = total
                size = push(heap_f, heap_n, size, total + octile(r, c, toward_row, toward_col, cell), there, FANOUT)
    front.size[0] = size


@jit
def search(clearance, heuristic, start, goal, radius, settings, front=None):
    """Hybrid A* from the pose ``start`` to within ``settings.reach`` of ``goal``, every sample of
    every arc in a cell whose clearance is at least ``radius`` (m), on the grid ``clearance``
    (ny, nx) of ``settings.cell`` m whose lower-left corner is the origin; ``heuristic`` (ny, nx):
    the cost-to-go of each cell (inf: unreachable), or the costs of the :func:`wavefront`
    ``front`` (reshaped), which the search then settles as far as it looks; ``settings``: a
    :class:`~fuzzynav.kernels.records.CarSearch` (:mod:`fuzzynav.world.hybrid_astar` tells the
    meaning of its fields; ``reverse`` 0: forward arcs only; ``shot`` > 0: analytic expansions, the
    module docstring). Returns the node arrays (x, y, θ, parent, primitive) and the goal node, the
    end of an analytic expansion or a node the search reached (−1: none within the budget of nodes)."""
    curvatures, cell, step, node_cell = settings.curvatures, settings.cell, settings.step, settings.node_cell
    weight, comfort, reach, reverse = settings.weight, settings.comfort, settings.reach, settings.reverse
    bins, budget, kinds = int(settings.headings), int(settings.budget), len(curvatures)
    primitives_per_node = 2 * kinds if reverse > 0 else kinds
    ny, nx = clearance.shape
    node_cols = int(nx * cell / node_cell) + 1
    # the best cost and closed flag of each search node seen, by key, in a hash table sized by what
    # the search has seen (doubled when half full), not by the grid or the budget: a plan costs
    # what it searches, and a small search's table stays in the processor's cache
    table, best, closed = np.full(FIRST_SLOTS, -1, np.int64), np.full(FIRST_SLOTS, np.inf), np.zeros(FIRST_SLOTS, np.bool_)
    entries = 0
    xs, ys, ths, gs = np.empty(budget), np.empty(budget), np.empty(budget), np.empty(budget)
    parents, primitives, keys = np.empty(budget, np.int64), np.empty(budget, np.int64), np.empty(budget, np.int64)
    heap_f, heap_n = np.empty(budget), np.empty(budget, np.int64)
    samples = max(2, int(math.ceil(step / (0.5 * cell))))
    end_sampled = step * samples / samples == step  # the last sample is then exactly the arc's end
    kmax = np.abs(curvatures).max()
    xs[0], ys[0], ths[0], gs[0], parents[0], primitives[0] = start[0], start[1], start[2], 0.0, -1, -1
    keys[0] = -1
    count, size, expanded = 1, push(heap_f, heap_n, 0, 0.0, 0, 1), 0
    while size > 0:
        lowest = heap_f[0]
        node, size = pop(heap_f, heap_n, size, 1)
        if keys[node] >= 0:
            at = slot(table, keys[node])
            if closed[at] or gs[node] > best[at]:
                continue
            closed[at] = True
        x, y, theta, g = xs[node], ys[node], ths[node], gs[node]
        if math.hypot(x - goal[0], y - goal[1]) <= reach:
            return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], node
        if settings.shot > 0 and expanded > 0 and expanded % settings.shot == 0:  # (the start's key: 0)
            end, cost = shot(clearance, goal, radius, settings, SearchNodes(xs, ys, ths, parents, primitives), node,
                             count, lowest - g)
            if end >= 0 and g + cost <= lowest:  # no dearer than the node's estimate, the lowest key
                return xs[:end + 1], ys[:end + 1], ths[:end + 1], parents[:end + 1], primitives[:end + 1], end
        expanded += 1
        cos_theta, sin_theta = math.cos(theta), math.sin(theta)
        for a in range(primitives_per_node):
            kappa, backwards = curvatures[a % kinds], a >= kinds
            length = -step if backwards else step
            # the arc's end first: an arc into a closed node is dropped before its points are tested
            ex, ey, eth = arc_from(x, y, theta, cos_theta, sin_theta, kappa, length)
            eth = turn_remainder(eth)
            key = ((int(ey / node_cell) * node_cols + int(ex / node_cell)) * bins
                   + int(eth / (2.0 * math.pi) * bins) % bins)
            at = slot(table, key)
            if closed[at] or g + arc_cost(1.0, kappa, kmax, backwards, primitives[node], a, settings) >= best[at]:
                continue  # the arc costs at least this (each of its points adds at least 1), so no better
            penalty, blocked = 0.0, False
            shared = uniform(clearance, cell, (x, y), (ex, ey), step, kappa)
            for j in range(1, samples + 1):
                if shared >= radius:  # every sample lies in a cell of this clearance: none is computed
                    clear = shared
                else:
                    if j == samples and end_sampled:  # the last sample is the end
                        px, py = ex, ey
                    else:
                        px, py, _ = arc_from(x, y, theta, cos_theta, sin_theta, kappa, length * j / samples)
                    row, col = int(math.floor(py / cell)), int(math.floor(px / cell))
                    if row < 0 or col < 0 or row >= ny or col >= nx or clearance[row, col] < radius:
                        blocked = True
                        break
                    clear = clearance[row, col]
                penalty += 1.0 + weight * max(0.0, comfort - (clear - radius))
            if blocked:
                continue
            row, col = int(math.floor(ey / cell)), int(math.floor(ex / cell))
            if front is not None and not front.done[row * nx + col]:
                settle(front, row * nx + col)
            h = heuristic[row, col]
            if not math.isfinite(h):
                continue
            cost = arc_cost(penalty / samples, kappa, kmax, backwards, primitives[node], a, settings)
            if g + cost >= best[at]:
                continue
            if count >= budget:
                return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], -1
            if table[at] != key:
                entries += 1
            table[at], best[at] = key, g + cost
            if 2 * entries > table.shape[0]:
                table, best, closed = grown(table, best, closed)
            xs[count], ys[count], ths[count], gs[count] = ex, ey, eth, g + cost
            parents[count], primitives[count], keys[count] = node, a, key
            size = push(heap_f, heap_n, size, g + cost + h, count, 1)
            count += 1
    return xs[:count], ys[:count], ths[:count], parents[:count], primitives[:count], -1
