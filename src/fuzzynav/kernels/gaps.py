"""Readings by sector and gap finding on a range scan, compiled (the ``-gap`` navigators,
inside the default ``fuzzy-5b``; the thesis variants, ``fuzzy-2b`` and ``fuzzy-5b-rays`` use neither).

- :func:`sector_readings`: the thesis' seven readings d1…d7 from a scan, each the nearest reading
  within ``half`` of its sensor's direction (a lidar reduced to the ring of §IV.7).
- :func:`gap_heading`: the direction to steer through the passage that fits the body. Every hit
  nearer than ``look`` blocks the directions within asin((body + margin) / r) of its bearing
  (the obstacle enlarged by the robot's radius and a margin, as the enlarged cells of VFH+,
  Ulrich & Borenstein, ICRA 1998); the free directions between blocked ones are the gaps
  (follow-the-gap, Sezer & Gokasan, Robotics and Autonomous Systems 2012). Of the free
  directions, the one nearest to the goal's bearing is taken — the goal's own bearing when it is
  free — so the robot goes through the gap that leads to the goal, not the widest one anywhere.
  A car cannot turn on the spot: as VFH+'s masked polar histogram, a hit within the enlarged
  reach of the full-lock turning circle on its side (centre R to the left or right) also blocks
  every direction beyond it on that side (:func:`turn_limits`).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.guard import THESIS_ANGLES
from fuzzynav.kernels.motion import wrap

INSET = math.radians(5.0)  # how far inside a gap's edge the robot aims


@jit
def within(difference, limit):
    """|wrap(``difference``)| ≤ ``limit``, the wrap (a float modulo, the costly part) skipped where
    |``difference``| alone settles it (wrapping moves it by 0 or 2π; 0.1 rad of slack for rounding)."""
    size = abs(difference)
    if limit + 0.1 < size < 2.0 * math.pi - limit - 0.1:
        return False
    return abs(wrap(difference)) <= limit


@jit
def sector_readings(ranges, angles, half, max_range):
    """(d1, …, d7): the nearest reading within ``half`` of each of the thesis' directions."""
    d = [max_range] * 7
    for j in range(ranges.shape[0]):
        for k in range(7):
            if within(angles[j] - THESIS_ANGLES[k], half + 1e-9) and ranges[j] < d[k]:
                d[k] = ranges[j]
    return d[0], d[1], d[2], d[3], d[4], d[5], d[6]


@jit
def covers(angles, i, j, spread):
    """Is direction ``angles[i]`` within ``spread`` of hit ``j``'s bearing?"""
    return within(angles[i] - angles[j], spread)


@jit
def blocked_directions(ranges, angles, clearance, look):
    """(S,) booleans: is each direction within the enlarged bearing asin(``clearance`` / r) of a hit
    nearer than ``look``? On a scan of ascending ``angles`` the directions a hit blocks are the
    run round its own bearing and, for a scan wider than 180°, the runs at the scan's two ends
    (across ±π), so each hit marks those runs only: the scan's cost grows with the hits near the
    robot and their spread, not with the square of its size. The directions fewer places from
    the hit than its spread over the scan's widest step, less one, are blocked without a test
    (each lies a step or more inside the spread, for steps above 10⁻⁹ rad, far above the
    rounding of the angles' differences); the run's two ends are then found as before."""
    size = ranges.shape[0]
    mask = np.zeros(size, dtype=np.bool_)
    widest = 0.0
    for i in range(size - 1):
        widest = max(widest, angles[i + 1] - angles[i])
    for j in range(size):
        r = ranges[j]
        if not r < look:
            continue
        spread = math.asin(min(1.0, clearance / max(r, 1e-9)))
        if not spread >= 0.0:  # a negative clearance blocks nothing, not even the hit's own direction
            continue
        sure = max(int(min(spread / widest, size + 1.0)) - 1, 0) if widest > 1e-9 else 0
        low, high = max(j - sure, 0), min(j + sure, size - 1)
        mask[low:high + 1] = True
        i = low - 1
        while i >= 0 and covers(angles, i, j, spread):
            mask[i], i = True, i - 1
        i = high + 1
        while i < size and covers(angles, i, j, spread):
            mask[i], i = True, i + 1
        i = 0
        while i < size and covers(angles, i, j, spread):
            mask[i], i = True, i + 1
        i = size - 1
        while i >= 0 and covers(angles, i, j, spread):
            mask[i], i = True, i - 1
    return mask


@jit
def turn_limits(ranges, angles, clearance, look, radius, field):
    """(lowest, highest) direction the robot can still turn to: a hit nearer than ``look`` on the
    left (right) that comes within radius + clearance of the left (right) full-lock turning
    circle's centre bounds the directions from above (below) at its bearing (VFH+ masking)."""
    low, high = -field, field
    for j in range(ranges.shape[0]):
        r = ranges[j]
        if r >= look:
            continue
        px, py = r * math.cos(angles[j]), r * math.sin(angles[j])
        side = 1.0 if angles[j] >= 0.0 else -1.0
        if math.hypot(px, py - side * radius) < radius + clearance:
            if side > 0.0:
                high = min(high, angles[j])
            else:
                low = max(low, angles[j])
    return low, high


@jit
def gap_heading(ranges, angles, goal_bearing, clearance, look, field, radius):
    """(found, heading, width) on a scan of ascending ``angles``: the free direction (within
    ``field`` of the heading and within the :func:`turn_limits` of full-lock ``radius``) nearest
    to ``goal_bearing`` with obstacles enlarged by ``clearance`` (module docstring) — moved :data:`INSET` inside the gap when that is the gap's
    edge — and the angular width (rad) of its run of free directions; (False, 0, 0) when none is free."""
    low_limit, high_limit = turn_limits(ranges, angles, clearance, look, radius, field)
    blocked = blocked_directions(ranges, angles, clearance, look)
    best, best_cost = -1, math.inf
    for i in range(angles.shape[0]):
        if not low_limit <= angles[i] <= high_limit or blocked[i]:
            continue
        cost = abs(wrap(angles[i] - goal_bearing))
        if cost < best_cost:
            best, best_cost = i, cost
    if best < 0:
        return False, 0.0, 0.0
    low = high = best
    while low > 0 and angles[low - 1] >= low_limit and not blocked[low - 1]:
        low -= 1
    while high < angles.shape[0] - 1 and angles[high + 1] <= high_limit and not blocked[high + 1]:
        high += 1
    width = angles[high] - angles[low]
    heading = angles[best]
    if best == low and low != high and goal_bearing < heading:  # the goal lies beyond the gap's edge:
        heading += min(0.5 * width, INSET)  # aim a little inside it
    elif best == high and low != high and goal_bearing > heading:
        heading -= min(0.5 * width, INSET)
    return True, heading, width
