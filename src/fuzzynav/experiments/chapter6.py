"""Figures and tables of chapter VI (§VI.2, §VI.5): learning curves, learned trajectories, comparisons.

Every function has the registry signature ``(out_dir, quick, seed) -> dict``: it trains what it
needs with the tasks of :mod:`fuzzynav.learn.tasks` (models and checkpoints under
``out_dir/models``), writes PNGs and returns the numbers it measured. ``quick`` cuts the episode
budgets (smoke runs); the full setting uses each task's default.

- ``fig-VI-1`` (with VI.2): tabular Q-learning from a fixed start — mean reinforcement per
  episode and the trajectory after learning;
- ``fig-VI-4`` (with VI.3): the same with random starts and goals, four learned trajectories;
- ``table-VI-1``: episodes to converge for 9, 11, 13 states × 3 actions and 19 states × 5;
- ``fig-VI-8`` (VI.7): FQL, 15 rules × 3, fixed start; ``fig-VI-9`` (VI.10): random starts,
  steering then speed; ``fig-VI-13`` (VI.14): 35 rules × 5; ``fig-VI-16`` (VI.15): traces;
- ``fig-VI-22`` (VI.18–VI.21): FQL obstacle avoidance — curves of both phases and trajectories
  in random worlds; ``fig-VI-24`` (VI.23): the chapter IV navigator and the learned one on the
  same world, side by side, with their success over 100 random worlds;
- ``fig-VI-29`` (VI.28–VI.30): the hand-made wall follower and the FQL-optimised one on the
  corners of Fig VI.28 and on random wall courses.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from fuzzynav import progress
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.catalog.tasks import load_controller
from fuzzynav.experiments import evaluation
from fuzzynav.learn.checkpoint import load_checkpoint
from fuzzynav.learn.envs import FixedGoal, RandomGoal, RandomObstacles
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal, fql_wall, tabular_goal
from fuzzynav.learn.tasks.common import TrainRequest
from fuzzynav.sim import run_episode
from fuzzynav.viz.curves import plot_learning_curve
from fuzzynav.viz.trajectories import plot_trajectory, save_figure


def _save(figure: Figure, out_dir, name: str) -> str:
    return save_figure(figure, Path(out_dir) / name)


def _request(out_dir, name: str, episodes, seed: int) -> TrainRequest:
    return TrainRequest(out=Path(out_dir) / "models" / f"{name}-{seed}.json", task=name, episodes=episodes, seed=seed,
                        progress=progress.enabled())


def _curves(request, phases) -> dict:
    """Per-episode mean reinforcement of each phase, read back from its checkpoint."""
    return {p: common.episode_curve(load_checkpoint(common.checkpoint_path(request.out, p))["curve"], "mean_reward")
            for p in phases}


def _figure(curves: dict, converged: dict, controller, starts, title: str, out_dir, name: str,
            obstacles: bool = False, window: int = common.GOAL_CONVERGENCE["window"]) -> dict:
    """Learning curves (one panel per phase, the training's episodes to converge marked) and
    trajectories of the learned controller, in a grid of at most three panels per row."""
    panels = len(curves) + len(starts)
    columns = min(3, panels)
    rows = -(-panels // columns)
    figure = Figure(figsize=(5.2 * columns, 4.6 * rows), layout="constrained")
    axes = figure.subplots(rows, columns, squeeze=False).ravel()
    for ax in axes[panels:]:
        ax.set_visible(False)
    budget = {phase: converged[phase]["episodes"] for phase in curves}
    converged = {phase: converged[phase]["converged_at"] for phase in curves}
    for ax, (phase, curve) in zip(axes, curves.items()):
        plot_learning_curve(curve, ax=ax, window=window, title=f"{title}: {phase}", label=phase,
                            converged_at=converged[phase] or len(curve) + 1)  # past the curve: not converged
    outcomes = []
    for ax, scenario in zip(axes[len(curves):], starts):
        trace = run_episode(scenario, controller)
        plot_trajectory(trace, scenario, ax, markers=obstacles)
        outcomes.append(trace.outcome)
    return {"figure": _save(figure, out_dir, name), "converged_at": converged, "episodes": budget,
            "trajectories": outcomes}


def _goal_scenarios(seed: int, n: int = 4, layout=None):
    layout = layout or RandomGoal()
    rng = np.random.default_rng(seed + 1000)
    scenarios = []
    for k in range(n):
        world, start, goal = layout.sample(rng, 1)
        scenarios.append(evaluation.scenario_of(world, start[0], goal[0], f"start {k + 1}", 60.0))
    return scenarios


def _fixed_scenario():
    layout = FixedGoal()
    world, start, goal = layout.sample(None, 1)
    return [evaluation.scenario_of(world, start[0], goal[0], "fixed start", 60.0)]


# -- tabular Q-learning (§VI.2) ----------------------------------------------------------------
def _q_run(out_dir, name, episodes, seed, n_states=13, n_actions=3, fixed=False):
    request = _request(out_dir, name, episodes, seed)
    env, learner, disc, steering = tabular_goal.q_goal_parts(n_states, n_actions, fixed)
    result, _ = common.run_phases([common.Phase("steering", env, learner, episodes, common.checkpoint_path(request.out, "steering"))],
                              request)
    phase = result["steering"]
    converged = phase["converged_at"] if phase["converged_at"] <= phase["episodes"] else None  # None: not within budget
    return request, tabular_goal.q_goal_controller(learner, disc, steering), {"episodes": phase["episodes"],
                                                                      "converged_at": converged}


def fig_vi_1(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.1–VI.2: tabular Q-learning, fixed start (thesis: converges from episode ~1000)."""
    request, controller, result = _q_run(out_dir, "q-goal-fixed", 500 if quick else 1500, seed, fixed=True)
    return _figure(_curves(request, ["steering"]), {"steering": result}, controller, _fixed_scenario(),
                   "Q-learning, fixed start", out_dir, "fig-VI-1.png")


def fig_vi_4(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.3–VI.4: tabular Q-learning, random starts and goals (thesis: ~3,500 episodes)."""
    request, controller, result = _q_run(out_dir, "q-goal", 600 if quick else 3000, seed)
    numbers = _figure(_curves(request, ["steering"]), {"steering": result}, controller, _goal_scenarios(seed),
                      "Q-learning, random starts", out_dir, "fig-VI-4.png")
    return {**numbers, "evaluation": evaluation.evaluate_goal(controller, 20 if quick else 100)}


def table_vi_1(out_dir, quick=False, seed=0) -> dict:
    """Table VI.1: episodes to converge as the number of states (and actions) grows."""
    rows = []
    for n_states, n_actions, thesis in ((9, 3, 3260), (11, 3, 4100), (13, 3, 6200), (19, 5, 8950)):
        _, controller, result = _q_run(out_dir, f"q-goal-{n_states}x{n_actions}", 500 if quick else 4000, seed,
                                       n_states, n_actions)
        rows.append({"states": n_states, "actions": n_actions, "thesis_episodes": thesis,
                     "episodes": result["episodes"], "episodes_to_converge": result["converged_at"],
                     "success": evaluation.evaluate_goal(controller, 20 if quick else 100)["success"]})
    figure = Figure(figsize=(9, 2.2), layout="constrained")
    ax = figure.add_subplot(111)
    ax.axis("off")
    here = lambda r: (f"not converged within {r['episodes']}" if r["episodes_to_converge"] is None
                      else r["episodes_to_converge"])
    table = ax.table(cellText=[[r["states"], r["actions"], r["thesis_episodes"], here(r), f"{r['success']:.0%}"]
                               for r in rows],
                     colLabels=["states", "actions", "thesis: episodes to converge", "here: episodes to converge",
                                "success on random goals"], colWidths=[0.1, 0.1, 0.27, 0.3, 0.23],
                     cellLoc="center", loc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(10)
    table.scale(1.0, 1.6)
    return {"rows": rows, "figure": _save(figure, out_dir, "table-VI-1.png")}


# -- fuzzy Q-learning goal seeking (§VI.5.1) ---------------------------------------------------
def _fql_goal(out_dir, task: fql_goal.GoalFQL, quick, episodes, seed, title, name, starts) -> dict:
    request = _request(out_dir, task.name + ("-fixed" if task.fixed else ""), episodes, seed)
    summary = fql_goal.train_goal_fql(task, request)
    controller = load_controller(request.out)
    phases = ["steering", "speed"] if task.learn_speed else ["steering"]
    numbers = _figure(_curves(request, phases), summary, controller, starts, title, out_dir, name)
    rules = json.loads(Path(request.out).read_text())["rules"]
    return {**numbers, "rules": rules, "evaluation": evaluation.evaluate_goal(controller, 20 if quick else 100)}


def fig_vi_8(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.7–VI.8: FQL, 15 rules × 3, fixed start, steering only (thesis: ~180 episodes)."""
    task = replace(fql_goal.GOAL_TASKS["fql-goal"], fixed=True, learn_speed=False)
    return _fql_goal(out_dir, task, quick, 200 if quick else 1000, seed, "FQL 15 rules, fixed start", "fig-VI-8.png",
                     _fixed_scenario())


def fig_vi_9(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.9–VI.10: FQL, 15 rules × 3, random starts, steering then speed (thesis: ~3,000 / ~900)."""
    return _fql_goal(out_dir, fql_goal.GOAL_TASKS["fql-goal"], quick, 400 if quick else None, seed, "FQL 15 rules",
                     "fig-VI-9.png", _goal_scenarios(seed))


def fig_vi_13(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.13–VI.14: FQL on the chapter IV partition, 35 rules × 5 (thesis: ~5,000 episodes)."""
    return _fql_goal(out_dir, fql_goal.GOAL_TASKS["fql-goal-35"], quick, 400 if quick else None, seed, "FQL 35 rules",
                     "fig-VI-13.png", _goal_scenarios(seed))


def fig_vi_16(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.15–VI.16: FQL 15 rules × 3 with eligibility traces (thesis: ~1,400 episodes)."""
    return _fql_goal(out_dir, fql_goal.GOAL_TASKS["fql-goal-traces"], quick, 300 if quick else None, seed,
                     "FQL with eligibility traces", "fig-VI-16.png", _goal_scenarios(seed))


# -- obstacle avoidance (§VI.5.2) --------------------------------------------------------------
def _avoid_model(out_dir, quick, seed):
    request = _request(out_dir, "fql-avoid", 400 if quick else None, seed)
    summary = fql_avoid.train_fql_avoid(request)
    return request, load_controller(request.out), summary


def fig_vi_22(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.18–VI.22: FQL avoidance — curves of steering and speed, learned trajectories
    (thesis: steering converged by ~250 episodes, speed by ~2,000)."""
    request, controller, summary = _avoid_model(out_dir, quick, seed)
    numbers = _figure(_curves(request, ["steering", "speed"]), summary, controller,
                      _goal_scenarios(seed, 3, layout=RandomObstacles()), "FQL obstacle avoidance", out_dir,
                      "fig-VI-22.png", obstacles=True,
                      window=common.convergence_window(common.WORLD_CONVERGENCE, fql_avoid.AVOID_BATCH)[0])
    return {**numbers, "evaluation": evaluation.evaluate_avoid(controller, 20 if quick else 100)}


def fig_vi_24(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.23–VI.24: the chapter IV fuzzy navigator (fuzzy-2b-thesis) and the FQL navigator on the
    same world, and both over the same random worlds."""
    _, learned, _ = _avoid_model(out_dir, quick, seed)
    fuzzy = make_controller("fuzzy-2b-thesis")
    scenario = _goal_scenarios(seed, 1, layout=RandomObstacles())[0]
    figure = Figure(figsize=(11, 5.5), layout="constrained")
    numbers = {}
    for ax, (name, controller) in zip(figure.subplots(1, 2), (("fuzzy-2b-thesis (Fig VI.23)", fuzzy),
                                                               ("FQL (Fig VI.24)", learned))):
        trace = run_episode(scenario, controller)
        plot_trajectory(trace, scenario, ax)
        numbers[name] = {"outcome": trace.outcome,
                         "evaluation": evaluation.evaluate_avoid(controller, 20 if quick else 100)}
    return {**numbers, "figure": _save(figure, out_dir, "fig-VI-24.png")}


# -- wall following (§VI.5.3) ------------------------------------------------------------------
def fig_vi_29(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.28–VI.30: the hand-made follower collides at the corners of Fig VI.28; the
    FQL-optimised one (Table VI.2's rules, learned interpretations, on the same single rays at
    −90°, 0°, +90° — ``sensing`` in the numbers) follows them."""
    from fuzzynav.world.scenario import load_scenario

    request = _request(out_dir, "fql-wall", 300 if quick else None, seed)
    fql_wall.train_fql_wall(request)
    learned, handmade = load_controller(request.out), make_controller("wall-follow")
    corners = load_scenario("fig-VI-28")
    course = evaluation.wall_course_scenario(np.random.default_rng(seed + 1000), "wall course")
    figure = Figure(figsize=(11, 11), layout="constrained")
    numbers = {}
    for row, scenario in zip(figure.subplots(2, 2), (corners, course)):
        for ax, (name, controller) in zip(row, (("wall-follow (Table VI.2)", handmade), ("FQL-optimised", learned))):
            trace = run_episode(scenario, controller, max_time=30.0)
            plot_trajectory(trace, scenario, ax, markers=False)
            numbers[f"{scenario.name}: {name}"] = trace.outcome
    numbers["evaluation"] = {"wall-follow": evaluation.evaluate_wall(handmade, 10 if quick else 20),
                             "fql-wall": evaluation.evaluate_wall(learned, 10 if quick else 20)}
    model = json.loads(Path(request.out).read_text())
    numbers["rules"], numbers["sensing"] = model["rules"], model["sensing"]
    return {**numbers, "figure": _save(figure, out_dir, "fig-VI-29.png")}
