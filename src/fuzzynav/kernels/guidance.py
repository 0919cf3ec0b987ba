"""Route guidance, compiled: the layer of ``fuzzy-5b-gap-robust`` (:mod:`fuzzynav.control.through_gaps`)
that aims the navigator along the shortest route to its target round the obstacle points seen so
far (:mod:`fuzzynav.kernels.sightings`), unseen space assumed free (:func:`fuzzynav.kernels.route.target`,
the freespace assumption of D*, Stentz 1994).

Every ``guide_replan`` s the route point is planned again: none when the straight line to the
target keeps the body's radius plus ``guide_room`` from every remembered point for
``guide_direct`` m (the grid route's 8-neighbour steps wander off the straight line in open
space); else the point ``guide_ahead`` m along the route on a grid of ``guide_cell`` m keeping
the radius plus ``guide_room``, else ``guide_narrow``, else ``guide_bare`` (none when no route
keeps even that). Between plans the point is kept. The navigator is given a target in the
direction of the route point, at the target's distance (at least the point's), so its goal
seeking and gap finding steer towards the passage the route takes while its behaviours keep the
body off what the memory has not seen yet. Names of ``params`` and ``state`` columns:
:mod:`fuzzynav.kernels.layers`.
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels import route
from fuzzynav.kernels.layers import (GUIDE_AHEAD, GUIDE_BARE, GUIDE_CELL, GUIDE_DIRECT, GUIDE_NARROW, GUIDE_PLANNED,
                                     GUIDE_REPLAN, GUIDE_ROOM, GUIDE_X, GUIDE_Y)


@jit
def line_free(points, count, x, y, tx, ty, room, direct):
    """Does the straight line from (x, y) towards (tx, ty) keep ``room`` from the first ``count``
    of ``points`` for ``direct`` m (or up to the target)?"""
    length = math.hypot(tx - x, ty - y)
    if count == 0 or length < 1e-9:
        return True
    ux, uy = (tx - x) / length, (ty - y) / length
    reach = min(length, direct)
    for p in range(count):
        along = min(max((points[p, 0] - x) * ux + (points[p, 1] - y) * uy, 0.0), reach)
        if math.hypot(points[p, 0] - (x + along * ux), points[p, 1] - (y + along * uy)) < room:
            return False
    return True


@jit
def plan(state, params, points, count, x, y, tx, ty, t, radius):
    """Plan the route point again when ``guide_replan`` s have passed (module docstring)."""
    if t - state[GUIDE_PLANNED] < params[GUIDE_REPLAN] - 1e-9:
        return
    state[GUIDE_X], state[GUIDE_Y], state[GUIDE_PLANNED] = math.nan, math.nan, t
    if line_free(points, count, x, y, tx, ty, radius + params[GUIDE_ROOM], params[GUIDE_DIRECT]):
        return
    for room in (GUIDE_ROOM, GUIDE_NARROW, GUIDE_BARE):
        found, rx, ry = route.target(points, count, x, y, tx, ty, radius + params[room], params[GUIDE_AHEAD],
                                     params[GUIDE_CELL])
        if found:
            state[GUIDE_X], state[GUIDE_Y] = rx, ry
            return


@jit
def aim(state, params, points, count, x, y, tx, ty, t, radius):
    """The target the navigator is given at (x, y) on its way to (tx, ty) at time ``t``
    (``radius``: the body's): towards the route point, at the target's distance; the target
    itself without a route point."""
    plan(state, params, points, count, x, y, tx, ty, t, radius)
    if state[GUIDE_X] != state[GUIDE_X]:
        return tx, ty
    ox, oy = state[GUIDE_X] - x, state[GUIDE_Y] - y
    length = math.hypot(ox, oy)
    if length < 1e-9:
        return tx, ty
    scale = max(math.hypot(tx - x, ty - y), length) / length
    return x + ox * scale, y + oy * scale
