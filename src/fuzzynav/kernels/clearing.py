"""Forgetting the obstacle points that are no longer there, compiled: the memory of the default
navigator's layers (:mod:`fuzzynav.kernels.sightings`) in a scenario with moving obstacles.

The layers remember every hit where it was seen, so a moving obstacle leaves a trail of points
that the route guidance plans round and the car route squeezes between, as if walls stood there
(docs/dynamic.md). In a scenario with moving obstacles (``params[PARAM.forget]`` set by
:meth:`fuzzynav.control.robust.RobustNavigator.for_traffic`) each scan clears the points it
contradicts, the clearing of an occupancy map by the free space a beam crosses (A. Elfes, "Using
occupancy grids for mobile robot perception and navigation", Computer 22(6), 1989; the
ray-traced clearing of the ROS costmap, E. Marder-Eppstein et al., "The Office Marathon", ICRA
2010):

- a point that the beam nearest its direction passes within ``BESIDE`` m of, the beam's echo (or
  its reach) lying more than ``BEYOND`` m farther: the beam went through where the point was;
- a point nearer than the nearest obstacle point the observation gives all round (D_ro) by more
  than ``BEYOND`` m: nothing is that near now (this clears the blind sector behind a lidar too).

A static scenario never clears (the flag is off), so its runs stay bit-identical.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import sightings
from fuzzynav.kernels.motion import turn_remainder

BESIDE = 0.05  # m: a beam passing this near a point covers it
BEYOND = 0.15  # m: the echo must lie this much farther than the point to clear it


@jit
def contradicted(px, py, pose, seen):
    """Does the scan ``seen`` (a :class:`~fuzzynav.kernels.records.Reading`: ``ranges`` along
    ``angles``, sorted ascending, relative to the heading; D_ro = ``d_o``, ``inf``: none) read at
    ``pose`` show that nothing stands at (px, py) now (module docstring)?"""
    x, y, theta = pose.x, pose.y, pose.theta
    ranges, angles, max_range, d_o = seen.ranges, seen.angles, seen.max_range, seen.d_o
    d = math.hypot(px - x, py - y)
    if math.isfinite(d_o) and d < d_o - BEYOND:
        return True
    if d >= max_range - BEYOND:
        return False
    phi = math.atan2(py - y, px - x) - theta
    phi = turn_remainder(phi + math.pi) - math.pi
    k = min(max(int(np.searchsorted(angles, phi)), 1), angles.shape[0] - 1)
    if abs(phi - angles[k - 1]) < abs(phi - angles[k]):
        k -= 1  # the beam nearest the point's direction
    off = phi - angles[k]
    return math.cos(off) > 0.0 and d * abs(math.sin(off)) < BESIDE and ranges[k] > d + BEYOND


@jit
def clear(points, cells, count, pose, seen):
    """Forget the first ``count`` of ``points`` that the scan ``seen`` (a
    :class:`~fuzzynav.kernels.records.Reading`) read at ``pose`` (a
    :class:`~fuzzynav.kernels.records.Pose`) contradicts, keeping the others in their order and
    their hash set ``cells`` in step; returns the new count."""
    kept = 0
    for i in range(count):
        if not contradicted(points[i, 0], points[i, 1], pose, seen):
            points[kept, 0], points[kept, 1] = points[i, 0], points[i, 1]
            kept += 1
    if kept < count:
        sightings.rehash(points, kept, cells)
    return kept
