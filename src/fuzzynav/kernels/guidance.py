"""Route guidance, compiled: the layer of ``fuzzy-5b`` (the default) (:mod:`fuzzynav.control.through_gaps`)
that aims the navigator along the shortest route to its target round the obstacle points seen so
far (:mod:`fuzzynav.kernels.sightings`), unseen space assumed free (:func:`fuzzynav.kernels.route.target`,
the freespace assumption of D*, Stentz 1994).

Every ``guide_replan`` s the route point is planned again: none when the straight line to the
target keeps the body's radius plus ``guide_room`` from every remembered point for
``guide_direct`` m (the grid route's 8-neighbour steps wander off the straight line in open
space) and the target is within ``guide_off_heading`` of the heading (0: anywhere; a target
beside or behind the car gets a route, which turns it round on arcs it can drive); else the point ``guide_ahead``
m along the route on a grid of ``guide_cell`` m keeping the radius plus ``guide_room``, else
``guide_narrow``, else ``guide_bare`` (none when no route keeps even that). Between plans the point is kept. The navigator is given a target in the
direction of the route point, at the target's distance (at least the point's), so its goal
seeking and gap finding steer towards the passage the route takes while its behaviours keep the
body off what the memory has not seen yet.

With ``guide_car`` on, a route the car can drive is tried before the grid route, from the
robot's pose (:func:`fuzzynav.kernels.car_route.plan`: hybrid A* with forward and backward
arcs, Dolgov et al. 2008, Reeds & Shepp 1990, keeping the radius plus ``guide_car_room``; the
grid route is the fallback when the search gives up within ``guide_car_budget`` nodes; a search
to a target off the heading tries an analytic expansion every ``guide_car_shot`` expanded nodes,
:func:`fuzzynav.kernels.car_search.shot`). Where
the plan's next ``guide_car_ahead`` m keep ``guide_car_tight`` m more than the radius from every
remembered point and hold no cusp, the route point is that far along it and the navigator
drives. Elsewhere — in a passage barely wider than the body, or in a K-turn — the layer drives
the plan's first arc itself (:func:`manoeuvre`: backward at the recovery's backing speed,
forward at ``guide_car_speed`` or the pace on its arc, :func:`fuzzynav.kernels.pace.car_pace`,
while the recovery's safety test passes) and plans again at its end (with ``guide_car_chain``,
:mod:`fuzzynav.kernels.robust` plans at once when a backward arc ends, so the next arc starts in
the same step). A route point that a newly seen point blocks (nearer than the body's radius) is
planned again at once.

The car route's poses are kept (``route_slots`` of them, in the robot's state row) and a plan
reuses them instead of searching again while they stay valid (:func:`reused`): searched less
than ``guide_car_reuse`` s ago, for the same target, the robot still on the route (within
``guide_car_stray`` m and ``guide_car_swerve`` rad of its nearest pose on the present leg), and
no point seen since it was searched within its radius plus ``guide_car_keep`` of the rest of it
— planning only when the route is invalidated, as D* Lite (Koenig & Likhachev 2002) repairs a
plan only where new sightings touch it, here by a plain new search. While the recovery manoeuvre drives, or when the loop escape begins or ends
(:func:`drop`), no arc is kept and no plan is made: the route is planned again from the pose the
robot has when the layer may drive again. Names of ``params`` and ``state`` columns: :mod:`fuzzynav.kernels.layers`.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import car_route, recovery, route, sightings
from fuzzynav.kernels.layers import NO_PHASE, PARAM, STATE
from fuzzynav.kernels.motion import wrap
from fuzzynav.kernels.records import CarSearch
from fuzzynav.kernels.row_blocks import route_of


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
def search_settings(params, shot):
    """The car route's search settings (a :class:`~fuzzynav.kernels.records.CarSearch`) of the
    layers' ``params``: the curvatures of the steering values, the grid cell and the search's
    ``guide_car_…`` settings (forward arcs only for a robot that cannot reverse), analytic
    expansions every ``shot`` expanded nodes (0: none)."""
    steering = params[PARAM.guide_car_steering]
    curvatures = np.tan(np.linspace(-steering, steering, int(params[PARAM.guide_car_steerings]))) / params[PARAM.wheelbase]
    reverse = params[PARAM.guide_car_reverse] if params[PARAM.max_reverse_speed] > 0 else 0.0
    return CarSearch(curvatures=curvatures, cell=params[PARAM.guide_car_cell], step=params[PARAM.guide_car_step],
                     node_cell=params[PARAM.guide_car_node], headings=int(params[PARAM.guide_car_headings]),
                     weight=params[PARAM.guide_car_weight], comfort=params[PARAM.guide_car_comfort],
                     turn_cost=params[PARAM.guide_car_turn], switch_cost=params[PARAM.guide_car_switch],
                     reach=params[PARAM.guide_car_reach], budget=int(params[PARAM.guide_car_budget]),
                     reverse=reverse, gear=params[PARAM.guide_car_gear], shot=shot)


@jit
def follow(state, params, seen, robot, radius, at):
    """Take the kept car route from its pose ``at`` on (:func:`fuzzynav.kernels.car_route.leg`):
    the arc the layer drives, or the route point (none when the robot is within reach of the
    target); returns whether it is a manoeuvre."""
    route, count = route_of(params, state), int(state[STATE.guide_poses])
    state[STATE.guide_at] = at
    if count - at < 2:
        return False
    manoeuvre, backwards, px, py, kappa, run = car_route.leg(route, at, count, seen, search_settings(params, 0), radius,
                                                             params[PARAM.guide_car_ahead], params[PARAM.guide_car_tight])
    if manoeuvre:
        state[STATE.guide_gear] = -1.0 if backwards else 1.0
        state[STATE.guide_kappa], state[STATE.guide_run] = kappa, run
        state[STATE.guide_driven] = 0.0
    elif math.hypot(px - robot.tx, py - robot.ty) > 1e-9:
        state[STATE.guide_x], state[STATE.guide_y] = px, py
    return manoeuvre


@jit
def car(state, params, seen, robot, t, radius):
    """Plan the car route (module docstring) of ``robot`` (a :class:`~fuzzynav.kernels.records.Robot`)
    from (x, y, θ) to (tx, ty) round the points ``seen`` (a
    :class:`~fuzzynav.kernels.records.Sightings`) at time ``t``, keep its first ``route_slots``
    poses and follow it: the route point, or the arc the layer drives; False when the search gives up."""
    search = search_settings(params, int(params[PARAM.guide_car_shot]) if off_heading(params, robot) else 0)
    wanted = radius + params[PARAM.guide_car_room]
    found, poses, primitives = car_route.plan(seen, robot, wanted, radius, search)
    forget(state)
    state[STATE.guide_made] = t
    route = route_of(params, state)
    if not found or route.shape[0] < 2:
        return found
    count = min(poses.shape[0], route.shape[0])
    route[:count, :3] = poses[:count]
    route[:count, 3] = primitives[:count]
    state[STATE.guide_poses], state[STATE.guide_whole] = count, 1.0 if count == poses.shape[0] else 0.0
    state[STATE.guide_tx], state[STATE.guide_ty] = robot.tx, robot.ty
    state[STATE.guide_seen], state[STATE.guide_keep] = seen.count, car_route.kept(seen, robot, wanted, radius)
    follow(state, params, seen, robot, radius, 0)
    return True


@jit
def forget(state):
    """No car route kept: the next plan searches again."""
    state[STATE.guide_poses] = 0.0


@jit
def nearest(route, at, count, x, y, kinds):
    """(index, distance): the pose of ``route`` nearest (x, y) on the leg from pose ``at`` to the
    next cusp (included; a pose on the next leg is never taken for one on this leg the route
    passes again)."""
    best, gap = at, math.inf
    for k in range(at, count):
        d = math.hypot(route[k, 0] - x, route[k, 1] - y)
        if d < gap:
            best, gap = k, d
        if k > at and k + 1 < count and (route[k + 1, 3] >= kinds) != (route[k, 3] >= kinds):
            break
    return best, gap


@jit
def still_clear(route, at, count, seen, first, keep):
    """Do the points ``seen`` from index ``first`` on keep ``keep`` from the poses of ``route``
    from ``at`` to ``count`` − 1?"""
    points = seen.points
    for p in range(first, seen.count):
        for k in range(at, count):
            if math.hypot(points[p, 0] - route[k, 0], points[p, 1] - route[k, 1]) < keep:
                return False
    return True


@jit
def reused(state, params, seen, robot, t, radius):
    """Follow the kept car route instead of searching again, when it is still valid: younger than
    ``guide_car_reuse`` s, to the same target, the robot within ``guide_car_stray`` m and
    ``guide_car_swerve`` rad of its nearest pose (within a search node, ``guide_car_node`` m and
    two heading bins, where the layer would drive an arc from there), no point seen since it was
    searched within its radius plus ``guide_car_keep`` of the rest of it, and (when the route was
    longer than the slots kept) more than ``guide_car_ahead`` m of it left."""
    count = int(state[STATE.guide_poses])
    if (count < 2 or t - state[STATE.guide_made] > params[PARAM.guide_car_reuse] + 1e-9
            or robot.tx != state[STATE.guide_tx] or robot.ty != state[STATE.guide_ty]):
        return False
    route, kinds = route_of(params, state), int(params[PARAM.guide_car_steerings])
    at, gap = nearest(route, int(state[STATE.guide_at]), count, robot.x, robot.y, kinds)
    swerve = abs(wrap(robot.theta - route[at, 2]))
    left = (count - 1 - at) * params[PARAM.guide_car_step]
    if (gap > params[PARAM.guide_car_stray] or swerve > params[PARAM.guide_car_swerve]
            or (state[STATE.guide_whole] == 0.0 and left <= params[PARAM.guide_car_ahead])):
        return False
    if not still_clear(route, at, count, seen, int(state[STATE.guide_seen]),
                       state[STATE.guide_keep] + params[PARAM.guide_car_keep]):
        return False
    state[STATE.guide_seen] = seen.count  # the rest of the route only shrinks: these points need no second test
    snap = 2.0 * (2.0 * math.pi / params[PARAM.guide_car_headings])
    if follow(state, params, seen, robot, radius, at) and (gap > params[PARAM.guide_car_node] or swerve > snap):
        state[STATE.guide_gear] = 0.0  # an arc driven from here would leave the route: search again
        return False
    return True


@jit
def off_heading(params, robot):
    """Is the target of ``robot`` (a :class:`~fuzzynav.kernels.records.Robot`) farther off its
    heading than ``guide_off_heading`` (0: never)? Then a route is planned even where the
    straight line to it is free: the car route turns the car round on arcs it can drive, where
    the navigator, steering at the target, swings wide (module docstring)."""
    limit = params[PARAM.guide_off_heading]
    return limit > 0.0 and abs(wrap(math.atan2(robot.ty - robot.y, robot.tx - robot.x) - robot.theta)) > limit


@jit
def drop(state):
    """Another layer takes over (the recovery manoeuvre, or the loop escape's start or end): forget
    the arc pending and the route kept, and plan again at the next chance, from the pose the robot then has."""
    state[STATE.guide_gear], state[STATE.guide_planned] = 0.0, -math.inf
    forget(state)


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
    if not off_heading(params, robot) and line_free(points, count, x, y, tx, ty, radius + params[PARAM.guide_room],
                                                    params[PARAM.guide_direct]):
        forget(state)
        return
    if params[PARAM.guide_car] != 0.0 and (reused(state, params, seen, robot, t, radius)
                                           or car(state, params, seen, robot, t, radius)):
        return
    forget(state)
    for room in (PARAM.guide_room, PARAM.guide_narrow, PARAM.guide_bare):
        found, rx, ry = route.target(seen, x, y, tx, ty, radius + params[room], params[PARAM.guide_ahead],
                                     params[PARAM.guide_cell])
        if found:
            state[STATE.guide_x], state[STATE.guide_y] = rx, ry
            return


@jit
def manoeuvre(state, params, seen, x, y, theta, dt, quick):
    """(moving, α, V): this step of the car route's arc, if the layer is driving one (module
    docstring; ``seen`` the remembered points, a :class:`~fuzzynav.kernels.records.Sightings`);
    when the arc is done or the step is not safe, the route is planned again at the next step. A forward arc is driven at ``quick`` (the pace on its arc,
    :func:`fuzzynav.kernels.pace.car_pace`) where that is above ``guide_car_speed`` and the step
    is safe at it, at most the speed that ends the arc in this step."""
    if state[STATE.guide_gear] == 0.0:
        return False, 0.0, 0.0
    points, count = seen.points, seen.count
    backwards = state[STATE.guide_gear] < 0
    speed = -min(params[PARAM.v_back], params[PARAM.max_reverse_speed]) if backwards else params[PARAM.guide_car_speed]
    unfinished = state[STATE.guide_driven] < state[STATE.guide_run] - 1e-9
    if unfinished and not backwards and quick > speed:
        faster = min(quick, max(speed, (state[STATE.guide_run] - state[STATE.guide_driven]) / dt))
        if recovery.safe(params, points, count, x, y, theta, faster, dt):
            speed = faster
    if unfinished and recovery.safe(params, points, count, x, y, theta, speed, dt):
        state[STATE.guide_driven] += abs(speed) * dt
        return True, math.atan(state[STATE.guide_kappa] * params[PARAM.wheelbase]), speed
    state[STATE.guide_gear], state[STATE.guide_planned] = 0.0, -math.inf
    if unfinished:  # stopped short: the route kept is not driven as planned
        forget(state)
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
