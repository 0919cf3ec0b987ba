"""Figures of chapter IV (§IV.6–IV.7) and of the hand-made wall follower (§VI.5.3.1).

- ``fig-IV-12``: free goal seeking (Table IV.1) from five starts to five goals per panel (a, b),
  positions read off the figure (the first pair of each panel is the built-in scenario);
- ``fig-IV-13``: free navigation with its commands α(t), V_r(t) (Figs IV.13–IV.14);
- ``fig-IV-15``: goal seeking + obstacle avoidance (``fuzzy-2b-thesis``) past circular obstacles, with
  the behaviour changes marked A, B, … (panels a, b);
- ``fig-IV-22``: the five-behaviour navigator (``fuzzy-5b-thesis``) in two unknown worlds (a, b);
- ``fig-IV-23``: ``fuzzy-5b-thesis`` reaching a goal inside a U-shaped wall;
- ``fig-VI-28``: the hand-made wall follower (Table VI.2) along an obtuse bend and a wall turning
  45° away (Fig VI.27 a, b) and into the sharp corner where it collides (Fig VI.28);
- ``eval-IV``: ``fuzzy-2b-thesis`` on circle worlds and ``fuzzy-5b-thesis`` on mixed worlds (100
  each, 10 with ``quick``), the numbers of ``fuzzynav evaluate``.

The navigators are the ``-thesis`` variants and ``goal-seeking``, as published: the tables, the
switch of Fig IV.9, the supervisor and VRB, without this package's layers
(:data:`fuzzynav.control.batched.LAYERS`; ``fuzzy-*-layered`` have them, ``fuzzy-2b`` and
``fuzzy-5b-rays`` add recovery and loop escape, :mod:`fuzzynav.control.robust`). ``eval-IV`` also
runs the ``-layered`` variants. Every rule base comes from :mod:`fuzzynav.experiments.rule_bases`
(``reproduce --fis ROLE=FILE`` replaces one).

Every function has the registry signature ``(out_dir, quick, seed) -> dict``, writes PNGs and
returns the measured outcomes, with what the figure shows of each run
(:mod:`fuzzynav.experiments.routes`: the route, the switch points, the side each obstacle is
passed on).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from fuzzynav.bench.evaluate import evaluate
from fuzzynav.experiments import routes
from fuzzynav.experiments.rule_bases import controller, systems_for
from fuzzynav.sim import metrics, run_episode
from fuzzynav.viz.trajectories import draw_world, plot_commands, plot_trajectory, save_in
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

# Fig IV.14: the steering "se diminue pour être nulle (le robot a la même direction de but)": the robot
# is aligned from the first step its steering is below this (rad).
ALIGNED_STEERING = float(np.radians(1.0))
# Fig IV.12: (start x, y, θ), (goal x, y) per panel; the first pair is the built-in scenario.
FIG_IV_12 = {
    "a": [((2.0, 17.0, 0.0), (10.0, 11.0)), ((2.0, 10.0, 0.0), (12.0, 15.0)), ((6.0, 2.0, 1.57), (14.0, 9.0)),
          ((18.0, 18.0, 3.14), (12.0, 5.0)), ((17.0, 2.0, 3.14), (4.0, 6.0))],
    "b": [((4.0, 1.5, 3.14), (9.0, 10.0)), ((17.0, 1.0, 1.57), (11.0, 7.0)), ((1.0, 12.0, -1.57), (7.0, 6.0)),
          ((10.0, 19.0, 0.0), (15.0, 12.0)), ((19.0, 10.0, 3.14), (4.0, 16.0))],
}


def _outcome(trace, scenario) -> dict:
    numbers = metrics(trace, scenario)
    keys = ("outcome", "time_s", "path_length_m", "min_clearance_m")
    return {**{k: numbers[k] for k in keys}, "final_speed_mps": float(trace.speed[-1]) if trace.steps else 0.0,
            "max_speed_mps": float(trace.speed.max()) if trace.steps else 0.0,
            "behaviour_changes": len(trace.behaviour_changes()), "switch_points": routes.switch_points(trace),
            "obstacle_sides": routes.obstacle_sides(trace, scenario), "route": routes.route(trace)}


def _panels(names, navigator: str, out_dir, figure_name: str, markers: bool = True) -> dict:
    figure = Figure(figsize=(6 * len(names), 6), layout="constrained")
    axes = np.atleast_1d(figure.subplots(1, len(names)))
    result = {}
    for ax, name in zip(axes, names):
        scenario = load_scenario(name)
        trace = run_episode(scenario, controller(navigator))
        plot_trajectory(trace, scenario, ax, markers=markers)
        result[name] = _outcome(trace, scenario)
    result["figure"] = save_in(figure, out_dir, figure_name)
    return result


def fig_iv_12(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig IV.12 (a, b): five free goal-seeking runs per panel; the speed falls near each goal."""
    figure = Figure(figsize=(12, 6), layout="constrained")
    result = {}
    for ax, (panel, pairs) in zip(figure.subplots(1, 2), FIG_IV_12.items()):
        runs = []
        for i, (start, goal) in enumerate(pairs, 1):
            scenario = scenario_from_dict({"name": f"S{i}->G{i}", "robot": dict(zip("x y theta".split(), start)),
                                           "goal": {"x": goal[0], "y": goal[1]}, "max_time": 60})
            trace = run_episode(scenario, controller("goal-seeking"))
            if i == 1:
                draw_world(ax, scenario)
            ax.plot(*trace.pose[:, :2].T, linewidth=1.6)
            ax.plot(*start[:2], "ks", markersize=5)
            ax.annotate(f"S{i}", start[:2], xytext=(4, -10), textcoords="offset points")
            ax.plot(*goal, "*", color="tab:green", markersize=11)
            ax.annotate(f"G{i}", goal, xytext=(4, 4), textcoords="offset points")
            runs.append(_outcome(trace, scenario))
        ax.set_title(f"({panel}) goal seeking, Table IV.1")
        result[panel] = runs
    result["figure"] = save_in(figure, out_dir, "fig-IV-12.png")
    result["all_reached"] = all(r["outcome"] == "reached" for panel in FIG_IV_12 for r in result[panel])
    return result


def fig_iv_13(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Figs IV.13–IV.14: a free navigation and its steering and speed against time."""
    scenario = load_scenario("fig-IV-13")
    trace = run_episode(scenario, controller("goal-seeking"))
    figure = Figure(figsize=(12, 6), layout="constrained")
    left, right = figure.subfigures(1, 2)
    plot_trajectory(trace, scenario, left.add_subplot(111), markers=False)
    plot_commands(trace, right.subplots(2, 1, sharex=True))
    steering = np.asarray(trace.steering, dtype=float)
    aligned = np.flatnonzero(np.abs(steering) < ALIGNED_STEERING)
    return {**_outcome(trace, scenario), "first_steering_rad": float(steering[0]),
            "largest_steering_rad": float(np.abs(steering).max()),
            "aligned_at_s": float(aligned[0] * trace.dt) if aligned.size else None,
            "largest_steering_once_aligned_rad": float(np.abs(steering[aligned[0]:]).max()) if aligned.size else None,
            "max_speed_mps": float(trace.speed.max()), "figure": save_in(figure, out_dir, "fig-IV-13.png")}


def fig_iv_15(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig IV.15 (a, b): ``fuzzy-2b-thesis`` past circular obstacles, behaviour changes marked A, B, …"""
    return _panels(["fig-IV-15a", "fig-IV-15b"], "fuzzy-2b-thesis", out_dir, "fig-IV-15.png")


def fig_iv_22(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig IV.22 (a, b): ``fuzzy-5b-thesis`` in two unknown cluttered worlds."""
    return _panels(["fig-IV-22a", "fig-IV-22b"], "fuzzy-5b-thesis", out_dir, "fig-IV-22.png", markers=False)


def fig_iv_23(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig IV.23: ``fuzzy-5b-thesis`` reaches a goal inside a U-shaped wall by running along it."""
    return _panels(["fig-IV-23"], "fuzzy-5b-thesis", out_dir, "fig-IV-23.png", markers=False)


def fig_vi_28(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Figs VI.27–VI.28: the hand-made wall follower succeeds round two corners, collides at a sharp one."""
    return _panels(["fig-VI-27", "fig-VI-27b", "fig-VI-28"], "wall-follow", out_dir, "fig-VI-28.png", markers=False)


def eval_iv(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Success / collision / timeout rates of ``fuzzy-2b-thesis`` (circles) and ``fuzzy-5b-thesis`` (mixed),
    as published and with this package's layers (``-layered``)."""
    n = 10 if quick else 100
    result = {}
    figure = Figure(figsize=(7, 4), layout="constrained")
    ax = figure.add_subplot(111)
    runs = [(f"fuzzy-{b}-{variant}", worlds) for b, worlds in (("2b", "circles"), ("5b", "mixed"))
            for variant in ("thesis", "layered")]
    for i, (name, worlds) in enumerate(runs):
        numbers = evaluate(name, worlds, n, seed, systems=systems_for(name) or None)
        numbers.pop("episodes")
        result[f"{name}/{worlds}"] = numbers
        rates = [100 * numbers[k] for k in ("success_rate", "collision_rate", "timeout_rate")]
        bars = ax.bar(np.arange(3) + 0.2 * i, rates, width=0.2, label=f"{name} on {n} {worlds} worlds",
                      hatch=("", "//")[i % 2])
        ax.bar_label(bars, fmt="%.0f", fontsize=7)
    ax.set_xticks(np.arange(3) + 0.3, ["reached the goal (%)", "collided (%)", "timed out (%)"])
    ax.set_ylabel("share of the worlds (%)")
    ax.set_ylim(0, 110)
    ax.legend(loc="upper right")
    result["figure"] = save_in(figure, out_dir, "eval-IV.png")
    return result
