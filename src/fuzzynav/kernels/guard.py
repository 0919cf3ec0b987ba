"""The supervisor's selection and switch, and the turning-room guard, compiled (thesis §IV.4,
§IV.7, Fig IV.16). The rules are stated in :mod:`fuzzynav.control.supervisor` and
:mod:`fuzzynav.control.turning_room`; these are their one implementation, for one robot at a
time (the navigators loop over robots).

Hit memory of one robot: ``memory`` (steps, S + 1, 3) — for each of the last ``steps`` steps and
each ray plus the cone echo, the world-frame hit (x, y) and 1.0 where it is a hit — filled
round-robin at slot ``count % steps``.
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels.motion import ring_gap, turn_remainder

GSB, FOA, ROA, LOA = 0, 1, 2, 3
# angles of C1…C7 (rad, thesis §IV.7) and the avoider on each sensor's side
THESIS_ANGLES = (0.0, -math.pi / 6, math.pi / 6, -math.pi / 3, math.pi / 3, -math.pi / 2, math.pi / 2)
SIDE = (FOA, ROA, LOA, ROA, LOA, ROA, LOA)


@jit
def select(d, goal_distance, goal_bearing, detection, front, keep, clear, vision):
    """Behaviour code (GSB, FOA, ROA, LOA) from the readings ``d`` (7,) in C1…C7 order and the
    goal's distance and bearing: GSB when nothing is within ``detection`` or the goal direction
    is clear (every ray within ``vision`` of the bearing clipped to ±90° reads at least
    min(d_rg, ``clear``), none below ``keep``); else FOA while d1 < ``front``, else the avoider
    of the nearest reading's side."""
    look = min(max(goal_bearing, -math.pi / 2), math.pi / 2)
    need = min(goal_distance, clear)
    nearest, arg = d[0], 0
    for j in range(1, 7):
        if d[j] < nearest:
            nearest, arg = d[j], j
    clear_view = nearest >= keep
    for j in range(7):
        if clear_view and abs(THESIS_ANGLES[j] - look) <= vision + 1e-9 and not d[j] >= need:
            clear_view = False
    if nearest >= detection or clear_view:
        return GSB
    return FOA if d[0] < front else SIDE[arg]


@jit
def switch(state, wanted, urgent, rank, dwell):
    """The behaviour switch with memory: ``state`` holds [mode (−1: none yet), held steps]; a
    change to a higher ``rank`` is taken at once where ``urgent``, any other after ``dwell``
    steps. Returns the mode."""
    mode, held = state[0], state[1]
    if mode < 0:
        state[0], state[1] = wanted, 0
        return wanted
    up, take = rank[wanted] > rank[mode], False
    take = wanted != mode and ((up and urgent) or held >= dwell)
    state[0], state[1] = (wanted, 0) if take else (mode, held + 1)
    return state[0]


@jit
def remember(memory, count, pose, seen, half_cone):
    """Store this step's hits, read at ``pose`` (a :class:`~fuzzynav.kernels.records.Pose`), in
    slot ``count % steps``: the rays of ``seen`` (a :class:`~fuzzynav.kernels.records.Reading`)
    plus the cone echo — the nearest obstacle point (``d_o``, ``b_o``) where it lies within
    ``half_cone`` of a sensor direction (a sonar's cone, not a line)."""
    x, y, theta, ranges, angles = pose.x, pose.y, pose.theta, seen.ranges, seen.angles
    max_range, distance, bearing = seen.max_range, seen.d_o, seen.b_o
    slot = count % memory.shape[0]
    gap = math.inf
    for a in angles:
        r = turn_remainder(bearing - a)
        gap = min(gap, min(r, 2.0 * math.pi - r))
    echo = distance if gap <= half_cone else math.inf
    limit = max_range - 1e-9
    for j in range(memory.shape[1]):
        r = ranges[j] if j < angles.shape[0] else echo
        heading = theta + (angles[j] if j < angles.shape[0] else bearing)
        hit = r < limit and math.isfinite(r)
        memory[slot, j, 0] = x + r * math.cos(heading) if hit else x
        memory[slot, j, 1] = y + r * math.sin(heading) if hit else y
        memory[slot, j, 2] = 1.0 if hit else 0.0


@jit
def local(memory, m, j, x, y, c, s):
    """Remembered point (m, j) in the robot frame at (x, y) with heading cos/sin (c, s)."""
    rx, ry = memory[m, j, 0] - x, memory[m, j, 1] - y
    return c * rx + s * ry, c * ry - s * rx


@jit
def turning_room(memory, x, y, theta, body, radius):
    """(room left, room right, free lane ahead) from the remembered hits: the smallest gap between
    the body of a robot turning half a circle of ``radius`` to that side and any hit (a hit
    ahead is passed at | |p − c| − R |, one behind at the nearer end of the half circle), and the
    free length of the lane of half-width ``body`` ahead. inf without hits. A hit d m away is at
    least d − 2R from either half circle (R ≥ 0; :func:`beyond`): one beyond both rooms found so
    far is passed without its circles, which leaves the three numbers as they are, bit for bit."""
    c, s = math.cos(theta), math.sin(theta)
    left = right = ahead = math.inf
    for m in range(memory.shape[0]):
        for j in range(memory.shape[1]):
            if memory[m, j, 2] == 0.0:
                continue
            lx, ly = local(memory, m, j, x, y, c, s)
            if lx > 0.0 and abs(ly) < body:
                ahead = min(ahead, lx - body)
            if beyond(lx, ly, max(left, right) + 2.0 * radius + body):
                continue
            if lx >= 0.0:
                gap_left = ring_gap(lx, ly - radius, radius, left + body)
                gap_right = ring_gap(lx, ly + radius, radius, right + body)
            else:
                here = ring_gap(lx, ly, 0.0, max(left, right) + body)
                gap_left = min(here, ring_gap(lx, ly - 2.0 * radius, 0.0, left + body))
                gap_right = min(here, ring_gap(lx, ly + 2.0 * radius, 0.0, right + body))
            left, right = min(left, gap_left - body), min(right, gap_right - body)
    return left, right, ahead


@jit
def beyond(dx, dy, reach):
    """Is (dx, dy) farther than ``reach`` from the origin, with 1 µm and a billionth of ``reach``
    to spare for rounding (so a point that passes could not have changed a minimum it is skipped
    for, wherever the world lies)? False for an infinite or unknown ``reach``."""
    far = reach * (1.0 + 1e-9) + 1e-6
    return dx * dx + dy * dy > far * far


@jit
def turn_wanted(memory, pose, step, turning, goal_bearing, side, room):
    """(full-lock turn wanted?, side ±1) at ``pose`` (a :class:`~fuzzynav.kernels.records.Pose`),
    ``room`` a :class:`~fuzzynav.kernels.records.TurnRoom`: the lane ahead blocked within
    ``lane`` and the better half turn closer than ``margin`` to a hit, both after one more
    ``step`` (m) — a turn under way until they exceed those by 0.5 m and 0.2 m. The side is the
    roomier one (within 0.1 m the goal's), kept while ``turning`` (``side`` ≠ 0 is the current one)."""
    lane, margin = room.lane, room.margin
    left, right, ahead = turning_room(memory, pose.x, pose.y, pose.theta, room.body, room.radius)
    wanted = (ahead - step < (lane + 0.5 if turning else lane)
              and max(left, right) - step < (margin + 0.2 if turning else margin))
    if abs(left - right) < 0.1:
        new_side = 1 if goal_bearing >= 0 else -1
    else:
        new_side = 1 if left > right else -1
    return wanted, (side if turning and side != 0 else new_side)


@jit
def step_clearance(memory, x, y, theta, advance, body):
    """Gap between the body after moving ``advance`` (m) straight ahead and the remembered hits (a
    hit farther than the gap found so far plus ``advance`` and the body is passed: :func:`beyond`)."""
    c, s = math.cos(theta), math.sin(theta)
    gap = math.inf
    for m in range(memory.shape[0]):
        for j in range(memory.shape[1]):
            if memory[m, j, 2] != 0.0 and not beyond(memory[m, j, 0] - x, memory[m, j, 1] - y,
                                                     gap + abs(advance) + body):
                lx, ly = local(memory, m, j, x, y, c, s)
                gap = min(gap, ring_gap(lx - advance, ly, 0.0, gap + body) - body)
    return gap


@jit
def select_all(d, goal_distance, goal_bearing, limits, out):
    """:func:`select` of every row of ``d`` (N, 7) into ``out`` (N,), with the distances of
    ``limits`` (a :class:`~fuzzynav.kernels.records.Thresholds`)."""
    for n in range(d.shape[0]):
        out[n] = select(d[n], goal_distance[n], goal_bearing[n], limits.detection, limits.front, limits.keep,
                        limits.clear, limits.vision)
