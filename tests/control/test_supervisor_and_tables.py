"""The supervisor of Fig IV.16 and the reconstructed Tables IV.3–IV.6, VI.2 checked against their principles."""

import numpy as np
import pytest

from fuzzynav.control import supervisor
from fuzzynav.fuzzy import systems_navigation as nav
from fuzzynav.fuzzy.systems import get_system

FAR = 4.0


def _select(readings, goal_distance=10.0, goal_bearing=0.0):
    return supervisor.select(np.array([readings], dtype=float), np.array([goal_distance]),
                             np.array([goal_bearing]))[0]


def test_supervisor_situations():
    assert _select([FAR] * 7) == supervisor.GSB  # nothing sensed
    assert _select([1.0, 2.0, 2.0, FAR, FAR, FAR, FAR]) == supervisor.FOA  # ahead
    assert _select([FAR, 1.2, FAR, 1.0, FAR, 1.1, FAR]) == supervisor.ROA  # on the right
    assert _select([FAR, FAR, 1.2, FAR, 1.0, FAR, 1.1]) == supervisor.LOA  # on the left
    # a wall on the right, the goal ahead-left in clear view: goal seeking (Fig IV.23)
    assert _select([FAR, 2.0, FAR, 1.6, FAR, 1.5, FAR], goal_bearing=0.6) == supervisor.GSB
    # the same wall with the goal behind it: keep avoiding
    assert _select([FAR, 2.0, FAR, 1.6, FAR, 1.5, FAR], goal_bearing=-1.2) == supervisor.ROA


def _grid(system):
    """Outputs at the 8 corners (P = 0.5 m, L = d_max) in rule order (first, second, column)."""
    p, l = 0.5, nav.D_MAX
    X = np.array([[a, b, c] for c in (p, l) for b in (p, l) for a in (p, l)])
    return system.evaluate(X)[:, 0]


def test_side_avoiders_turn_away_and_mirror_each_other():
    roa, loa = _grid(get_system("roa")), _grid(get_system("loa"))
    assert (roa >= 0).all() and (loa <= 0).all()  # Table IV.4 ≥ 0, Table IV.5 ≤ 0
    np.testing.assert_allclose(loa, -roa)
    assert roa[-1] == 0.0  # nothing near: no avoidance steering


def test_front_avoider_keeps_the_published_cells_it_agrees_with():
    foa = _grid(get_system("foa"))  # rows (d2, d1) = PP PL LP LL, d1 varying fastest, columns d3 = P, L
    a = np.pi / 5
    np.testing.assert_allclose(foa[[0, 2, 3]], [-a, -a, 0.0])  # published (d3 = P): NG · NG Z
    np.testing.assert_allclose(foa[6], a)  # published (d3 = L, d2 L, d1 P): PG
    assert foa[4] > 0 and foa[5] > 0 and foa[7] == 0.0  # obstacle on the right -> left; none -> straight


@pytest.mark.parametrize("v, dmin, expected", [(0.5, 0.5, 0.0), (1.0, 0.5, -0.5), (2.0, 0.5, -0.8),
                                               (0.5, 4.0, 0.5), (1.0, 4.0, 0.0), (3.0, 4.0, -0.8)])
def test_vrb_table_IV_6(v, dmin, expected):
    assert get_system("vrb").evaluate(np.array([[v, dmin]]))[0, 0] == pytest.approx(expected)


def test_wall_follower_keeps_the_left_wall():
    wf = get_system("wall-follow")
    near, far = 0.5, nav.D_MAX
    alpha = lambda dd, df, dg: wf.evaluate(np.array([[dd, df, dg]]))[0, 0]
    assert alpha(far, far, near) < 0  # too close to the left wall: turn right
    assert alpha(far, far, far) > 0  # wall lost: turn back left
    assert alpha(far, near, near) < 0  # inner corner: turn away from the wall
    speed = wf.evaluate(np.array([[near, near, near]]))[0, 1]
    assert 0 < speed <= nav.WALL_V1  # slow, but moving (a tricycle at rest cannot turn)
