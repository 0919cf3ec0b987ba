"""The wall-following evaluation leaves out courses that start the robot inside a wall: no
follower can avoid that collision (thesis §VI.5.3.2; docs/results/chapter-vi.md)."""

import numpy as np

from fuzzynav.experiments.evaluation import starts_in_a_wall, wall_course_scenario


def evaluation_courses(n):
    rng = np.random.default_rng(777)  # evaluate_wall's courses
    return [wall_course_scenario(rng, f"wall-course-{k}") for k in range(n)]


def test_a_start_overlapping_a_wall_is_recognised_and_a_clear_one_is_not():
    courses = evaluation_courses(79)
    inside = courses[78]  # its start's centre is inside a wall (place_starts kept a blocked position)
    clearance = inside.world.clearance(inside.start[:2])[0]
    assert clearance < inside.robot.radius and starts_in_a_wall(inside)
    clear = [c for c in courses if c.world.clearance(c.start[:2])[0] >= c.robot.radius + 0.1]
    assert len(clear) > 70 and not any(starts_in_a_wall(c) for c in clear)
