"""Evading a moving obstacle by sampling commands against its predicted track, compiled, for a
batch of robots: the last word of the yield / evade layer
(:class:`fuzzynav.control.yield_layer.YieldLayer`, ``evade=True``) in the default ``fuzzy-5b``
among moving obstacles (docs/dynamic.md; the thesis' perspective of dynamic obstacles,
Conclusion générale).

The rules of the layer answer the time to collision and the side of the nearest threat; they do
not know whether their answer clears it. This step checks it: the robot's command held for
``HORIZON`` s (the tricycle's kinematics, eq IV.1–IV.2, in steps of its Δt) against every confirmed
track, each predicted at constant velocity (:mod:`fuzzynav.kernels.scan_tracks`). When that path
comes within ``TRIGGER`` m of a track (beyond the radii), a fan of commands (``STEERINGS`` ×
``SPEEDS``, reverse included, and the command itself first) is rolled out the same way and
scored by its clearance from the tracks (those seen ``SEEN`` times and not yet confirmed too)
and from the scan's standing echoes within ``STANDING_RANGE`` (the echoes on a track left out).
The robot takes the command closest to its own among those keeping ``MARGIN`` from the tracks
and ``STANDING_MARGIN`` from what stands; when none does, the one with the most room, never one
that drives through a standing echo while another does not (a contact with what stands is
certain, one with a predicted track is not). This is the sampling of a dynamic window over
predicted obstacle motion (D. Fox, W. Burgard, S. Thrun, "The dynamic window approach to
collision avoidance", IEEE RAM 4(1), 1997) with the constant-velocity prediction of velocity
obstacles (P. Fiorini, Z. Shiller, IJRR 17(7), 1998), used only when the command it would leave
is on a collision course.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import scan_tracks
from fuzzynav.kernels.motion import DT, LOWEST_SPEED, MAX_SPEED, MAX_STEERING, RADIUS, advance, clip

HORIZON = 2.0  # s of the rollouts (in steps of the robot's Δt)
TRIGGER = 0.15  # m: the robot's own command is replaced when it comes this close to a track (beyond the radii)
MARGIN = 0.15  # m an evasive command keeps from a track (beyond the radii)
STANDING_MARGIN = 0.1  # m it keeps from a standing echo
SEEN = 2  # sightings of a track not yet confirmed that evasive commands keep clear of too
STANDING_RANGE = 5.0  # m: the scan's echoes this close count as standing obstacles
ON_TRACK = 0.3  # m: an echo this far beyond a track's radius from its centre is the tracked obstacle's
SPEEDS = (-1.0, 0.0, 0.25, 0.5, 1.0)  # fractions of the top speed (reverse: of the lowest speed)
STEERINGS = (-1.0, -0.5, 0.0, 0.5, 1.0)  # fractions of the steering limit
FAN = 1 + len(SPEEDS) * len(STEERINGS)  # the command itself, then the grid


@jit
def rollout(pose, steering, speed, robot, path):
    """Fill ``path`` (K, 2) with the positions, one step Δt apart, of the robot (parameters
    ``robot``) from ``pose`` (x, y, θ) holding (``steering``, ``speed``): its own kinematics
    (:func:`fuzzynav.kernels.motion.advance`, eq IV.1–IV.2)."""
    x, y, theta = pose[0], pose[1], pose[2]
    for k in range(path.shape[0]):
        x, y, theta = advance(x, y, theta, steering, speed, robot)
        path[k, 0], path[k, 1] = x, y


@jit
def track_gap(path, dt, centres, velocities, radii, m, body):
    """Smallest gap between ``path`` (K, 2; ``dt`` s apart) and the first ``m`` tracks (now at
    ``centres``, moving at ``velocities``, of ``radii``) at the same times, for a body of radius
    ``body``."""
    best = np.inf
    for k in range(path.shape[0]):
        later = dt * (k + 1)
        for j in range(m):
            gap = math.hypot(path[k, 0] - centres[j, 0] - velocities[j, 0] * later,
                             path[k, 1] - centres[j, 1] - velocities[j, 1] * later) - radii[j] - body
            best = min(best, gap)
    return best


@jit
def standing_gap(path, points, p, body):
    """Smallest gap between ``path`` (K, 2) and the first ``p`` standing echoes ``points``."""
    best = np.inf
    for k in range(path.shape[0]):
        for j in range(p):
            best = min(best, math.hypot(path[k, 0] - points[j, 0], path[k, 1] - points[j, 1]) - body)
    return best


@jit
def tracks_now(tracks, i, t, unconfirmed, centres, velocities, radii):
    """Fill the first rows of ``centres``, ``velocities``, ``radii`` with robot ``i``'s confirmed
    tracks at time ``t`` (and, with ``unconfirmed``, those seen ``SEEN`` times); their count."""
    m = 0
    for k in range(tracks.count[i]):
        if scan_tracks.confirmed(tracks, i, k) or (unconfirmed and tracks.sightings[i, k] >= SEEN):
            centres[m, 0], centres[m, 1] = scan_tracks.predict(tracks, i, k, t)
            velocities[m, 0], velocities[m, 1], radii[m] = tracks.velocity[i, k, 0], tracks.velocity[i, k, 1], tracks.radius[i, k]
            m += 1
    return m


@jit
def standing_echoes(pose, points, valid, centres, radii, m, out):
    """Fill ``out`` with the echoes (``points`` (B, 2), ``valid`` (B,)) within ``STANDING_RANGE``
    of ``pose`` that lie on none of the first ``m`` tracks; their count."""
    p = 0
    for b in range(points.shape[0]):
        if not valid[b] or math.hypot(points[b, 0] - pose[0], points[b, 1] - pose[1]) >= STANDING_RANGE:
            continue
        on_track = False
        for j in range(m):
            if math.hypot(points[b, 0] - centres[j, 0], points[b, 1] - centres[j, 1]) <= radii[j] + ON_TRACK:
                on_track = True
        if not on_track:
            out[p, 0], out[p, 1] = points[b, 0], points[b, 1]
            p += 1
    return p


@jit
def fan_command(c, steering, speed, robot):
    """Command ``c`` of the fan within the ``robot``'s limits: its own (``steering``, ``speed``)
    for ``c`` = 0, else the grid's (``STEERINGS`` × ``SPEEDS`` of those limits)."""
    if c == 0:
        return clip(steering, speed, robot)
    share = SPEEDS[(c - 1) % len(SPEEDS)]
    wanted = share * robot[MAX_SPEED] if share >= 0 else -share * min(robot[LOWEST_SPEED], 0.0)
    return clip(STEERINGS[(c - 1) // len(SPEEDS)] * robot[MAX_STEERING], wanted, robot)


@jit
def evade(poses, steering, speed, active, tracks, scans, robot, t):
    """Replace, in place, the commands (``steering``, ``speed`` (N,)) of the ``active`` robots at
    ``poses`` that would run into a predicted track (module docstring); ``scans`` is the step's
    :class:`~fuzzynav.kernels.records.Scans`, ``robot`` the robots' parameters
    (:data:`fuzzynav.kernels.motion.ROBOT_FIELDS`), ``t`` the tracks' time. Returns which robots
    evaded (N,) bool."""
    n, capacity = poses.shape[0], tracks.radius.shape[1]
    evaded = np.zeros(n, dtype=np.bool_)
    dt = robot[DT]
    path = np.empty((max(1, int(round(HORIZON / dt))), 2))
    centres, velocities, radii = np.empty((capacity, 2)), np.empty((capacity, 2)), np.empty(capacity)
    standing = np.empty((scans.points.shape[1], 2))
    body, limit, top = robot[RADIUS], robot[MAX_STEERING], robot[MAX_SPEED]
    for i in range(n):
        if not active[i] or tracks.count[i] == 0:
            continue
        m = tracks_now(tracks, i, t, False, centres, velocities, radii)
        if m == 0:
            continue
        own_steering, own_speed = fan_command(0, steering[i], speed[i], robot)
        rollout(poses[i], own_steering, own_speed, robot, path)
        if track_gap(path, dt, centres, velocities, radii, m, body) >= TRIGGER:
            continue
        m = tracks_now(tracks, i, t, True, centres, velocities, radii)
        p = standing_echoes(poses[i], scans.points[i], scans.valid[i], centres, radii, m, standing)
        safe, change = -1, np.inf
        free, free_room, any_, any_room = -1, -np.inf, -1, -np.inf
        for c in range(FAN):
            alpha, v = fan_command(c, steering[i], speed[i], robot)
            rollout(poses[i], alpha, v, robot, path)
            moving = track_gap(path, dt, centres, velocities, radii, m, body) - MARGIN
            still = standing_gap(path, standing, p, body) - STANDING_MARGIN
            room = min(moving, still)
            if moving >= 0 and still >= 0:
                cost = abs(v - own_speed) / top + abs(alpha - own_steering) / limit
                if cost < change:
                    safe, change = c, cost
            if still >= -STANDING_MARGIN and room > free_room:
                free, free_room = c, room
            if room > any_room:
                any_, any_room = c, room
        best = safe if safe >= 0 else (free if free >= 0 else any_)
        steering[i], speed[i] = fan_command(best, steering[i], speed[i], robot)
        evaded[i] = True
    return evaded
