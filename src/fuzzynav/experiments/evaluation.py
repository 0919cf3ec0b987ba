"""Evaluations of a controller in the simulator: success, collision and timeout rates.

:func:`evaluate` runs one episode per world of :func:`fuzzynav.world.generate.generate_worlds`
and summarises them: ``success_rate``, ``collision_rate``, ``timeout_rate``,
``invalid_command_rate`` (fractions of the ``n`` worlds; the last counts episodes the simulator
stopped on a NaN or infinite command, each with its ``invalid_command`` reason), ``mean_time_s`` and ``mean_path_length_m`` over the successful episodes, plus the
per-world outcomes. ``fuzzynav evaluate`` prints it. The controller is a registered name or a
trained model file (``model``, built by :func:`fuzzynav.catalog.tasks.load_controller`). With
``save_failures`` (a folder), each world not reached is written there as a scenario file with
the plot of its episode (:func:`save_failure`), so ``fuzzynav run FILE`` reruns it.

The learned controllers of chapter VI are evaluated as the thesis does: :func:`evaluate_goal`
(random starts and goals in the empty workspace, Figs VI.3, VI.10, VI.14), :func:`evaluate_avoid`
(random obstacle worlds, §VI.5.2) and :func:`evaluate_wall` (the corners of Fig VI.28 and random
wall courses, §VI.5.3).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from fuzzynav import progress as progress_bars
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.learn.envs import RandomGoal, RandomObstacles, WallCourse
from fuzzynav.learn.tasks.common import GOAL_TOLERANCE
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.plants import DEFAULT_PLANT
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.generate import generate_worlds
from fuzzynav.world.scenario import Goal, Scenario, load_scenario


def save_failure(folder: Path, scenario, trace, controllers: tuple[str, ...] = ()) -> Path:
    """Write a failed world as ``folder/<world>.yaml`` (naming the built-in ``controllers``, for
    ``fuzzynav demo --scenario FILE``) and the plot of the episode as ``folder/<world>.png``;
    returns the scenario file."""
    from fuzzynav.viz.trajectories import plot_episode
    from fuzzynav.world.scenario_file import save_scenario

    path = save_scenario(scenario, Path(folder) / f"{scenario.name}.yaml", controllers=controllers)
    plot_episode(trace, scenario, path.with_suffix(".png"))
    return path


def evaluate(controller: str | None = None, worlds: str = "mixed", n: int = 100, seed: int = 0,
             progress: Callable[[int, dict], None] | None = None, *, model: str | Path | None = None,
             systems: dict | None = None, save_failures: str | Path | None = None, sensors: str | None = None,
             options: dict | None = None, plant: str = DEFAULT_PLANT) -> dict:
    """Run the registered ``controller`` (with its fuzzy ``systems`` replaced by role, if given, and
    the keyword ``options`` of its factory, e.g. ``layers=``) —
    or the one stored in the ``model`` file — on ``n`` seeded worlds of family ``worlds``, with the
    sensor ring named ``sensors`` (default: the controller's, :func:`fuzzynav.sim.simulator.default_ring`);
    ``progress(i, outcome)`` is called after each world; ``plant`` moves the robot
    (:mod:`fuzzynav.sim.plants`).

    A model is loaded once; every episode starts from the simulator's ``reset(rng)`` of it, as a
    registered controller is built afresh per world. A progress bar shows on a terminal
    (:mod:`fuzzynav.progress`).
    """
    if (controller is None) == (model is None):
        raise InputError("give exactly one of a controller name and a model file", field="controller")
    if model is not None:
        from fuzzynav.catalog.tasks import load_controller

        loaded = load_controller(model)
        build, controller = (lambda: loaded), loaded.name
    else:
        extra = {**(options or {}), **({"systems": systems} if systems else {})}
        build = lambda: make_controller(controller, **extra)
    ring = None if sensors is None else named_ring(sensors)
    scenarios = generate_worlds(worlds, n, seed)
    runs = []
    bar = progress_bars.bar(total=len(scenarios), desc=f"{controller} on {worlds} worlds", unit="world", leave=False)
    for i, scenario in enumerate(scenarios):
        trace = run_episode(scenario, build(), seed=seed, sensors=ring, plant=plant)
        numbers = metrics(trace, scenario)
        runs.append({key: numbers[key] for key in ("scenario", "outcome", "time_s", "path_length_m",
                                                    "min_clearance_m")})
        if numbers["invalid_command"] is not None:
            runs[-1]["invalid_command"] = numbers["invalid_command"]
        if save_failures is not None and numbers["outcome"] != "reached":
            named = () if model is not None else (controller,)
            runs[-1]["saved"] = str(save_failure(save_failures, scenario, trace, named))
        bar.update()
        bar.set_postfix(reached=sum(r["outcome"] == "reached" for r in runs))
        if progress is not None:
            progress(i, runs[-1])
    bar.close()
    outcomes = np.array([r["outcome"] for r in runs])
    reached = outcomes == "reached"
    rate = lambda name: float(np.mean(outcomes == name))
    return {
        "controller": controller,
        "model": None if model is None else str(model),
        "worlds": worlds,
        "n": int(n),
        "seed": int(seed),
        "plant": plant,
        "success_rate": rate("reached"),
        "collision_rate": rate("collision"),
        "timeout_rate": rate("timeout"),
        "invalid_command_rate": rate("invalid_command"),
        "mean_time_s": float(np.mean([r["time_s"] for r, ok in zip(runs, reached) if ok])) if reached.any() else None,
        "mean_path_length_m": (float(np.mean([r["path_length_m"] for r, ok in zip(runs, reached) if ok]))
                               if reached.any() else None),
        "episodes": runs,
    }


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
