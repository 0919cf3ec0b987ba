"""The evaluations of the learned controllers of chapter VI, as the thesis runs them:
:func:`evaluate_goal` (random starts and goals in the empty workspace, Figs VI.3, VI.10, VI.14),
:func:`evaluate_avoid` (random obstacle worlds, §VI.5.2) and :func:`evaluate_wall` (the corners
of Fig VI.28 and random wall courses, §VI.5.3): many starts of one layout of the training
environments (:mod:`fuzzynav.learn.envs`) stepped together by the simulator, each protocol with
its own measure (stopping at the goal, collisions of a follower that has no goal). A registered
controller over generated worlds is :func:`fuzzynav.bench.evaluate.evaluate`.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav import progress as progress_bars
from fuzzynav.learn.envs import RandomGoal, RandomObstacles, WallCourse
from fuzzynav.learn.tasks.common import GOAL_TOLERANCE
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import Goal, Scenario, load_scenario

STOP_SPEED = 0.2  # m/s: a run "stops at its goal" when it reaches it at most this fast


def scenario_of(world, start, goal, name: str, max_time: float):
    """A goal scenario of one start in ``world`` (as drawn by the training layouts)."""
    return Scenario(name=name, world=world, start=np.asarray(start, dtype=float),
                    goal=Goal(np.asarray(goal, dtype=float), GOAL_TOLERANCE), max_time=max_time)


def evaluate_goal(controller, n: int = 100, seed: int = 12345, goals: int = 10, max_time: float = 60.0) -> dict:
    """Success of a goal seeker in the simulator from ``n`` random starts (≥ 3 m from their goal)
    towards ``goals`` random goals in the empty 20 m × 20 m workspace (Figs VI.3, VI.10, VI.14).

    ``stopped``: the share of runs that reach their goal at a speed ≤ :data:`STOP_SPEED` (the
    speed at the last step, ``final_speed_mps`` of a run; Table IV.1's robot stops at its goal);
    ``final_speeds``: that speed of every reaching run (m/s)."""
    rng = np.random.default_rng(seed)
    layout = RandomGoal()
    outcomes, speeds = [], []
    for g in range(goals):
        world, candidates, targets = layout.sample(rng, 8 * math.ceil(n / goals))
        far = np.hypot(*(candidates[:, :2] - targets[0]).T) >= layout.min_distance
        starts = candidates[far][: n // goals + (g < n % goals)]
        scenario = scenario_of(world, starts[0], targets[0], f"random-goal-{g}", max_time)
        batch = BatchSimulator(scenario, controller, starts=starts, record=True).run()
        outcomes += batch.outcomes()
        speeds += [float(batch.trace(i).speed[-1]) for i in range(len(starts))]
    outcomes, speeds = outcomes[:n], speeds[:n]
    arrivals = [round(v, 4) for v, o in zip(speeds, outcomes) if o == "reached"]
    return {"runs": len(outcomes), "success": outcomes.count("reached") / len(outcomes),
            "collisions": outcomes.count("collision"), "timeouts": outcomes.count("timeout"),
            "stopped": sum(v <= STOP_SPEED for v in arrivals) / len(outcomes), "final_speeds": arrivals}


def evaluate_avoid(controller, n: int = 100, seed: int = 54321, max_time: float = 60.0) -> dict:
    """Success and collisions of a navigator in ``n`` random obstacle worlds (one start and goal
    each, drawn as in training but from another seed) — the evaluation of §VI.5.2."""
    rng = np.random.default_rng(seed)
    outcomes = []
    for k in progress_bars.bar(range(n), desc="evaluation in obstacle worlds", unit="world", leave=False):
        world, starts, goals = RandomObstacles().sample(rng, 1)
        scenario = scenario_of(world, starts[0], goals[0], f"random-world-{k}", max_time)
        outcomes += BatchSimulator(scenario, controller, record=False).run().outcomes()
    return {"runs": n, "success": outcomes.count("reached") / n, "collisions": outcomes.count("collision"),
            "timeouts": outcomes.count("timeout")}


def wall_course_scenario(rng, name: str, max_time: float = 30.0):
    """A random wall course as a scenario. The follower ignores goals: the goal, in a corner of
    the workspace, only gives the episode a task; success is lasting ``max_time`` without collision."""
    world, starts, _ = WallCourse().sample(rng, 1)
    return scenario_of(world, starts[0], (0.5, 0.5), name, max_time)


def starts_in_a_wall(scenario) -> bool:
    """Does the robot's footprint overlap a wall at its start pose? Then no controller avoids the
    collision. :func:`fuzzynav.kernels.courses.place_starts` keeps a position whose both directions
    are blocked (the rule the training courses were drawn with), and a few such starts lie within
    the footprint's radius of a wall (docs/results/chapter-vi.md, "Wall following")."""
    return bool(scenario.world.collides(scenario.start[:2], scenario.robot.radius)[0])


def evaluate_wall(controller, n: int = 20, seed: int = 777, max_time: float = 30.0) -> dict:
    """Collisions of a wall follower on the Fig VI.28 corners and on the random wall courses among
    the ``n`` drawn whose start is collision-free (``excluded``: those that start in a wall, the
    same for every follower; ``courses``: the ones run)."""
    corners = BatchSimulator(load_scenario("fig-VI-28"), controller, record=False).run().outcomes()[0]
    rng = np.random.default_rng(seed)
    outcomes, excluded = [], 0
    for k in progress_bars.bar(range(n), desc="evaluation on wall courses", unit="course", leave=False):
        scenario = wall_course_scenario(rng, f"wall-course-{k}", max_time)
        if starts_in_a_wall(scenario):
            excluded += 1
            continue
        outcomes += BatchSimulator(scenario, controller, record=False).run().outcomes()
    return {"fig-VI-28": corners, "courses": n - excluded, "excluded": excluded,
            "collisions": outcomes.count("collision")}
