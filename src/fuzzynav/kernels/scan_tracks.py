"""Moving obstacles tracked from successive range scans, compiled, for a batch of robots: what the
yield layer (:mod:`fuzzynav.kernels.threats`) and the tracked classic navigators
(:class:`fuzzynav.control.sighting_tracks.ScanTracker`) know of them (docs/dynamic.md).

Each step, the echoes that lie off the previous scan's outline (they moved;
:mod:`fuzzynav.kernels.outline`) are grouped into clusters (neighbouring beams less than ``JOIN``
m apart); a cluster's centre is its mean point pushed away from the robot by half its extent (a
disc seen from one side). A cluster extends the track whose predicted centre lies within ``GATE``
m of it, or starts a new one. A track's velocity is the least-squares slope of its last
``WINDOW`` sightings, so a 0.1 s step's noise is averaged over up to a second; a track is
confirmed after ``CONFIRM`` sightings, and kept — its centre predicted at constant velocity —
``MEMORY`` s after its last one, so an obstacle that walks into the lidar's blind sector behind
the robot is still avoided. A robot holds at most ``CAPACITY`` tracks (a cluster that finds none
free starts no track; ten at most were seen at once among the dynamic family's 20 movers).

The time to collision of a confirmed track is the first time t ≥ 0 at which the relative
position p + w t (w: the track's velocity less the robot's) comes within the sum of the radii:
the collision-cone test of velocity obstacles (P. Fiorini, Z. Shiller, "Motion planning in
dynamic environments using velocity obstacles", IJRR 17(7), 1998), solved in closed form; a
track whose relative motion misses the robot has none (inf).

The tracks of N robots are a :class:`~fuzzynav.kernels.records.Tracks` record of arrays
(:func:`empty`); robot i's tracks are its slots ``0 … count[i] − 1``, oldest first.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.motion import wrap
from fuzzynav.kernels.records import Tracks

JOIN = 0.6  # m: neighbouring moved echoes closer than this belong to one obstacle
GATE = 1.0  # m: a cluster extends a track whose predicted centre is this close
WINDOW = 8  # sightings in a track's velocity fit
CONFIRM = 5  # sightings before a track is believed
MIN_SPEED = 0.4  # m/s: a slower track is taken for noise of the outline test
MEMORY = 2.0  # s: a track unseen this long is forgotten
MARGIN = 0.2  # m added to the sum of the radii
CAPACITY = 32  # tracks a robot holds at once


def empty(n: int) -> Tracks:
    """No tracks for ``n`` robots."""
    return Tracks(np.zeros((n, CAPACITY, WINDOW)), np.zeros((n, CAPACITY, WINDOW, 2)), np.zeros((n, CAPACITY), np.int64),
                  np.zeros((n, CAPACITY)), np.zeros((n, CAPACITY, 2)), np.zeros(n, np.int64))


@jit
def clusters(points, moved, here):
    """(centres (C, 2), radii (C,)) of the groups of neighbouring moved echoes (``points`` (B, 2)
    in beam order, ``moved`` (B,) bool) seen from ``here`` (module docstring)."""
    index = np.flatnonzero(moved)
    centres, radii = np.empty((len(index), 2)), np.empty(len(index))
    n, start = 0, 0
    for k in range(1, len(index) + 1):
        if k < len(index) and math.hypot(points[index[k], 0] - points[index[k - 1], 0],
                                         points[index[k], 1] - points[index[k - 1], 1]) <= JOIN:
            continue
        if k - start >= 2:
            first, last = index[start], index[k - 1]
            radius = max(0.2, 0.5 * math.hypot(points[last, 0] - points[first, 0], points[last, 1] - points[first, 1]))
            mx, my = 0.0, 0.0
            for j in range(start, k):
                mx += points[index[j], 0]
                my += points[index[j], 1]
            mx, my = mx / (k - start), my / (k - start)
            ax, ay = mx - here[0], my - here[1]
            norm = max(math.hypot(ax, ay), 1e-9)
            centres[n, 0], centres[n, 1] = mx + 0.5 * radius * ax / norm, my + 0.5 * radius * ay / norm
            radii[n] = radius
            n += 1
        start = k
    return centres[:n], radii[:n]


@jit
def predict(tracks, i, k, t):
    """(x, y): where robot ``i``'s track ``k`` is at time ``t``, at constant velocity."""
    last = tracks.sightings[i, k] - 1
    later = t - tracks.times[i, k, last]
    return (tracks.centres[i, k, last, 0] + tracks.velocity[i, k, 0] * later,
            tracks.centres[i, k, last, 1] + tracks.velocity[i, k, 1] * later)


@jit
def confirmed(tracks, i, k):
    """Is robot ``i``'s track ``k`` believed (``CONFIRM`` sightings, at least ``MIN_SPEED``)?"""
    return tracks.sightings[i, k] >= CONFIRM and math.hypot(tracks.velocity[i, k, 0], tracks.velocity[i, k, 1]) >= MIN_SPEED


@jit
def _sight(tracks, i, k, t, x, y, radius):
    """Add a sighting at (x, y), time ``t``, to robot ``i``'s track ``k`` (the oldest of a full
    window dropped) and fit its velocity."""
    n = tracks.sightings[i, k]
    if n == WINDOW:
        for j in range(WINDOW - 1):
            tracks.times[i, k, j] = tracks.times[i, k, j + 1]
            tracks.centres[i, k, j, 0], tracks.centres[i, k, j, 1] = tracks.centres[i, k, j + 1, 0], tracks.centres[i, k, j + 1, 1]
        n -= 1
    tracks.times[i, k, n], tracks.centres[i, k, n, 0], tracks.centres[i, k, n, 1] = t, x, y
    tracks.sightings[i, k] = n + 1
    tracks.radius[i, k] = max(tracks.radius[i, k], radius)
    if n + 1 >= 2:
        mean_t, mean_x, mean_y = 0.0, 0.0, 0.0
        for j in range(n + 1):
            mean_t += tracks.times[i, k, j]
            mean_x += tracks.centres[i, k, j, 0]
            mean_y += tracks.centres[i, k, j, 1]
        mean_t, mean_x, mean_y = mean_t / (n + 1), mean_x / (n + 1), mean_y / (n + 1)
        spread, sx, sy = 0.0, 0.0, 0.0
        for j in range(n + 1):
            dt = tracks.times[i, k, j] - mean_t
            spread += dt * dt
            sx += dt * (tracks.centres[i, k, j, 0] - mean_x)
            sy += dt * (tracks.centres[i, k, j, 1] - mean_y)
        if spread > 0:
            tracks.velocity[i, k, 0], tracks.velocity[i, k, 1] = sx / spread, sy / spread


@jit
def update(tracks, i, t, points, moved, here):
    """Add robot ``i``'s moved echoes of the step (``points`` (B, 2) in beam order, ``moved`` (B,))
    at time ``t``, seen from ``here`` (module docstring): each cluster extends the nearest free
    track within ``GATE`` of it (ties to the oldest) or starts one; then the tracks unseen for
    more than ``MEMORY`` s are forgotten."""
    centres, radii = clusters(points, moved, here)
    old = tracks.count[i]
    free = np.ones(old, dtype=np.bool_)
    for c in range(len(radii)):
        best, nearest = np.inf, -1
        for k in range(old):
            if free[k]:
                px, py = predict(tracks, i, k, t)
                gap = math.hypot(px - centres[c, 0], py - centres[c, 1])
                if gap < best:
                    best, nearest = gap, k
        if nearest >= 0 and best <= GATE:
            free[nearest] = False
            _sight(tracks, i, nearest, t, centres[c, 0], centres[c, 1], radii[c])
        elif tracks.count[i] < CAPACITY:
            k = tracks.count[i]
            tracks.sightings[i, k], tracks.radius[i, k] = 0, 0.0
            tracks.velocity[i, k, 0], tracks.velocity[i, k, 1] = 0.0, 0.0
            _sight(tracks, i, k, t, centres[c, 0], centres[c, 1], radii[c])
            tracks.count[i] = k + 1
    kept = 0
    for k in range(tracks.count[i]):
        if t - tracks.times[i, k, tracks.sightings[i, k] - 1] <= MEMORY:
            if kept != k:
                _move(tracks, i, k, kept)
            kept += 1
    tracks.count[i] = kept


@jit
def _move(tracks, i, k, to):
    """Copy robot ``i``'s track ``k`` into slot ``to``."""
    tracks.times[i, to], tracks.centres[i, to] = tracks.times[i, k], tracks.centres[i, k]
    tracks.sightings[i, to], tracks.radius[i, to] = tracks.sightings[i, k], tracks.radius[i, k]
    tracks.velocity[i, to] = tracks.velocity[i, k]


@jit
def first_contact(px, py, wx, wy, reach):
    """Smallest t ≥ 0 with |p + w t| ≤ ``reach`` (0 when already within; inf when never)."""
    c = px * px + py * py - reach * reach
    if c <= 0:
        return 0.0
    a, b = wx * wx + wy * wy, 2.0 * (px * wx + py * wy)
    disc = b * b - 4 * a * c
    if a <= 1e-12 or b >= 0 or disc < 0:
        return np.inf
    return (-b - math.sqrt(disc)) / (2 * a)


@jit
def time_to_collision(tracks, i, t, pose, speed, robot_radius):
    """(time to collision (s, inf: none), bearing of that obstacle from the heading (rad)) of
    robot ``i``'s confirmed tracks against the robot at ``pose`` (x, y, θ) driving straight on
    at ``speed`` (ties to the oldest track)."""
    best, bearing = np.inf, 0.0
    ox, oy = speed * math.cos(pose[2]), speed * math.sin(pose[2])
    for k in range(tracks.count[i]):
        if not confirmed(tracks, i, k):
            continue
        cx, cy = predict(tracks, i, k, t)
        px, py = cx - pose[0], cy - pose[1]
        when = first_contact(px, py, tracks.velocity[i, k, 0] - ox, tracks.velocity[i, k, 1] - oy,
                             robot_radius + tracks.radius[i, k] + MARGIN)
        if when < best:
            best, bearing = when, wrap(math.atan2(py, px) - pose[2])
    return best, bearing
