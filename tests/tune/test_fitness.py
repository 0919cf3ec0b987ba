"""The cost of an episode ranks success first, then time, and a collision below any timeout."""

import numpy as np

from fuzzynav.kernels.step import COLLISION, REACHED, TIMEOUT
from fuzzynav.tune.episodes import N_OUT, OFF_BAND, OUTCOME, PATH, REMAINING, START_DISTANCE, STEPS, TOO_CLOSE
from fuzzynav.tune.fitness import COLLISION_COST, TIMEOUT_COST, episode_cost, wall_cost


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


def test_wall_cost_ranks_distance_kept_then_any_lasted_episode_above_any_collision():
    """Eq VI.21's ranking made a number: a follower that lasts in the band [d_m, d_s] at 1 m/s beats
    one too close a tenth of the time, which beats one drifting away, a stopped one pays, and
    every collision (the earlier, the worse) costs more than any lasted episode."""
    rows = np.array([_wall_row(TIMEOUT, 300), _wall_row(TIMEOUT, 300, too_close=30, off_band=3.0),
                     _wall_row(TIMEOUT, 300, off_band=150.0), _wall_row(TIMEOUT, 300, path=0.0),
                     _wall_row(TIMEOUT, 300, too_close=300, off_band=300.0, path=0.0),
                     _wall_row(COLLISION, 250), _wall_row(COLLISION, 20)])
    cost = wall_cost(rows, np.full(7, 0.1), np.full(7, 30.0))
    assert list(np.argsort(cost)) == [0, 1, 2, 3, 4, 5, 6]
    assert cost[0] == 0.0 and cost[4] < COLLISION_COST <= cost[5]


def test_a_creeping_wall_follower_costs_more_than_any_follower_at_speed_and_less_than_a_collision():
    """A follower that lasts at a tenth of Table VI.2's slow speed P, inside the band, costs more
    than one at speed that is too close or off the band the whole time, and less than a collision."""
    rows = np.array([_wall_row(TIMEOUT, 300, path=0.2 * 300 * 0.1 * 0.6),
                     _wall_row(TIMEOUT, 300, too_close=300, off_band=300.0, path=0.6 * 300 * 0.1 * 0.6),
                     _wall_row(COLLISION, 299)])
    slow_but_following, fast, crash = wall_cost(rows, np.full(3, 0.1), np.full(3, 30.0))
    assert slow_but_following >= TIMEOUT_COST > fast
    assert slow_but_following < COLLISION_COST <= crash
