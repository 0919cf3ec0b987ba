"""The pace of the default navigator, compiled: a speed set by the room ahead on the arc the robot
is steering, the layer of ``fuzzy-5b`` (the default) that lets it drive quickly where it is
clear (:mod:`fuzzynav.control.through_gaps`, ``pace_*``).

The thesis' speeds (Table IV.1 slowing towards the goal, VRB's eq IV.9 adding a bounded change
to the last speed, §IV.7) and the gap navigator's brake on the nearest reading anywhere around
the robot keep it near 0.5 m/s in clutter, even where the way ahead is open. Here the speed is
instead the one that leaves ``horizon`` seconds of travel before the body, on the circular arc
of the present steering (curvature tan α / l, eq IV.1), comes within ``room`` m of a lidar hit:
V = min(top, free run / horizon, distance to the target / ``goal``) — the dynamic window's
admissible-velocity idea (Fox, Burgard & Thrun 1997: a speed from which the robot can still
react before the nearest obstacle on its curvature), with the curvature the navigator chose.
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels.layers import PARAM, STATE


@jit
def free_run(ranges, angles, max_range, kappa, room):
    """Arc length (m) the robot's centre can travel forward on the arc of curvature ``kappa``
    (1/m, + to the left) before it comes within ``room`` of a hit of the scan (``ranges`` along
    ``angles`` from the centre, robot frame; ``max_range``: no hit); 0 when it is already that
    close to one ahead of it, ``max_range`` at most. The centre comes within ``room`` of a hit r m
    away only after r − ``room`` m of travel, so a hit farther than the best run so far plus
    ``room`` (and 1 µm for rounding) is passed unmeasured: the run is the same number, bit for bit."""
    best = max_range
    for j in range(ranges.shape[0]):
        r = ranges[j]
        if r >= max_range or r > best + room + 1e-6:
            continue
        hx, hy = r * math.cos(angles[j]), r * math.sin(angles[j])
        if abs(kappa) < 1e-3:  # straight on (the arc leaves the line by < 5 cm over 10 m)
            if hx > 0.0 and abs(hy) < room:
                best = min(best, max(hx - math.sqrt(room * room - hy * hy), 0.0))
            continue
        radius = 1.0 / abs(kappa)
        cy = radius if kappa > 0 else -radius  # the arc's centre (0, cy)
        dx, dy = hx, hy - cy
        rho = math.hypot(dx, dy)
        if abs(rho - radius) >= room:
            continue
        # the hit's angle round the centre, from the robot's, in the direction of travel
        phi = math.atan2(dx, -dy) if kappa > 0 else math.atan2(dx, dy)
        if phi < 0.0:
            phi += 2.0 * math.pi
        half = math.acos(min(max((radius * radius + rho * rho - room * room) / (2.0 * radius * rho), -1.0), 1.0))
        if phi <= half:  # within room already, and the arc leads nearer: no run
            return 0.0
        if phi < 2.0 * math.pi - half:  # (beyond that: within room, but the arc leads away)
            best = min(best, radius * (phi - half))
    return best


@jit
def pace(ranges, angles, max_range, steering, params, distance):
    """The speed of the module docstring for the steering α, ``distance`` m from the target, with
    the layers' ``params`` (:mod:`fuzzynav.kernels.layers`: the room is the body's radius plus
    ``pace_room``)."""
    run = free_run(ranges, angles, max_range, math.tan(steering) / params[PARAM.wheelbase],
                   params[PARAM.radius] + params[PARAM.pace_room])
    return min(params[PARAM.max_speed], run / params[PARAM.pace_horizon], distance / params[PARAM.pace_goal])


@jit
def car_pace(ranges, angles, max_range, params, state, distance):
    """The speed of :func:`pace` on the forward arc of the car route the layer drives
    (:func:`fuzzynav.kernels.guidance.manoeuvre`, curvature ``state[STATE.guide_kappa]``); 0 (no
    raise) when ``pace_car`` is off or no forward arc is driven."""
    if params[PARAM.pace] == 0.0 or params[PARAM.pace_car] == 0.0 or state[STATE.guide_gear] <= 0.0:
        return 0.0
    return pace(ranges, angles, max_range, math.atan(state[STATE.guide_kappa] * params[PARAM.wheelbase]), params,
                distance)
