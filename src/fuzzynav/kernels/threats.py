"""The yield layer's times to collision with moving obstacles, compiled, for a batch of robots:
what :class:`fuzzynav.control.yield_layer.YieldLayer` reads from the lidar each step
(docs/dynamic.md; the thesis' perspective of dynamic obstacles, Conclusion générale).

For each robot, its echoes within the ``horizon`` (and, with tracks, within ``track_range``) are
tested against the outline of its scan before (:func:`fuzzynav.kernels.outline.off_outline`):

- the two-scan cue: an echo that moved faster than ``mover_speed`` and whose gap to the robot
  shrank faster than that gives a time to collision gap / closing speed (the closing-speed cue
  of Fiorini & Shiller's velocity obstacles, IJRR 1998, read from two range scans);
- with tracks, the moved echoes feed the robot's tracks (:mod:`fuzzynav.kernels.scan_tracks`),
  whose collision cone gives a second time to collision; it counts only for a threat more than
  ``tracked_beyond`` off the heading (abeam, behind), where the two-scan cue sees little.

The smaller time and the bearing of its threat are the layer's inputs.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import scan_tracks
from fuzzynav.kernels.outline import BRIDGE, off_outline


@jit
def scan_points(poses, ranges, angles, active):
    """(N, B, 2): each beam's echo (or its reach) in the world frame, for the ``active`` (N,)
    robots (zeros for the others)."""
    points = np.zeros((ranges.shape[0], ranges.shape[1], 2))
    for i in range(ranges.shape[0]):
        if not active[i]:
            continue
        for j in range(ranges.shape[1]):
            heading = poses[i, 2] + angles[j]
            points[i, j, 0] = poses[i, 0] + ranges[i, j] * math.cos(heading)
            points[i, j, 1] = poses[i, 1] + ranges[i, j] * math.sin(heading)
    return points


@jit
def threats(poses, speeds, ranges, angles, active, before, tracks, settings):
    """(time to collision (N,), inf when nothing comes; bearing of that threat from the heading
    (N,); the scan's echoes (:func:`scan_points`)) of robots at ``poses`` (N, 3) with ``speeds``
    (N,), whose scan reads ``ranges`` (N, B) along ``angles`` (B,), against their scan ``before``
    (a :class:`~fuzzynav.kernels.records.Scans`); ``tracks`` are updated in place, for the
    ``active`` (N,) robots only."""
    s = settings
    n, beams = ranges.shape
    points = scan_points(poses, ranges, angles, active)
    ttc, bearing = np.full(n, np.inf), np.zeros(n)
    seen_within = min(s.max_range - 1e-6, s.horizon)
    tracked_within = min(s.max_range - 1e-6, s.track_range) if s.tracks else -1.0
    for i in range(n):
        if not active[i]:
            continue
        tested = np.flatnonzero((ranges[i] < seen_within) | (ranges[i] < tracked_within))
        if len(tested) == 0:
            continue
        off, was = off_outline(points[i][tested], before.points[i], before.valid[i], BRIDGE)
        if np.any(ranges[i] < tracked_within):
            moved = np.zeros(beams, dtype=np.bool_)
            for m in range(len(tested)):
                moved[tested[m]] = ranges[i, tested[m]] < tracked_within and off[m] / s.dt > s.mover_speed
            scan_tracks.update(tracks, i, s.t, points[i], moved, poses[i, :2])
            ttc[i], bearing[i] = scan_tracks.time_to_collision(tracks, i, s.t, poses[i], speeds[i], s.radius)
            if abs(bearing[i]) < s.tracked_beyond:
                ttc[i] = np.inf  # ahead, the closing speed read off the scans decides
        best, which = np.inf, -1
        for m in range(len(tested)):
            j = tested[m]
            if not ranges[i, j] < seen_within or not math.isfinite(off[m]):
                continue
            gap = math.hypot(points[i, j, 0] - poses[i, 0], points[i, j, 1] - poses[i, 1])
            closing = (math.hypot(was[m, 0] - before.here[i, 0], was[m, 1] - before.here[i, 1]) - gap) / s.dt
            if off[m] / s.dt > s.mover_speed and closing > s.mover_speed and gap / closing < best:
                best, which = gap / closing, j
        if which >= 0 and best < ttc[i]:
            ttc[i], bearing[i] = best, angles[which]
    return ttc, bearing, points
