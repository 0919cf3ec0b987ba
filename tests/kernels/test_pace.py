"""The pace's free run (fuzzynav.kernels.pace) against a march along the arc in small steps."""

import math

import numpy as np
import pytest

from fuzzynav.kernels import layers
from fuzzynav.kernels.pace import car_pace, free_run, pace

ANGLES = np.radians(np.linspace(-135.0, 135.0, 271))
MAX_RANGE = 5.0


def marched(ranges, kappa, room, step=1e-3):
    """Arc length before the centre comes within ``room`` of a hit, walking the arc."""
    hits = np.c_[ranges * np.cos(ANGLES), ranges * np.sin(ANGLES)][ranges < MAX_RANGE]
    s = 0.0
    while s < MAX_RANGE:
        if abs(kappa) < 1e-9:
            x, y = s, 0.0
        else:
            x, y = math.sin(kappa * s) / kappa, (1.0 - math.cos(kappa * s)) / kappa
        if len(hits) and np.min(np.hypot(hits[:, 0] - x, hits[:, 1] - y)) < room:
            return s
        s += step
    return MAX_RANGE


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("kappa", [0.0, 0.5, -0.8, 1.45, -1.45])
def test_free_run_is_the_arc_length_to_the_first_hit_within_room(seed, kappa):
    rng = np.random.default_rng(seed)
    ranges = np.full(ANGLES.size, MAX_RANGE)
    beams = rng.choice(ANGLES.size, 12, replace=False)
    ranges[beams] = rng.uniform(0.6, 4.5, 12)
    run = free_run(ranges, ANGLES, MAX_RANGE, kappa, 0.35)
    assert run == pytest.approx(marched(ranges, kappa, 0.35), abs=0.01)


@pytest.mark.parametrize("kappa", [0.0, 0.3, -0.9, 1.45, 5e-4])
def test_far_hits_passed_unmeasured_change_no_run(kappa):
    """The run of a cluttered scan is the least of its hits' runs alone, bit for bit."""
    rng = np.random.default_rng(int(abs(kappa) * 100) + 7)
    passed = 0
    for _ in range(60):
        ranges = np.where(rng.random(ANGLES.size) < 0.5, rng.uniform(0.2, MAX_RANGE, ANGLES.size), MAX_RANGE)
        alone = []
        for j in np.flatnonzero(ranges < MAX_RANGE):
            one = np.full(ANGLES.size, MAX_RANGE)
            one[j] = ranges[j]
            alone.append(free_run(one, ANGLES, MAX_RANGE, kappa, 0.35))
        run = free_run(ranges, ANGLES, MAX_RANGE, kappa, 0.35)
        assert run == min(alone, default=MAX_RANGE)
        passed += int(np.sum((ranges < MAX_RANGE) & (ranges > run + 0.35 + 1e-6)))
    assert passed > 500  # most scans hold hits beyond the run: the pruning was exercised


def test_a_hit_at_the_edge_of_the_skip_changes_no_run():
    """A hit straight ahead a hair nearer or farther than the best run so far plus the room, where
    the bound is tight: a skip tightened by a micrometre fails here."""
    rng = np.random.default_rng(12)
    for _ in range(400):
        ranges = np.full(ANGLES.size, MAX_RANGE)
        first = int(rng.integers(90, 130))  # to the right of straight ahead: read first
        ranges[first] = rng.uniform(1.0, 3.0)
        best = free_run(ranges, ANGLES, MAX_RANGE, 0.0, 0.35)
        ranges[135] = best + 0.35 + rng.uniform(-2e-6, 2e-6)
        one = np.full(ANGLES.size, MAX_RANGE)
        one[135] = ranges[135]
        assert free_run(ranges, ANGLES, MAX_RANGE, 0.0, 0.35) == min(best, free_run(one, ANGLES, MAX_RANGE, 0.0, 0.35))


def test_a_hit_inside_the_room_ahead_leaves_no_run_and_one_behind_is_ignored():
    ranges = np.full(ANGLES.size, MAX_RANGE)
    ranges[135] = 0.3  # straight ahead, within 0.35 m
    assert free_run(ranges, ANGLES, MAX_RANGE, 0.0, 0.35) == 0.0
    assert free_run(ranges, ANGLES, MAX_RANGE, 1.0, 0.35) == 0.0
    ranges[135], ranges[0] = MAX_RANGE, 0.3  # 135° to the right, behind the centre
    assert free_run(ranges, ANGLES, MAX_RANGE, 0.0, 0.35) == MAX_RANGE


def layer_params(horizon=1.0, top=4.0):
    params = np.zeros(layers.TABLES_AT)
    params[[layers.PARAM.wheelbase, layers.PARAM.radius, layers.PARAM.pace_room]] = 0.5, 0.3, 0.05
    params[[layers.PARAM.pace_horizon, layers.PARAM.pace_goal, layers.PARAM.max_speed]] = horizon, 1.0, top
    return params


def test_pace_is_the_slowest_of_top_speed_room_and_target():
    ranges = np.full(ANGLES.size, MAX_RANGE)
    ranges[135] = 2.35  # 2 m of run straight ahead with 0.35 m of room
    assert pace(ranges, ANGLES, MAX_RANGE, 0.0, layer_params(), 9.0) == pytest.approx(2.0)
    assert pace(ranges, ANGLES, MAX_RANGE, 0.0, layer_params(horizon=2.0), 9.0) == pytest.approx(1.0)
    assert pace(ranges, ANGLES, MAX_RANGE, 0.0, layer_params(), 0.5) == pytest.approx(0.5)
    assert pace(ranges, ANGLES, MAX_RANGE, 0.0, layer_params(horizon=0.1, top=1.5), 9.0) == pytest.approx(1.5)


def test_the_car_routes_forward_arc_is_paced_on_its_curvature_and_nothing_else_is():
    params = layer_params()
    params[[layers.PARAM.pace, layers.PARAM.pace_car]] = 1.0, 1.0
    state = np.zeros(len(layers.STATE_NAMES))
    state[[layers.STATE.guide_gear, layers.STATE.guide_kappa]] = 1.0, 0.8
    ranges = np.full(ANGLES.size, MAX_RANGE)
    ranges[150] = 1.2
    on_arc = pace(ranges, ANGLES, MAX_RANGE, math.atan(0.8 * 0.5), params, 9.0)
    assert car_pace(ranges, ANGLES, MAX_RANGE, params, state, 9.0) == pytest.approx(on_arc)
    assert on_arc != pytest.approx(pace(ranges, ANGLES, MAX_RANGE, 0.0, params, 9.0))  # the arc's, not straight on
    state[layers.STATE.guide_gear] = -1.0  # backing: not paced
    assert car_pace(ranges, ANGLES, MAX_RANGE, params, state, 9.0) == 0.0
    state[layers.STATE.guide_gear], params[layers.PARAM.pace_car] = 1.0, 0.0  # pace_car off (version 5)
    assert car_pace(ranges, ANGLES, MAX_RANGE, params, state, 9.0) == 0.0
