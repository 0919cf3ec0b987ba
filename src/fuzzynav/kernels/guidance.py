"""Route guidance, compiled: the layer of ``fuzzy-5b`` (the default) (:mod:`fuzzynav.control.through_gaps`)
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
body off what the memory has not seen yet.

With ``guide_car`` on, a route the car can drive is tried before the grid route, from the
robot's pose (:func:`fuzzynav.kernels.car_route.first_leg`: hybrid A* with forward and backward
arcs, Dolgov et al. 2008, Reeds & Shepp 1990, keeping the radius plus ``guide_car_room``; the
grid route is the fallback when the search gives up within ``guide_car_budget`` nodes). Where
the plan's next ``guide_car_ahead`` m keep ``guide_car_tight`` m more than the radius from every
remembered point and hold no cusp, the route point is that far along it and the navigator
drives. Elsewhere — in a passage barely wider than the body, or in a K-turn — the layer drives
the plan's first arc itself (:func:`manoeuvre`: backward at the recovery's backing speed,
forward at ``guide_car_speed``, while the recovery's safety test passes) and plans again at its
end. A route point that a newly seen point blocks (nearer than the body's radius) is planned
again at once. While the recovery manoeuvre drives, or when the loop escape begins or ends
(:func:`drop`), no arc is kept and no plan is made: the route is planned again from the pose the
robot has when the layer may drive again. Names of ``params`` and ``state`` columns: :mod:`fuzzynav.kernels.layers`.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import car_route, recovery, route, sightings
from fuzzynav.kernels.layers import NO_PHASE, PARAM, STATE
from fuzzynav.kernels.records import CarSearch


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
def search_settings(params):
    """The car route's search settings (a :class:`~fuzzynav.kernels.records.CarSearch`) of the
    layers' ``params``: the curvatures of the steering values, the grid cell and the search's
    ``guide_car_…`` settings (forward arcs only for a robot that cannot reverse)."""
    steering = params[PARAM.guide_car_steering]
    curvatures = np.tan(np.linspace(-steering, steering, int(params[PARAM.guide_car_steerings]))) / params[PARAM.wheelbase]
    reverse = params[PARAM.guide_car_reverse] if params[PARAM.max_reverse_speed] > 0 else 0.0
    return CarSearch(curvatures=curvatures, cell=params[PARAM.guide_car_cell], step=params[PARAM.guide_car_step],
                     node_cell=params[PARAM.guide_car_node], headings=int(params[PARAM.guide_car_headings]),
                     weight=params[PARAM.guide_car_weight], comfort=params[PARAM.guide_car_comfort],
                     turn_cost=params[PARAM.guide_car_turn], switch_cost=params[PARAM.guide_car_switch],
                     reach=params[PARAM.guide_car_reach], budget=int(params[PARAM.guide_car_budget]),
                     reverse=reverse, gear=params[PARAM.guide_car_gear])


@jit
def car(state, params, seen, robot, radius):
    """Plan the car route (module docstring) of ``robot`` (a :class:`~fuzzynav.kernels.records.Robot`)
    from (x, y, θ) to (tx, ty) round the points ``seen`` (a
    :class:`~fuzzynav.kernels.records.Sightings`): the route point, or the arc the layer drives;
    False when the search gives up."""
    tx, ty = robot.tx, robot.ty
    search = search_settings(params)
    found, manoeuvre, backwards, px, py, kappa, run = car_route.first_leg(
        seen, robot, radius + params[PARAM.guide_car_room], radius, search, params[PARAM.guide_car_ahead],
        params[PARAM.guide_car_tight])
    if found and manoeuvre:
        state[STATE.guide_gear] = -1.0 if backwards else 1.0
        state[STATE.guide_kappa], state[STATE.guide_run] = kappa, run
        state[STATE.guide_driven] = 0.0
    elif found and math.hypot(px - tx, py - ty) > 1e-9:
        state[STATE.guide_x], state[STATE.guide_y] = px, py
    return found


@jit
def drop(state):
    """Another layer takes over (the recovery manoeuvre, or the loop escape's start or end): forget
    the arc pending, and plan again at the next chance, from the pose the robot then has."""
    state[STATE.guide_gear], state[STATE.guide_planned] = 0.0, -math.inf


@jit
def plan(state, params, seen, robot, t, radius):
    """Plan the route point of ``robot`` (a :class:`~fuzzynav.kernels.records.Robot`) again when
    ``guide_replan`` s have passed, or when a point of ``seen`` (a
    :class:`~fuzzynav.kernels.records.Sightings`) blocks it; never while the recovery drives
    (module docstring)."""
    points, count, x, y, tx, ty = seen.points, seen.count, robot.x, robot.y, robot.tx, robot.ty
    if state[STATE.phase] != NO_PHASE:
        drop(state)
        return
    gx, gy = state[STATE.guide_x], state[STATE.guide_y]
    blocked = gx == gx and sightings.clearance(points, count, gx, gy) < radius
    waiting = t - state[STATE.guide_planned] < params[PARAM.guide_replan] - 1e-9 and not blocked
    if waiting or state[STATE.guide_gear] != 0.0:
        return
    state[STATE.guide_x], state[STATE.guide_y], state[STATE.guide_planned] = math.nan, math.nan, t
    if line_free(points, count, x, y, tx, ty, radius + params[PARAM.guide_room], params[PARAM.guide_direct]):
        return
    if params[PARAM.guide_car] != 0.0 and car(state, params, seen, robot, radius):
        return
    for room in (PARAM.guide_room, PARAM.guide_narrow, PARAM.guide_bare):
        found, rx, ry = route.target(seen, x, y, tx, ty, radius + params[room], params[PARAM.guide_ahead],
                                     params[PARAM.guide_cell])
        if found:
            state[STATE.guide_x], state[STATE.guide_y] = rx, ry
            return


@jit
def manoeuvre(state, params, points, count, x, y, theta, dt):
    """(moving, α, V): this step of the car route's arc, if the layer is driving one (module
    docstring); when the arc is done or the step is not safe, the route is planned again at the
    next step."""
    if state[STATE.guide_gear] == 0.0:
        return False, 0.0, 0.0
    backwards = state[STATE.guide_gear] < 0
    speed = -min(params[PARAM.v_back], params[PARAM.max_reverse_speed]) if backwards else params[PARAM.guide_car_speed]
    if (state[STATE.guide_driven] < state[STATE.guide_run] - 1e-9
            and recovery.safe(params, points, count, x, y, theta, speed, dt)):
        state[STATE.guide_driven] += abs(speed) * dt
        return True, math.atan(state[STATE.guide_kappa] * params[PARAM.wheelbase]), speed
    state[STATE.guide_gear], state[STATE.guide_planned] = 0.0, -math.inf
    return False, 0.0, 0.0


@jit
def aim(state, params, seen, robot, t, radius):
    """The target the navigator is given at (x, y, θ) on its way to (tx, ty) at time ``t``
    (``robot`` a :class:`~fuzzynav.kernels.records.Robot`, ``seen`` the remembered points, a
    :class:`~fuzzynav.kernels.records.Sightings`; ``radius``: the body's): towards the route point,
    at the target's distance; the target itself without a route point."""
    x, y, tx, ty = robot.x, robot.y, robot.tx, robot.ty
    plan(state, params, seen, robot, t, radius)
    if state[STATE.guide_x] != state[STATE.guide_x]:
        return tx, ty
    ox, oy = state[STATE.guide_x] - x, state[STATE.guide_y] - y
    length = math.hypot(ox, oy)
    if length < 1e-9:
        return tx, ty
    scale = max(math.hypot(tx - x, ty - y), length) / length
    return x + ox * scale, y + oy * scale
