"""``fuzzy-5b`` reuses its car route while it stays valid, in closed loop: on a generated U-trap
world it reuses the route at some plans, never keeps one that a point seen since lies on, and
drops it (searches again) when an obstacle comes into view on it — and still reaches its goal."""

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.kernels import layers, row_blocks
from fuzzynav.sim import BatchSimulator
from fuzzynav.world.generate import generate_world


def _rest_touched(params, before, after, start):
    """Does a point remembered after the step (``after``: the state row) but not checked against
    the route kept before it (``before``) lie within the route's radius plus ``guide_car_keep``
    of that route from its pose ``start`` on?"""
    at = layers.STATE
    route = row_blocks.route_of(params, before)[int(start):int(before[at.guide_poses]), :2]
    points = row_blocks.points_of(params, after)[int(before[at.guide_seen]):int(after[at.count])]
    if len(route) == 0 or len(points) == 0:
        return False
    gaps = np.hypot(points[:, None, 0] - route[None, :, 0], points[:, None, 1] - route[None, :, 1])
    return bool(gaps.min() < before[at.guide_keep] + params[layers.PARAM.guide_car_keep])


def test_the_car_route_is_reused_while_valid_and_dropped_when_an_obstacle_appears_on_it():
    at = layers.STATE
    controller = make_controller("fuzzy-5b")
    # utrap world 1: a run that reuses, searches and drops a plan (world 0 drops none at version 15's pace)
    sim = BatchSimulator(generate_world("utrap", 0, 1), controller, seed=0, record=False)
    reused = searched = dropped = 0
    while not sim.done:
        params, rows = controller.params, controller.compiled(1, sim.sensors.angles)[-1]
        before = rows[0].copy()
        sim.step()
        params, after = controller.params, controller.compiled(1, sim.sensors.angles)[-1][0]
        if not after[at.guide_planned] > before[at.guide_planned] or before[at.guide_poses] < 2:
            continue  # no plan this step (or an arc ended: the plan comes at the next step)
        if after[at.guide_made] == before[at.guide_made] and after[at.guide_poses] > 0:
            reused += 1
            assert not _rest_touched(params, before, after, after[at.guide_at])  # never kept with a new point on it
        elif after[at.guide_made] != before[at.guide_made]:
            searched += 1
            dropped += _rest_touched(params, before, after, before[at.guide_at])
    assert sim.outcomes()[0] == "reached"
    assert reused > 0 and searched > 0 and dropped > 0, (reused, searched, dropped)
