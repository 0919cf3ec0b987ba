"""Compare a scenario read back from a file (or a document) with the one written, field by field:
comparing the two ``to_dict()`` would not see a field ``Scenario.to_dict`` drops (the file then
lacks it, the scenario read back gets its default, and both documents lack it)."""

import numpy as np


def assert_same_goal_scenario(again, original):
    """``again`` has ``original``'s name, description, time limit, robot, start pose, goal and world."""
    assert (again.name, again.description, again.max_time, again.controllers, again.sensors) == (
        original.name, original.description, original.max_time, original.controllers, original.sensors)
    assert again.robot == original.robot and again.imperfections == original.imperfections
    np.testing.assert_array_equal(again.start, original.start)  # the heading too
    np.testing.assert_array_equal(again.goal.position, original.goal.position)
    assert again.goal.tolerance == original.goal.tolerance
    assert (again.world.width, again.world.height) == (original.world.width, original.world.height)
    assert [shape.kind for shape in again.world.obstacles] == [shape.kind for shape in original.world.obstacles]
    for shape, first in zip(again.world.obstacles, original.world.obstacles):
        np.testing.assert_array_equal(shape.packed(), first.packed())
