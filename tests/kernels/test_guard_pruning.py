"""The turning-room guard and the safety stop pass far hits without their geometry
(:func:`fuzzynav.kernels.guard.beyond`); their numbers are those of every hit measured, bit for
bit, on random hit memories round the robot, near and far, and with no hit at all."""

import math

import numpy as np
import pytest

from fuzzynav.kernels import guard
from fuzzynav.kernels.motion import ring_gap

BODY, RADIUS = 0.3, 0.69


def memories(count: int = 150):
    """Hit memories (steps, rays + 1, 3) of 10 steps: hits 0.2–6 m round (5, 5), some slots empty."""
    rng = np.random.default_rng(11)
    for _ in range(count):
        memory = np.zeros((10, 40, 3))
        r = rng.uniform(0.2, 6.0, (10, 40))
        a = rng.uniform(-math.pi, math.pi, (10, 40))
        memory[:, :, 0], memory[:, :, 1] = 5.0 + r * np.cos(a), 5.0 + r * np.sin(a)
        memory[:, :, 2] = rng.random((10, 40)) < rng.uniform(0.0, 1.0)
        yield memory, float(rng.uniform(-math.pi, math.pi))


def every_hit_room(memory, x, y, theta):
    """(left, right, ahead) of :func:`guard.turning_room` with every hit measured exactly."""
    c, s = math.cos(theta), math.sin(theta)
    left = right = ahead = math.inf
    for m, j in zip(*np.nonzero(memory[:, :, 2])):
        lx, ly = guard.local(memory, m, j, x, y, c, s)
        if lx >= 0.0:
            gap_left, gap_right = ring_gap(lx, ly - RADIUS, RADIUS, math.inf), ring_gap(lx, ly + RADIUS, RADIUS, math.inf)
        else:
            here = ring_gap(lx, ly, 0.0, math.inf)
            gap_left = min(here, ring_gap(lx, ly - 2.0 * RADIUS, 0.0, math.inf))
            gap_right = min(here, ring_gap(lx, ly + 2.0 * RADIUS, 0.0, math.inf))
        left, right = min(left, gap_left - BODY), min(right, gap_right - BODY)
        if lx > 0.0 and abs(ly) < BODY:
            ahead = min(ahead, lx - BODY)
    return left, right, ahead


def every_hit_clearance(memory, x, y, theta, advance):
    """:func:`guard.step_clearance` with every hit measured exactly."""
    c, s = math.cos(theta), math.sin(theta)
    gap = math.inf
    for m, j in zip(*np.nonzero(memory[:, :, 2])):
        lx, ly = guard.local(memory, m, j, x, y, c, s)
        gap = min(gap, ring_gap(lx - advance, ly, 0.0, math.inf) - BODY)
    return gap


def test_far_hits_passed_by_the_guard_change_no_number():
    skipped = 0
    for memory, theta in memories():
        assert guard.turning_room(memory, 5.0, 5.0, theta, BODY, RADIUS) == every_hit_room(memory, 5.0, 5.0, theta)
        for advance in (0.4, 0.0, -0.2):
            assert guard.step_clearance(memory, 5.0, 5.0, theta, advance, BODY) == \
                every_hit_clearance(memory, 5.0, 5.0, theta, advance)
        room = guard.turning_room(memory, 5.0, 5.0, theta, BODY, RADIUS)
        reach = max(room[0], room[1]) + 2.0 * RADIUS + BODY
        skipped += int(np.sum(memory[:, :, 2] * (np.hypot(memory[:, :, 0] - 5.0, memory[:, :, 1] - 5.0) > reach + 1e-6)))
    assert skipped > 1000  # the memories hold hits beyond the rooms: the pruning was exercised


def test_hits_at_the_edge_of_the_reach_change_no_number():
    """Hits a hair inside and outside the distance at which they could first matter, where the
    bounds are tight (beside the robot on the side of the larger room, straight along the step):
    a bound tightened by a micrometre, or without the rounding slack, fails here."""
    rng = np.random.default_rng(4)
    for trial in range(12000):
        theta, advance = float(rng.uniform(-math.pi, math.pi)), float(rng.choice([-1.0, 1.0]) * rng.uniform(0.01, 0.5))
        c, s = math.cos(theta), math.sin(theta)
        memory = np.zeros((1, 3, 3))
        near, a = rng.uniform(0.4, 1.5), rng.uniform(-math.pi, math.pi)  # one hit sets the rooms and the gap
        memory[0, 0] = 5.0 + near * math.cos(a), 5.0 + near * math.sin(a), 1.0
        left, right, _ = guard.turning_room(memory[:, :1], 5.0, 5.0, theta, BODY, RADIUS)
        gap = guard.step_clearance(memory[:, :1], 5.0, 5.0, theta, advance, BODY)
        slack = 2e-6 if trial % 2 else 4e-15  # micrometres, or a few units of rounding
        side = 1.0 if left >= right else -1.0
        d = max(left, right) + 2.0 * RADIUS + BODY + rng.uniform(-slack, slack)
        memory[0, 1] = 5.0 - side * d * s, 5.0 + side * d * c, 1.0  # beside the robot, local (0, ±d)
        d = gap + abs(advance) + BODY + rng.uniform(-slack, slack)
        memory[0, 2] = 5.0 + math.copysign(d, advance) * c, 5.0 + math.copysign(d, advance) * s, 1.0  # along the step
        assert guard.turning_room(memory, 5.0, 5.0, theta, BODY, RADIUS) == every_hit_room(memory, 5.0, 5.0, theta)
        assert guard.step_clearance(memory, 5.0, 5.0, theta, advance, BODY) == \
            every_hit_clearance(memory, 5.0, 5.0, theta, advance)


def test_without_hits_everything_is_free():
    memory = np.zeros((10, 40, 3))
    assert guard.turning_room(memory, 1.0, 2.0, 0.3, BODY, RADIUS) == (math.inf, math.inf, math.inf)
    assert guard.step_clearance(memory, 1.0, 2.0, 0.3, 0.1, BODY) == math.inf


@pytest.mark.parametrize("reach", [math.inf, math.nan])
def test_beyond_an_infinite_or_unknown_reach_is_nothing(reach):
    assert not guard.beyond(1e300, 1e300, reach)
