"""The cost of an episode ranks success first, then time, and a collision below any timeout."""

import numpy as np

from fuzzynav.kernels.step import COLLISION, REACHED, TIMEOUT
from fuzzynav.tune.episodes import N_OUT, OUTCOME, REMAINING, START_DISTANCE, STEPS
from fuzzynav.tune.fitness import episode_cost


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
