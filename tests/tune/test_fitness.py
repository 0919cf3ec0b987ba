"""The cost of an episode ranks success first, then time, and a collision below any timeout."""

import numpy as np
import pytest

from fuzzynav.kernels.step import COLLISION, REACHED, TIMEOUT
from fuzzynav.tune.episodes import N_OUT, OFF_BAND, OUTCOME, PATH, REMAINING, START_DISTANCE, STEPS, TOO_CLOSE
from fuzzynav.tune.fitness import COLLISION_COST, TIMEOUT_COST, episode_cost, summary, wall_cost


def _row(outcome, steps, remaining=0.0):
    row = np.zeros(N_OUT)
    row[[OUTCOME, STEPS, REMAINING, START_DISTANCE]] = outcome, steps, remaining, 10.0
    return row


def test_success_then_time_then_no_collision():
    rows = np.array([_row(REACHED, 100), _row(REACHED, 1199), _row(TIMEOUT, 1200, 0.1), _row(TIMEOUT, 1200, 9.0),
                     _row(COLLISION, 5, 0.1), _row(COLLISION, 5, 9.0)])
    cost = episode_cost(rows, np.full(6, 0.1), np.full(6, 120.0))
    assert list(np.argsort(cost)) == [0, 1, 2, 3, 4, 5]
    assert cost[1] < 1.0 <= cost[2]  # the slowest arrival beats the nearest miss
    assert cost[2] > 10 * cost[1]  # a timeout outweighs ten arrivals at the time limit


def _wall_row(outcome, steps, too_close=0, off_band=0.0, path=None):
    row = np.zeros(N_OUT)
    row[[OUTCOME, STEPS, TOO_CLOSE, OFF_BAND, PATH]] = outcome, steps, too_close, off_band, 0.1 * steps if path is None else path
    return row


def test_wall_cost_ranks_distance_kept_then_any_followed_episode_above_any_failure():
    """Eq VI.21's ranking made a number: a follower that lasts in the band [d_m, d_s] at 1 m/s beats
    one too close a tenth of the time, which beats one drifting away, one slowed to just above half
    of P pays its shortfall, and every collision (the earlier, the worse) costs more than any
    episode that followed the wall."""
    slow = 0.31 * 300 * 0.1  # 0.31 m/s: above half of P (0.6 m/s)
    rows = np.array([_wall_row(TIMEOUT, 300), _wall_row(TIMEOUT, 300, too_close=30, off_band=3.0),
                     _wall_row(TIMEOUT, 300, off_band=120.0), _wall_row(TIMEOUT, 300, path=slow),
                     _wall_row(TIMEOUT, 300, too_close=300, off_band=300.0, path=slow),
                     _wall_row(COLLISION, 250), _wall_row(COLLISION, 20)])
    cost = wall_cost(rows, np.full(7, 0.1), np.full(7, 30.0))
    assert list(np.argsort(cost)) == [0, 1, 2, 3, 4, 5, 6]
    assert cost[0] == 0.0 and cost[4] < COLLISION_COST <= cost[5]


def test_a_creeping_wall_follower_fails_as_a_collision_does():
    """A follower that lasts below half of Table VI.2's slow speed P, inside the band, has not
    followed the wall: it costs more than one at speed that is too close or off the band the whole
    time, as much as a crash after the same share of the course, and a follower that stops as the
    earliest crash — so creeping can never buy the absence of collisions."""
    rows = np.array([_wall_row(TIMEOUT, 300, path=0.2 * 300 * 0.1 * 0.6),
                     _wall_row(TIMEOUT, 300, too_close=300, off_band=300.0, path=0.6 * 300 * 0.1 * 0.6),
                     _wall_row(COLLISION, 60), _wall_row(TIMEOUT, 300, path=0.0), _wall_row(COLLISION, 0)])
    creep, fast, crash_at_a_fifth, stopped, crash_at_once = wall_cost(rows, np.full(5, 0.1), np.full(5, 30.0))
    assert fast < TIMEOUT_COST < COLLISION_COST <= creep
    assert creep == pytest.approx(crash_at_a_fifth) and stopped == pytest.approx(crash_at_once)


def test_a_course_crept_along_is_lasted_but_not_followed():
    """The wall summary's share followed leaves out a course lasted below half of P (the failure
    the cost prices as a collision); the share lasted counts it."""
    rows = np.array([_wall_row(TIMEOUT, 300, path=0.6 * 300 * 0.1), _wall_row(TIMEOUT, 300, path=0.1 * 300 * 0.1),
                     _wall_row(COLLISION, 100)])
    numbers = summary(rows, np.full(3, 0.1), wall=True)
    assert numbers["success_rate"] == pytest.approx(2 / 3) and numbers["followed_rate"] == pytest.approx(1 / 3)
